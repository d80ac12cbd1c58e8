// The lighting family's per-pixel material ids (a small BVH over world-space triangles,
// one primary ray per pixel centre) and its image differences.
#include "lighting_images.h"

#include <sherpa/texture/mips.h>
#include <sherpa/texture/quality.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include <glm/gtc/constants.hpp>

namespace sherpa::lab::detail {
namespace {

struct Triangle {
    glm::vec3 a, b, c;
    std::int32_t material = -1;
};

struct Node {
    glm::vec3 lo{std::numeric_limits<float>::max()}, hi{-std::numeric_limits<float>::max()};
    std::uint32_t first = 0, count = 0; // leaf: triangles [first, first + count)
    std::uint32_t left = 0;             // inner: children left, left + 1
};

constexpr std::uint32_t kLeafSize = 4;

class Bvh {
public:
    explicit Bvh(std::vector<Triangle> triangles) : tris_(std::move(triangles)) {
        if (tris_.empty()) return;
        nodes_.reserve(2 * tris_.size());
        nodes_.push_back({});
        nodes_[0].count = std::uint32_t(tris_.size());
        // Iterative build: split each node at the median centroid of its longest axis.
        std::vector<std::uint32_t> todo{0};
        while (!todo.empty()) {
            const std::uint32_t n = todo.back();
            todo.pop_back();
            Node node = nodes_[n];
            glm::vec3 clo(std::numeric_limits<float>::max()), chi(-clo);
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                const Triangle& t = tris_[i];
                node.lo = glm::min(node.lo, glm::min(t.a, glm::min(t.b, t.c)));
                node.hi = glm::max(node.hi, glm::max(t.a, glm::max(t.b, t.c)));
                const glm::vec3 centroid = (t.a + t.b + t.c) / 3.0f;
                clo = glm::min(clo, centroid), chi = glm::max(chi, centroid);
            }
            const glm::vec3 extent = chi - clo;
            const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                             : extent.y >= extent.z                       ? 1
                                                                          : 2;
            if (node.count <= kLeafSize || !(extent[axis] > 0.0f)) {
                nodes_[n] = node;
                continue;
            }
            const std::uint32_t half = node.count / 2;
            auto begin = tris_.begin() + node.first;
            std::nth_element(begin, begin + half, begin + node.count,
                             [axis](const Triangle& x, const Triangle& y) {
                                 return x.a[axis] + x.b[axis] + x.c[axis] <
                                        y.a[axis] + y.b[axis] + y.c[axis];
                             });
            node.left = std::uint32_t(nodes_.size());
            Node l, r;
            l.first = node.first, l.count = half;
            r.first = node.first + half, r.count = node.count - half;
            node.count = 0;
            nodes_[n] = node;
            nodes_.push_back(l);
            nodes_.push_back(r);
            todo.push_back(node.left);
            todo.push_back(node.left + 1);
        }
    }

    // The material of the nearest hit along origin + t dir (t > 0), -1 for none.
    std::int32_t trace(glm::vec3 origin, glm::vec3 dir) const {
        if (nodes_.empty()) return -1;
        const glm::vec3 inv = 1.0f / dir;
        float best = std::numeric_limits<float>::max();
        std::int32_t material = -1;
        std::array<std::uint32_t, 64> stack;
        std::size_t top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& node = nodes_[stack[--top]];
            if (!hits_box(node, origin, inv, best)) continue;
            if (node.count > 0) {
                for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                    const float t = intersect(tris_[i], origin, dir);
                    if (t > 0.0f && t < best) best = t, material = tris_[i].material;
                }
            } else if (top + 2 <= stack.size()) {
                stack[top++] = node.left;
                stack[top++] = node.left + 1;
            }
        }
        return material;
    }

private:
    static bool hits_box(const Node& n, glm::vec3 o, glm::vec3 inv, float best) {
        const glm::vec3 t0 = (n.lo - o) * inv, t1 = (n.hi - o) * inv;
        const glm::vec3 near = glm::min(t0, t1), far = glm::max(t0, t1);
        const float enter = std::max(std::max(near.x, near.y), std::max(near.z, 0.0f));
        const float leave = std::min(std::min(far.x, far.y), std::min(far.z, best));
        return enter <= leave;
    }
    // Moeller-Trumbore, both faces (the raster's culling of single-sided back faces is
    // not modelled: a pixel that sees a back face is still that material's surface).
    static float intersect(const Triangle& t, glm::vec3 o, glm::vec3 d) {
        const glm::vec3 e1 = t.b - t.a, e2 = t.c - t.a, p = glm::cross(d, e2);
        const float det = glm::dot(e1, p);
        if (std::abs(det) < 1e-20f) return -1.0f;
        const float inv = 1.0f / det;
        const glm::vec3 s = o - t.a;
        const float u = glm::dot(s, p) * inv;
        if (u < 0.0f || u > 1.0f) return -1.0f;
        const glm::vec3 q = glm::cross(s, e1);
        const float v = glm::dot(d, q) * inv;
        if (v < 0.0f || u + v > 1.0f) return -1.0f;
        return glm::dot(e2, q) * inv;
    }

    std::vector<Triangle> tris_;
    std::vector<Node> nodes_;
};

