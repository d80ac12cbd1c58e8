#include "builtin_shapes.h"

#include <cmath>

namespace sherpa::scene::detail {
namespace {

constexpr float kPi = 3.14159265358979f;

Mesh new_mesh() {
    Mesh m;
    m.provenance.fill(Provenance::Defaulted);
    for (VertexAttribute a :
         {VertexAttribute::Position, VertexAttribute::Normal, VertexAttribute::TexCoord0})
        m.provenance[static_cast<std::size_t>(a)] =
            Provenance::Authored; // authored by the generator
    return m;
}

void finish(Mesh& m) {
    m.local_bounds = core::Aabb::empty();
    for (const auto& v : m.vertices) m.local_bounds.expand(v.position);
    m.source_vertex_count = static_cast<std::uint32_t>(m.vertices.size());
    m.source_triangle_count = m.triangle_count();
}

// Indices of a (cols+1) x (rows+1) vertex grid, counter-clockwise seen from outside.
void grid_indices(Mesh& m, std::uint32_t cols, std::uint32_t rows, bool flip) {
    for (std::uint32_t r = 0; r < rows; ++r)
        for (std::uint32_t c = 0; c < cols; ++c) {
            const std::uint32_t a = r * (cols + 1) + c, b = a + 1, d = a + cols + 1, e = d + 1;
            if (flip)
                m.indices.insert(m.indices.end(), {a, b, d, b, e, d});
            else
                m.indices.insert(m.indices.end(), {a, d, b, b, d, e});
        }
}

ImageRecord new_image(std::string name, std::uint32_t size) {
    ImageRecord img;
    img.name = std::move(name);
    img.mime_type = "image/x-sherpa-rgba8";
    img.width = img.height = size;
    img.pixels.resize(std::size_t{size} * size * 4);
    img.byte_size = img.pixels.size();
    return img;
}

} // namespace

Mesh make_plane(float size, std::uint32_t segments, float uv_tiles) {
    Mesh m = new_mesh();
    for (std::uint32_t r = 0; r <= segments; ++r)
        for (std::uint32_t c = 0; c <= segments; ++c) {
            const float u = static_cast<float>(c) / segments, v = static_cast<float>(r) / segments;
            Vertex vx;
            vx.position = {(u - 0.5f) * size, 0.0f, (v - 0.5f) * size};
            vx.normal = {0.0f, 1.0f, 0.0f};
            vx.uv0 = {u * uv_tiles, v * uv_tiles};
            m.vertices.push_back(vx);
        }
    grid_indices(m, segments, segments, false);
    finish(m);
    return m;
}

Mesh make_uv_sphere(float radius, std::uint32_t segments, std::uint32_t rings) {
    Mesh m = new_mesh();
    for (std::uint32_t r = 0; r <= rings; ++r) {
        const float v = static_cast<float>(r) / rings, theta = v * kPi;
        for (std::uint32_t s = 0; s <= segments; ++s) {
            const float u = static_cast<float>(s) / segments, phi = u * 2.0f * kPi;
            const glm::vec3 n{std::sin(theta) * std::cos(phi), std::cos(theta),
                              -std::sin(theta) * std::sin(phi)};
            Vertex vx;
            vx.position = n * radius;
            vx.normal = n;
            vx.uv0 = {u, v};
            m.vertices.push_back(vx);
        }
    }
    grid_indices(m, segments, rings, false);
    finish(m);
    return m;
}

Mesh make_torus(float major_radius, float minor_radius, std::uint32_t segments,
                std::uint32_t sides) {
    Mesh m = new_mesh();
    for (std::uint32_t r = 0; r <= sides; ++r) {
        const float v = static_cast<float>(r) / sides, theta = v * 2.0f * kPi;
        for (std::uint32_t s = 0; s <= segments; ++s) {
            const float t = static_cast<float>(s) / segments, phi = t * 2.0f * kPi;
            const glm::vec3 ring{std::cos(phi), 0.0f, -std::sin(phi)};
            const glm::vec3 n = ring * std::cos(theta) + glm::vec3(0.0f, std::sin(theta), 0.0f);
            Vertex vx;
            vx.position = ring * major_radius + n * minor_radius;
            vx.normal = n;
            vx.uv0 = {1.0f - std::abs(2.0f * t - 1.0f), v}; // mirrored at t = 0.5
            m.vertices.push_back(vx);
        }
    }
    grid_indices(m, segments, sides, true);
    finish(m);
    return m;
}

Mesh make_box(glm::vec3 h) {
    Mesh m = new_mesh();
    struct Face {
        glm::vec3 n, u, v;
        bool mirrored;
    };
    const Face faces[6] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}, false}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}, true},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}, false}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}, true},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, false},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}, true},
    };
    for (const Face& f : faces) {
        const auto base = static_cast<std::uint32_t>(m.vertices.size());
        for (int k = 0; k < 4; ++k) {
            const float su = (k == 1 || k == 2) ? 1.0f : -1.0f, sv = (k >= 2) ? 1.0f : -1.0f;
            Vertex vx;
            vx.position = (f.n + f.u * su + f.v * sv) * h;
            vx.normal = f.n;
            const float u = 0.5f * (su + 1.0f), v = 1.0f - 0.5f * (sv + 1.0f); // glTF: v down
            vx.uv0 = {f.mirrored ? 1.0f - u : u, v};
            m.vertices.push_back(vx);
        }
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    finish(m);
    return m;
}

