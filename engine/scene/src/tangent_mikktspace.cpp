// Exact MikkTSpace (Morten S. Mikkelsen's tangent space, as the reference implementation
// computes it with its default 180° angular threshold), for triangle lists.
//
// Steps, each reproducing the reference's result:
//  1. weld corners by value (tangent_topology.cpp);
//  2. drop triangles with a repeated welded vertex; keep the rest in their order;
//  3. per triangle: unit dP/du, dP/dv, their magnitudes, orientation, and whether the
//     triangle is degenerate in uv/position space ("group with any");
//  4. face adjacency (tangent_topology.cpp);
//  5. per corner, grow a group of triangles around its vertex through shared edges,
//     never crossing a change of uv orientation;
//  6. per group: split it into subgroups by tangent direction, then average each
//     subgroup's projected dP/du weighted by the corner angles;
//  7. corners of dropped triangles copy the first kept corner of their vertex.
// What differs is the data layout and the work avoided: per-group projections are
// computed once instead of once per pair, and the subgroup search is skipped when every
// pair in a group agrees (the common case).
#include <algorithm>

#include "tangent_internal.h"

namespace sherpa::tangent_detail {
namespace {

constexpr std::uint8_t kOrientPreserving = 1; // uv winding agrees with position winding
constexpr std::uint8_t kGroupWithAny = 2;     // zero uv area or zero tangent magnitude
constexpr std::uint32_t kNoGroup = ~0u;

// Per kept triangle, structure of arrays.
struct Triangles {
    std::vector<std::uint32_t> original; // triangle index in the input
    std::vector<std::uint32_t> cls;      // 3 welded classes per triangle
    std::vector<glm::vec3> os, ot;       // unit dP/du, dP/dv (zero when undefined)
    std::vector<std::uint8_t> flags;     // kOrientPreserving | kGroupWithAny
    std::vector<std::int32_t> neighbour; // 3 per triangle, across edge (i, i+1)
    std::vector<std::uint32_t> group_of; // 3 per triangle: the corner's group
    std::vector<float> angle;            // 3 per triangle: the corner's weight
};

struct Group {
    std::uint32_t cls;         // the welded vertex the group is around
    std::uint32_t first, size; // range in the face buffer
    bool orient_preserving;
};

void compute_triangle_frames(const TangentInput& in, Triangles& tris) {
    const std::size_t count = tris.original.size();
    tris.os.assign(count, glm::vec3(0.0f));
    tris.ot.assign(count, glm::vec3(0.0f));
    tris.flags.assign(count, kGroupWithAny);
    for (std::size_t f = 0; f < count; ++f) {
        const std::uint32_t* idx = &in.indices[3 * std::size_t(tris.original[f])];
        const glm::vec3 p1 = in.positions[idx[0]], p2 = in.positions[idx[1]],
                        p3 = in.positions[idx[2]];
        const glm::vec2 t1 = in.uvs[idx[0]], t2 = in.uvs[idx[1]], t3 = in.uvs[idx[2]];
        const float t21x = t2.x - t1.x, t21y = t2.y - t1.y;
        const float t31x = t3.x - t1.x, t31y = t3.y - t1.y;
        const glm::vec3 d1 = p2 - p1, d2 = p3 - p1;
        const float signed_area_x2 = t21x * t31y - t21y * t31x;
        const glm::vec3 os = t31y * d1 - t21y * d2;
        const glm::vec3 ot = -t31x * d1 + t21x * d2;
        std::uint8_t flags = kGroupWithAny | (signed_area_x2 > 0.0f ? kOrientPreserving : 0);
        if (not_zero(signed_area_x2)) {
            const float abs_area = std::fabs(signed_area_x2);
            const float len_os = robust_length(os), len_ot = robust_length(ot);
            const float sign = (flags & kOrientPreserving) ? 1.0f : -1.0f;
            if (not_zero(len_os)) tris.os[f] = (sign / len_os) * os;
            if (not_zero(len_ot)) tris.ot[f] = (sign / len_ot) * ot;
            if (not_zero(len_os / abs_area) && not_zero(len_ot / abs_area)) flags &= ~kGroupWithAny;
        }
        tris.flags[f] = flags;
    }
}

int corner_of(const std::uint32_t* cls3, std::uint32_t cls) {
    return cls3[0] == cls ? 0 : (cls3[1] == cls ? 1 : 2);
}

// Group members are stored as triangle << 2 | corner, so later steps need not search the
// triangle for the group's vertex again. Sorting these sorts by triangle.
std::uint32_t member(std::size_t triangle, int corner) {
    return static_cast<std::uint32_t>(triangle << 2) | static_cast<std::uint32_t>(corner);
}

// Groups corners around each vertex (the reference's Build4RuleGroups/AssignRecur). The
// reference recurses into the left neighbour, then the right; an explicit stack visits
// triangles in the same order, which matters: the first group to reach a "group with
// any" triangle decides that triangle's orientation.
std::vector<Group> build_groups(Triangles& tris, std::vector<std::uint32_t>& members) {
    const std::size_t count = tris.original.size();
    tris.group_of.assign(3 * count, kNoGroup);
    members.clear();
    members.reserve(3 * count);
    std::vector<Group> groups;
    groups.reserve(count);
    std::vector<std::int32_t> stack;
    for (std::size_t f = 0; f < count; ++f) {
        if (tris.flags[f] & kGroupWithAny) continue;
        for (int i = 0; i < 3; ++i) {
            if (tris.group_of[3 * f + i] != kNoGroup) continue;
            const auto id = static_cast<std::uint32_t>(groups.size());
            Group g{tris.cls[3 * f + i], static_cast<std::uint32_t>(members.size()), 0,
                    (tris.flags[f] & kOrientPreserving) != 0};
            members.push_back(member(f, i));
            tris.group_of[3 * f + i] = id;
            stack.assign({tris.neighbour[3 * f + (i + 2) % 3], tris.neighbour[3 * f + i]});
            while (!stack.empty()) {
                const std::int32_t t = stack.back();
                stack.pop_back();
                if (t < 0) continue;
                const std::uint32_t* cls3 = &tris.cls[3 * std::size_t(t)];
                std::uint32_t* assigned = &tris.group_of[3 * std::size_t(t)];
                const int c = corner_of(cls3, g.cls);
                if (assigned[c] != kNoGroup) continue; // already ours, or another group's
                std::uint8_t& flags = tris.flags[t];
                if ((flags & kGroupWithAny) && assigned[0] == kNoGroup && assigned[1] == kNoGroup &&
                    assigned[2] == kNoGroup)
                    flags = (flags & ~kOrientPreserving) | (g.orient_preserving ? 1 : 0);
                if (((flags & kOrientPreserving) != 0) != g.orient_preserving) continue;
                members.push_back(member(std::size_t(t), c));
                assigned[c] = id;
                const std::int32_t* nb = &tris.neighbour[3 * std::size_t(t)];
                stack.push_back(nb[(c + 2) % 3]); // right, visited after all of left
                stack.push_back(nb[c]);           // left
            }
            g.size = static_cast<std::uint32_t>(members.size()) - g.first;
            groups.push_back(g);
        }
    }
    return groups;
}

// acos on [-1, 1] from Abramowitz & Stegun 4.4.46 (|error| <= 2e-8 rad): the angle
// weights only need float accuracy, and this is several times cheaper than acosf.
float fast_acos(float x) {
    const float a = std::fabs(x);
    float p = -0.0012624911f;
    p = p * a + 0.0066700901f;
    p = p * a - 0.0170881256f;
    p = p * a + 0.0308918810f;
    p = p * a - 0.0501743046f;
    p = p * a + 0.0889789874f;
    p = p * a - 0.2145988016f;
    p = p * a + 1.5707963050f;
    const float r = std::sqrt(1.0f - a) * p;
    return x < 0.0f ? 3.14159265f - r : r;
}

// The angle of every kept corner between its two edges, projected onto the tangent
// plane of the corner's normal: the weight MikkTSpace gives the triangle at that vertex.
// One streaming pass instead of random access from inside the groups.
void compute_corner_angles(const TangentInput& in, const WeldedCorners& weld, Triangles& tris) {
    const std::size_t count = tris.original.size();
    tris.angle.resize(3 * count);
    for (std::size_t f = 0; f < count; ++f) {
        const std::uint32_t* idx = &in.indices[3 * std::size_t(tris.original[f])];
        const glm::vec3 p[3] = {in.positions[idx[0]], in.positions[idx[1]], in.positions[idx[2]]};
        for (int c = 0; c < 3; ++c) {
            const glm::vec3 n = weld.class_normal[tris.cls[3 * f + c]];
            const glm::vec3 v1 = project_normalized(p[(c + 2) % 3] - p[c], n);
            const glm::vec3 v2 = project_normalized(p[(c + 1) % 3] - p[c], n);
            tris.angle[3 * f + c] = fast_acos(std::clamp(dot3(v1, v2), -1.0f, 1.0f));
        }
    }
}

// Angle-weighted average of the projected dP/du over `sorted` (members in ascending
// triangle order; `proj_os[k]` belongs to sorted[k]): the reference's EvalTspace.
glm::vec3 eval_tangent(const Triangles& tris, std::span<const std::uint32_t> sorted,
                       std::span<const glm::vec3> proj_os) {
    glm::vec3 sum(0.0f);
    for (std::size_t k = 0; k < sorted.size(); ++k) {
        const std::uint32_t f = sorted[k] >> 2, c = sorted[k] & 3;
        if (tris.flags[f] & kGroupWithAny) continue;
        sum += tris.angle[3 * std::size_t(f) + c] * proj_os[k];
    }
    return not_zero(sum) ? normalized(sum) : sum;
}

// Sorts members (and their projected tangents alongside) by triangle. Groups hold a
// vertex's valence worth of members, so insertion sort.
void sort_members(std::span<std::uint32_t> m, std::span<glm::vec3> os) {
    for (std::size_t i = 1; i < m.size(); ++i)
        for (std::size_t j = i; j > 0 && m[j - 1] > m[j]; --j) {
            std::swap(m[j - 1], m[j]);
            std::swap(os[j - 1], os[j]);
        }
}

} // namespace

void mikktspace_corners(const TangentInput& in, std::span<glm::vec4> out,
                        std::span<std::uint8_t> assigned, std::uint64_t& rescaled_normals) {
    const std::size_t tri_count = in.indices.size() / 3;
    WeldedCorners weld = weld_corners(in);
    rescaled_normals = weld.rescaled_normals;

    // Unassigned corners keep the reference's default: tangent +x, bitangent sign -1
    // (+1 once flipped to glTF's v-down convention below).
    std::fill(out.begin(), out.end(), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    std::fill(assigned.begin(), assigned.end(), std::uint8_t{0});

    Triangles tris;
    tris.original.reserve(tri_count);
    tris.cls.reserve(3 * tri_count);
    std::vector<std::uint32_t> dropped; // repeated welded vertex
    for (std::size_t t = 0; t < tri_count; ++t) {
        const std::uint32_t* c = &weld.corner_class[3 * t];
        if (c[0] == c[1] || c[0] == c[2] || c[1] == c[2]) {
            dropped.push_back(static_cast<std::uint32_t>(t));
            continue;
        }
        tris.original.push_back(static_cast<std::uint32_t>(t));
        tris.cls.insert(tris.cls.end(), c, c + 3);
    }
    compute_triangle_frames(in, tris);
    tris.neighbour.resize(tris.cls.size());
    build_neighbours(tris.cls, static_cast<std::uint32_t>(weld.class_normal.size()),
                     tris.neighbour);
    compute_corner_angles(in, weld, tris);
    std::vector<std::uint32_t> members;
    const std::vector<Group> groups = build_groups(tris, members);

    // The reference's threshold is cos(180°) computed in float, i.e. exactly -1: two
    // triangles stay in one subgroup unless their projected tangents point exactly apart.
    constexpr float kThresholdCos = -1.0f;
    std::vector<glm::vec3> proj_os, proj_ot, sorted_os, subgroup_tangent;
    std::vector<std::uint32_t> sorted, subgroup_members, subgroup_first;
    for (const Group& g : groups) {
        const std::span<const std::uint32_t> group(&members[g.first], g.size);
        const glm::vec3 n = weld.class_normal[g.cls];
        proj_os.resize(g.size);
        proj_ot.resize(g.size);
        for (std::uint32_t m = 0; m < g.size; ++m) {
            proj_os[m] = project_normalized(tris.os[group[m] >> 2], n);
            proj_ot[m] = project_normalized(tris.ot[group[m] >> 2], n);
        }
        auto together = [&](std::uint32_t a, std::uint32_t b) {
            return a == b ||
                   ((tris.flags[group[a] >> 2] | tris.flags[group[b] >> 2]) & kGroupWithAny) ||
                   (dot3(proj_os[a], proj_os[b]) > kThresholdCos &&
                    dot3(proj_ot[a], proj_ot[b]) > kThresholdCos);
        };
        bool all_together = true;
        for (std::uint32_t a = 0; a < g.size && all_together; ++a)
            for (std::uint32_t b = a + 1; b < g.size && all_together; ++b)
                all_together = together(a, b);

        auto write = [&](std::uint32_t m, const glm::vec3& tangent) {
            const std::size_t corner =
                3 * std::size_t(tris.original[group[m] >> 2]) + (group[m] & 3);
            out[corner] = glm::vec4(tangent, g.orient_preserving ? -1.0f : 1.0f);
            assigned[corner] = 1;
        };
        if (all_together) { // one subgroup: the whole group
            sorted.assign(group.begin(), group.end());
            sorted_os.assign(proj_os.begin(), proj_os.end());
            sort_members(sorted, sorted_os);
            const glm::vec3 tangent = eval_tangent(tris, sorted, sorted_os);
            for (std::uint32_t m = 0; m < g.size; ++m) write(m, tangent);
            continue;
        }
        // General case: each corner's subgroup is the set of members it agrees with;
        // equal sets share one evaluation.
        subgroup_members.clear();
        subgroup_first.clear();
        subgroup_tangent.clear();
        for (std::uint32_t a = 0; a < g.size; ++a) {
            sorted.clear();
            sorted_os.clear();
            for (std::uint32_t b = 0; b < g.size; ++b)
                if (together(a, b)) {
                    sorted.push_back(group[b]);
                    sorted_os.push_back(proj_os[b]);
                }
            sort_members(sorted, sorted_os);
            std::size_t found = subgroup_first.size();
            for (std::size_t s = 0; s < subgroup_first.size(); ++s) {
                const std::size_t end =
                    s + 1 < subgroup_first.size() ? subgroup_first[s + 1] : subgroup_members.size();
                if (std::equal(sorted.begin(), sorted.end(),
                               subgroup_members.begin() + subgroup_first[s],
                               subgroup_members.begin() + end)) {
                    found = s;
                    break;
                }
            }
            if (found == subgroup_first.size()) {
                subgroup_first.push_back(static_cast<std::uint32_t>(subgroup_members.size()));
                subgroup_members.insert(subgroup_members.end(), sorted.begin(), sorted.end());
                subgroup_tangent.push_back(eval_tangent(tris, sorted, sorted_os));
            }
            write(a, subgroup_tangent[found]);
        }
    }

    // Corners of dropped triangles copy the first kept corner of the same welded vertex.
    if (!dropped.empty()) {
        std::vector<std::uint32_t> first_kept(weld.class_normal.size(), ~0u);
        for (std::size_t f = 0; f < tris.original.size(); ++f)
            for (int i = 0; i < 3; ++i) {
                std::uint32_t& first = first_kept[tris.cls[3 * f + i]];
                if (first == ~0u) first = 3 * tris.original[f] + i;
            }
        for (std::uint32_t t : dropped)
            for (int i = 0; i < 3; ++i) {
                const std::size_t corner = 3 * std::size_t(t) + i;
                const std::uint32_t source = first_kept[weld.corner_class[corner]];
                if (source == ~0u) continue;
                out[corner] = out[source];
                assigned[corner] = assigned[source];
            }
    }
}

} // namespace sherpa::tangent_detail