bool finite(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::vector<Triangle> world_triangles(const scene::Scene& scene) {
    std::vector<Triangle> out;
    for (const scene::MeshInstance& inst : scene.instances) {
        if (inst.mesh_id >= scene.meshes.size()) continue;
        const scene::Mesh& mesh = scene.meshes[inst.mesh_id];
        if (mesh.topology() != scene::Topology::Triangles) continue;
        const std::int32_t material = std::int32_t(inst.material_id);
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            Triangle t;
            glm::vec3* corner[3] = {&t.a, &t.b, &t.c};
            bool ok = true;
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = mesh.indices[i + std::size_t(k)];
                if (v >= mesh.vertices.size()) {
                    ok = false;
                    break;
                }
                *corner[k] = glm::vec3(inst.world * glm::vec4(mesh.vertices[v].position, 1.0f));
            }
            t.material = material;
            if (ok && finite(t.a) && finite(t.b) && finite(t.c)) out.push_back(t);
        }
    }
    return out;
}

} // namespace

std::vector<std::int32_t> material_id_image(const scene::Scene& scene,
                                            const scene::CameraSpec& camera, std::uint32_t width,
                                            std::uint32_t height) {
    std::vector<std::int32_t> ids(std::size_t(width) * height, -1);
    const Bvh bvh(world_triangles(scene));
    const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::cross(right, forward);
    const float tan_half = std::tan(glm::radians(camera.fov_y_degrees) * 0.5f);
    const float aspect = camera.aspect > 0.0f ? camera.aspect : float(width) / float(height);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            // Pixel centres; row 0 is the top of the image (+Y up on screen).
            const float nx = 2.0f * (float(x) + 0.5f) / float(width) - 1.0f;
            const float ny = 1.0f - 2.0f * (float(y) + 0.5f) / float(height);
            const glm::vec3 dir =
                glm::normalize(forward + nx * tan_half * aspect * right + ny * tan_half * up);
            ids[std::size_t(y) * width + x] = bvh.trace(camera.eye, dir);
        }
    return ids;
}

std::vector<std::uint8_t> downsample_srgb(const std::vector<std::uint8_t>& rgba,
                                          std::uint32_t width, std::uint32_t height,
                                          std::uint32_t factor) {
    factor = std::max(factor, 1u);
    const std::size_t big_w = std::size_t(width) * factor;
    std::vector<std::uint8_t> out(std::size_t(width) * height * 4, 0);
    if (rgba.size() < big_w * height * factor * 4) return out;
    std::array<float, 256> linear;
    for (int i = 0; i < 256; ++i) linear[std::size_t(i)] = tex::srgb_to_linear(float(i) / 255.0f);
    const float n = float(factor * factor);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            float sum[4] = {};
            for (std::uint32_t dy = 0; dy < factor; ++dy)
                for (std::uint32_t dx = 0; dx < factor; ++dx) {
                    const std::uint8_t* p = &rgba[4 * ((std::size_t(y) * factor + dy) * big_w +
                                                       std::size_t(x) * factor + dx)];
                    for (int c = 0; c < 3; ++c) sum[c] += linear[p[c]];
                    sum[3] += float(p[3]);
                }
            std::uint8_t* o = &out[4 * (std::size_t(y) * width + x)];
            for (int c = 0; c < 3; ++c)
                o[c] = std::uint8_t(
                    std::lround(std::clamp(tex::linear_to_srgb(sum[c] / n), 0.0f, 1.0f) * 255.0f));
            o[3] = std::uint8_t(std::lround(sum[3] / n));
        }
    return out;
}

ImageDifference image_difference(const std::vector<std::uint8_t>& a,
                                 const std::vector<std::uint8_t>& b,
                                 const std::vector<std::int32_t>& ids, std::size_t materials) {
    ImageDifference out;
    out.material_mean.assign(materials, 0.0);
    out.material_pixels.assign(materials, 0);
    const std::size_t pixels = std::min({a.size() / 4, b.size() / 4, ids.size()});
    double sum = 0.0, squares = 0.0;
    for (std::size_t i = 0; i < pixels; ++i) {
        double d = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double e = double(a[4 * i + std::size_t(c)]) - double(b[4 * i + std::size_t(c)]);
            d += std::abs(e), squares += e * e;
        }
        sum += d;
        const std::int32_t m = ids[i];
        if (m >= 0 && std::size_t(m) < materials) {
            out.material_mean[std::size_t(m)] += d / 3.0;
            ++out.material_pixels[std::size_t(m)];
        }
    }
    out.pixels = pixels;
    out.mean = pixels ? sum / (3.0 * double(pixels)) : 0.0;
    out.psnr_db = tex::SquaredError{squares, 3 * std::uint64_t(pixels)}.psnr();
    for (std::size_t m = 0; m < materials; ++m)
        if (out.material_pixels[m]) out.material_mean[m] /= double(out.material_pixels[m]);
    return out;
}

} // namespace sherpa::lab::detail
