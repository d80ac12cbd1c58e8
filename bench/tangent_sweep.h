#pragma once
// Generated meshes that break tangent methods, each with the tangent every corner
// should get: a unit grid in the XY plane (u = x, v = 1 - y, so tangent +x, w = +1) and
// damaged or rescaled variants of it, mirrored uv islands, and a thin rounded bevel.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "tangent_meshes.h"

namespace sherpa::bench {

struct SweepCase {
    BenchMesh mesh;
    std::vector<glm::vec4> expected; // per corner
};

inline BenchMesh make_grid(std::uint32_t n, float scale = 1.0f,
                           glm::vec3 offset = glm::vec3(0.0f)) {
    BenchMesh m;
    for (std::uint32_t j = 0; j <= n; ++j)
        for (std::uint32_t i = 0; i <= n; ++i) {
            const float x = float(i) / n, y = float(j) / n;
            m.positions.push_back(offset + scale * glm::vec3(x, y, 0.0f));
            m.normals.push_back({0, 0, 1});
            m.uvs.push_back({x, 1.0f - y});
        }
    for (std::uint32_t j = 0; j < n; ++j)
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
        }
    return m;
}

// Gives triangle t its own copies of its vertices, so damage stays local to it.
inline void detach_triangle(BenchMesh& m, std::size_t t) {
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = m.indices[3 * t + k];
        m.positions.push_back(m.positions[v]);
        m.normals.push_back(m.normals[v]);
        m.uvs.push_back(m.uvs[v]);
        m.indices[3 * t + k] = static_cast<std::uint32_t>(m.positions.size() - 1);
    }
}

inline SweepCase with_expected(BenchMesh mesh, glm::vec4 tangent) {
    SweepCase c{std::move(mesh), {}};
    c.expected.assign(c.mesh.indices.size(), tangent);
    return c;
}

inline std::vector<SweepCase> make_sweep() {
    constexpr std::uint32_t kGrid = 24;
    const glm::vec4 plus_x(1, 0, 0, 1);
    std::vector<SweepCase> cases;
    auto grid_case = [&](std::string name, float scale = 1.0f, glm::vec3 offset = glm::vec3(0.0f)) {
        BenchMesh m = make_grid(kGrid, scale, offset);
        m.name = std::move(name);
        return with_expected(std::move(m), plus_x);
    };
    cases.push_back(grid_case("clean-grid"));
    {
        SweepCase c = grid_case("zero-area-uv");
        for (std::size_t t = 0; t < c.mesh.triangles(); t += 7) {
            detach_triangle(c.mesh, t);
            for (int k = 1; k < 3; ++k)
                c.mesh.uvs[c.mesh.indices[3 * t + k]] = c.mesh.uvs[c.mesh.indices[3 * t]];
        }
        cases.push_back(std::move(c));
    }
    {
        SweepCase c = grid_case("collinear-corners");
        for (std::size_t t = 0; t < c.mesh.triangles(); t += 7) {
            detach_triangle(c.mesh, t);
            const glm::vec3 a = c.mesh.positions[c.mesh.indices[3 * t]],
                            b = c.mesh.positions[c.mesh.indices[3 * t + 1]];
            c.mesh.positions[c.mesh.indices[3 * t + 2]] = a + 0.5f * (b - a);
        }
        cases.push_back(std::move(c));
    }
    {
        // Right half mirrored in u about x = 0.5; the seam column's vertices are shared.
        SweepCase c = grid_case("mirrored-uv-island");
        for (glm::vec2& uv : c.mesh.uvs)
            if (uv.x > 0.5f) uv.x = 1.0f - uv.x;
        for (std::size_t t = 0; t < c.mesh.triangles(); ++t) {
            float x = 0.0f;
            for (int k = 0; k < 3; ++k) x += c.mesh.positions[c.mesh.indices[3 * t + k]].x / 3.0f;
            if (x > 0.5f)
                for (int k = 0; k < 3; ++k) c.expected[3 * t + k] = glm::vec4(-1, 0, 0, -1);
        }
        cases.push_back(std::move(c));
    }
    {
        SweepCase c = grid_case("non-unit-normals");
        for (std::size_t v = 0; v < c.mesh.normals.size(); ++v)
            c.mesh.normals[v] *= 0.25f + 0.5f * float(v % 8);
        cases.push_back(std::move(c));
    }
    {
        SweepCase c = grid_case("nan-normals");
        for (std::size_t v = 0; v < c.mesh.normals.size(); v += 11)
            c.mesh.normals[v] = glm::vec3(std::numeric_limits<float>::quiet_NaN());
        cases.push_back(std::move(c));
    }
    {
        SweepCase c = grid_case("zero-normals");
        for (std::size_t v = 0; v < c.mesh.normals.size(); v += 11)
            c.mesh.normals[v] = glm::vec3(0.0f);
        cases.push_back(std::move(c));
    }
    for (float scale : {1e-6f, 1e-3f, 1e3f, 1e6f, 1e20f})
        cases.push_back(grid_case("scale-" + std::to_string(int(std::log10(scale))), scale));
    cases.push_back(grid_case("offset-1e7", 1.0f, glm::vec3(1e7f, 0.0f, 0.0f)));
    {
        // Two faces meeting at a right angle through a rounded bevel of radius 1e-4
        // (8 segments): the edge runs along x, u = x, v along the cross-section.
        BenchMesh m;
        m.name = "thin-bevel";
        std::vector<glm::vec2> section;        // (y, z)
        std::vector<glm::vec2> section_normal; // (ny, nz)
        section.push_back({-1.0f, 0.0f});
        section_normal.push_back({0.0f, 1.0f});
        const float r = 1e-4f;
        for (int k = 0; k <= 8; ++k) {
            const float a = 1.5707963f * float(k) / 8.0f;
            section.push_back({r * std::sin(a), -r + r * std::cos(a)});
            section_normal.push_back({std::sin(a), std::cos(a)});
        }
        section.push_back({r, -1.0f});
        section_normal.push_back({1.0f, 0.0f});
        std::vector<float> arc(section.size(), 0.0f);
        for (std::size_t k = 1; k < section.size(); ++k)
            arc[k] = arc[k - 1] + glm::length(section[k] - section[k - 1]);
        const std::uint32_t along = 8, across = static_cast<std::uint32_t>(section.size());
        for (std::uint32_t i = 0; i <= along; ++i)
            for (std::uint32_t k = 0; k < across; ++k) {
                const float x = float(i) / along;
                m.positions.push_back({x, section[k].x, section[k].y});
                m.normals.push_back({0.0f, section_normal[k].x, section_normal[k].y});
                m.uvs.push_back({x, arc[k] / arc.back()});
            }
        for (std::uint32_t i = 0; i < along; ++i)
            for (std::uint32_t k = 0; k + 1 < across; ++k) {
                const std::uint32_t a = i * across + k, b = a + across, c = a + 1, d = b + 1;
                m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
            }
        // Tangent +x; v grows along the section away from face A (normal +z, going +y), so
        // the bitangent (towards decreasing v) is -y there: cross(+z, +x) = +y, so w = -1.
        cases.push_back(with_expected(std::move(m), glm::vec4(1, 0, 0, -1)));
    }
    return cases;
}

} // namespace sherpa::bench
