// Geometry of matched primitives compared vertex to nearest vertex, in world space.
#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include <sherpa/scene/tangent_compare.h>

#include "compare_detail.h"

namespace sherpa::lab::detail {
namespace {

struct WorldVertex {
    glm::vec3 position, normal;
    glm::vec4 tangent;
    glm::vec2 uv;
};

std::vector<WorldVertex> world_vertices(const scene::Scene& scene, std::uint32_t mesh_id) {
    const scene::Mesh& mesh = scene.meshes[mesh_id];
    glm::mat4 world(1.0f);
    for (const scene::MeshInstance& inst : scene.instances)
        if (inst.mesh_id == mesh_id) {
            world = inst.world;
            break;
        }
    const glm::mat3 linear(world), normal_matrix = glm::transpose(glm::inverse(linear));
    glm::mat3 uv_matrix(1.0f);
    if (mesh.material_id < scene.materials.size()) {
        const scene::TextureTransform& t = scene.materials[mesh.material_id].base_color.transform;
        if (t.present) uv_matrix = t.matrix();
    }
    std::vector<WorldVertex> out;
    out.reserve(mesh.vertices.size());
    for (const scene::Vertex& v : mesh.vertices) {
        const glm::vec3 n = normal_matrix * v.normal, t = linear * glm::vec3(v.tangent);
        out.push_back({glm::vec3(world * glm::vec4(v.position, 1.0f)),
                       glm::length(n) > 0.0f ? glm::normalize(n) : n, glm::vec4(t, v.tangent.w),
                       glm::vec2(uv_matrix * glm::vec3(v.uv0, 1.0f))});
    }
    return out;
}

// Positions bucketed on a uniform grid; nearest() searches rings of cells outward.
class NearestGrid {
public:
    explicit NearestGrid(const std::vector<WorldVertex>& v) : v_(v) {
        core::Aabb box;
        for (const WorldVertex& w : v) box.expand(w.position);
        const float extent =
            box.valid() ? std::max({box.extent().x, box.extent().y, box.extent().z}) : 0.0f;
        cell_ = extent > 0.0f ? extent / std::max(1.0f, std::cbrt(float(v.size()))) : 1.0f;
        lo_ = glm::ivec3(std::numeric_limits<int>::max()), hi_ = -lo_;
        for (std::size_t i = 0; i < v.size(); ++i) {
            const glm::ivec3 c = cell(v[i].position);
            lo_ = glm::min(lo_, c), hi_ = glm::max(hi_, c);
            cells_[key(c)].push_back(i);
        }
    }
    // Index of the vertex nearest to `q`; among those at the same distance, the one
    // whose normal and uv are closest.
    std::size_t nearest(const WorldVertex& q) const {
        const glm::ivec3 c = cell(q.position);
        const glm::ivec3 reach = glm::max(glm::abs(c - lo_), glm::abs(hi_ - c));
        const int max_ring = std::max({reach.x, reach.y, reach.z});
        std::vector<std::pair<float, std::size_t>> found;
        float best = INFINITY;
        for (int r = 0; r <= max_ring; ++r) {
            for (int dx = -r; dx <= r; ++dx)
                for (int dy = -r; dy <= r; ++dy)
                    for (int dz = -r; dz <= r; ++dz) {
                        if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != r) continue;
                        const auto it = cells_.find(key(c + glm::ivec3(dx, dy, dz)));
                        if (it == cells_.end()) continue;
                        for (std::size_t i : it->second) {
                            const float d = glm::length(v_[i].position - q.position);
                            found.emplace_back(d, i);
                            best = std::min(best, d);
                        }
                    }
            if (best <= float(r) * cell_) break;
        }
        std::size_t pick = 0;
        float pick_score = INFINITY;
        for (const auto& [d, i] : found) {
            if (d > best) continue;
            const float score = glm::length(v_[i].normal - q.normal) + glm::length(v_[i].uv - q.uv);
            if (score < pick_score) pick_score = score, pick = i;
        }
        return pick;
    }

private:
    glm::ivec3 cell(glm::vec3 p) const { return glm::ivec3(glm::floor(p / cell_)); }
    static std::uint64_t key(glm::ivec3 c) {
        return (std::uint64_t(std::uint32_t(c.x) & 0x1fffff) << 42) |
               (std::uint64_t(std::uint32_t(c.y) & 0x1fffff) << 21) |
               std::uint64_t(std::uint32_t(c.z) & 0x1fffff);
    }
    const std::vector<WorldVertex>& v_;
    float cell_ = 1.0f;
    glm::ivec3 lo_, hi_;
    std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

struct Sums {
    double pos_sq = 0.0, normal_sum = 0.0, tangent_sum = 0.0, uv_sq = 0.0;
    std::uint64_t n = 0;
};

double angle(glm::vec3 a, glm::vec3 b) {
    const double d = scene::tangent_angle_degrees(glm::vec4(a, 0.0f), glm::vec4(b, 0.0f));
    return std::isfinite(d) ? d : 180.0;
}

// Every vertex of `from` against its nearest in `to`.
void one_way(const std::vector<WorldVertex>& from, const std::vector<WorldVertex>& to,
             bool tangents, PrimitiveDiff& d, Sums& s) {
    const NearestGrid grid(to);
    for (const WorldVertex& q : from) {
        const WorldVertex& m = to[grid.nearest(q)];
        const double dp = glm::length(glm::dvec3(m.position) - glm::dvec3(q.position));
        const double duv = glm::length(glm::dvec2(m.uv) - glm::dvec2(q.uv));
        const double na = angle(q.normal, m.normal);
        d.position_max = std::max(d.position_max, dp);
        d.uv_max = std::max(d.uv_max, duv);
        d.normal_max_deg = std::max(d.normal_max_deg, na);
        s.pos_sq += dp * dp, s.uv_sq += duv * duv, s.normal_sum += na;
        if (tangents) {
            const double ta = angle(glm::vec3(q.tangent), glm::vec3(m.tangent));
            d.tangent_max_deg = std::max(d.tangent_max_deg.value_or(0.0), ta);
            s.tangent_sum += ta;
        }
        ++s.n;
    }
}

bool has_tangents(const scene::Mesh& m) {
    return m.provenance_of(scene::VertexAttribute::Tangent) != scene::Provenance::Defaulted;
}

} // namespace

std::vector<PrimitiveDiff> compare_primitives(const scene::Scene& a, const scene::Scene& b) {
    std::vector<PrimitiveDiff> out;
    for (std::size_t g = 0; g < a.mesh_primitives.size(); ++g)
        for (std::size_t p = 0; p < a.mesh_primitives[g].size(); ++p) {
            PrimitiveDiff d;
            d.mesh = std::uint32_t(g), d.primitive = std::uint32_t(p);
            const std::int32_t ia = a.mesh_primitives[g][p];
            const std::int32_t ib = g < b.mesh_primitives.size() && p < b.mesh_primitives[g].size()
                                        ? b.mesh_primitives[g][p]
                                        : -1;
            if (ia < 0 || ib < 0) {
                d.note = ia < 0 ? "not drawable in A" : "no such primitive in B";
                out.push_back(std::move(d));
                continue;
            }
            const scene::Mesh &ma = a.meshes[std::size_t(ia)], &mb = b.meshes[std::size_t(ib)];
            d.vertices_a = ma.source_vertex_count, d.vertices_b = mb.source_vertex_count;
            d.indices_a = ma.indices.size(), d.indices_b = mb.indices.size();
            if (ma.vertices.empty() || mb.vertices.empty()) {
                d.note = "no vertices";
                out.push_back(std::move(d));
                continue;
            }
            const auto va = world_vertices(a, std::uint32_t(ia)),
                       vb = world_vertices(b, std::uint32_t(ib));
            const bool tangents = has_tangents(ma) && has_tangents(mb);
            Sums s;
            one_way(va, vb, tangents, d, s);
            one_way(vb, va, tangents, d, s);
            d.position_rms = std::sqrt(s.pos_sq / double(s.n));
            d.uv_rms = std::sqrt(s.uv_sq / double(s.n));
            d.normal_mean_deg = s.normal_sum / double(s.n);
            if (tangents) d.tangent_mean_deg = s.tangent_sum / double(s.n);
            out.push_back(std::move(d));
        }
    return out;
}

} // namespace sherpa::lab::detail