ImageRecord make_bump_normal_map(std::uint32_t size) {
    ImageRecord img = new_image("builtin:bumps_normal", size);
    const std::uint32_t cell = size / 8;
    for (std::uint32_t y = 0; y < size; ++y)
        for (std::uint32_t x = 0; x < size; ++x) {
            // Hemispherical bump per cell: the height field h = sqrt(1 - r^2) gives
            // tangent-space normal (-dh/dx, -dh/dy, 1) normalised. glTF's +Y is up in
            // the image (green = +V tangent direction, which points to decreasing v).
            const float cx = (static_cast<float>(x % cell) + 0.5f) / cell * 2.0f - 1.0f;
            const float cy = (static_cast<float>(y % cell) + 0.5f) / cell * 2.0f - 1.0f;
            const float r2 = cx * cx + cy * cy;
            glm::vec3 n{0.0f, 0.0f, 1.0f};
            if (r2 < 0.64f) {
                const float hz = std::sqrt(1.0f - r2);
                n = glm::normalize(glm::vec3(cx / hz, -cy / hz, 1.0f) *
                                   glm::vec3(0.6f, 0.6f, 1.0f));
            }
            std::uint8_t* p = &img.pixels[(std::size_t{y} * size + x) * 4];
            p[0] = static_cast<std::uint8_t>(std::lround((n.x * 0.5f + 0.5f) * 255.0f));
            p[1] = static_cast<std::uint8_t>(std::lround((n.y * 0.5f + 0.5f) * 255.0f));
            p[2] = static_cast<std::uint8_t>(std::lround((n.z * 0.5f + 0.5f) * 255.0f));
            p[3] = 255;
        }
    return img;
}

ImageRecord make_checker(std::uint32_t size, std::uint32_t cells) {
    ImageRecord img = new_image("builtin:checker", size);
    const std::uint32_t cell = size / cells;
    for (std::uint32_t y = 0; y < size; ++y)
        for (std::uint32_t x = 0; x < size; ++x) {
            const bool dark = ((x / cell) + (y / cell)) % 2 == 0;
            std::uint8_t* p = &img.pixels[(std::size_t{y} * size + x) * 4];
            p[0] = dark ? 90 : 200;
            p[1] = dark ? 96 : 205;
            p[2] = dark ? 105 : 210;
            p[3] = 255;
        }
    return img;
}

ImageRecord make_disc_mask(std::uint32_t size, std::uint32_t discs_per_side) {
    ImageRecord img = new_image("builtin:disc_mask", size);
    const float cell = static_cast<float>(size) / discs_per_side;
    for (std::uint32_t y = 0; y < size; ++y)
        for (std::uint32_t x = 0; x < size; ++x) {
            const float fx = std::fmod(static_cast<float>(x) + 0.5f, cell) / cell - 0.5f;
            const float fy = std::fmod(static_cast<float>(y) + 0.5f, cell) / cell - 0.5f;
            const bool inside = fx * fx + fy * fy < 0.16f;
            std::uint8_t* p = &img.pixels[(std::size_t{y} * size + x) * 4];
            p[0] = 230;
            p[1] = 120;
            p[2] = 40;
            p[3] = inside ? 255 : 0;
        }
    return img;
}

} // namespace sherpa::scene::detail
