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

// Groups corners around each vertex (the reference's Build4RuleGroups/AssignRecur). The
// reference recurses into the left neighbour, then the right; an explicit stack visits
// triangles in the same order, which matters: the first group to reach a "group with
// any" triangle decides that triangle's orientation.
std::vector<Group> build_groups(Triangles& tris, std::vector<std::uint32_t>& faces) {
    const std::size_t count = tris.original.size();
    tris.group_of.assign(3 * count, kNoGroup);
    faces.clear();
    faces.reserve(3 * count);
    std::vector<Group> groups;
    std::vector<std::int32_t> stack;
    for (std::size_t f = 0; f < count; ++f) {
        if (tris.flags[f] & kGroupWithAny) continue;
        for (int i = 0; i < 3; ++i) {
            if (tris.group_of[3 * f + i] != kNoGroup) continue;
            const auto id = static_cast<std::uint32_t>(groups.size());
            Group g{tris.cls[3 * f + i], static_cast<std::uint32_t>(faces.size()), 0,
                    (tris.flags[f] & kOrientPreserving) != 0};
            faces.push_back(static_cast<std::uint32_t>(f));
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
                faces.push_back(static_cast<std::uint32_t>(t));
                assigned[c] = id;
                const std::int32_t* nb = &tris.neighbour[3 * std::size_t(t)];
                stack.push_back(nb[(c + 2) % 3]); // right, visited after all of left
                stack.push_back(nb[c]);           // left
            }
            g.size = static_cast<std::uint32_t>(faces.size()) - g.first;
            groups.push_back(g);
        }
    }
    return groups;
}

// Angle-weighted average of the projected dP/du of `members` (ascending triangle order)
// at the group's vertex: the reference's EvalTspace. `proj_os` holds each member's
// projected, normalised dP/du, indexed like `members`.
glm::vec3 eval_tangent(const TangentInput& in, const Triangles& tris,
                       std::span<const std::uint32_t> members, std::span<const glm::vec3> proj_os,
                       std::uint32_t cls, const glm::vec3& n) {
    glm::vec3 sum(0.0f);
    for (std::size_t m = 0; m < members.size(); ++m) {
        const std::uint32_t f = members[m];
        if (tris.flags[f] & kGroupWithAny) continue;
        const int c = corner_of(&tris.cls[3 * std::size_t(f)], cls);
        const std::uint32_t* idx = &in.indices[3 * std::size_t(tris.original[f])];
        const glm::vec3 p0 = in.positions[idx[(c + 2) % 3]];
        const glm::vec3 p1 = in.positions[idx[c]];
        const glm::vec3 p2 = in.positions[idx[(c + 1) % 3]];
        const glm::vec3 v1 = project_normalized(p0 - p1, n);
        const glm::vec3 v2 = project_normalized(p2 - p1, n);
        const float cosine = std::clamp(dot3(v1, v2), -1.0f, 1.0f);
        sum += std::acos(cosine) * proj_os[m];
    }
    return not_zero(sum) ? normalized(sum) : sum;
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
    std::vector<std::uint32_t> faces;
    const std::vector<Group> groups = build_groups(tris, faces);

    // The reference's threshold is cos(180°) computed in float, i.e. exactly -1: two
    // triangles stay in one subgroup unless their projected tangents point exactly apart.
    constexpr float kThresholdCos = -1.0f;
    std::vector<glm::vec3> proj_os, proj_ot;
    std::vector<std::uint32_t> sorted, members, subgroup_members, subgroup_first, everyone, local;
    std::vector<glm::vec3> subgroup_tangent, member_os;
    for (const Group& g : groups) {
        const std::span<const std::uint32_t> group_faces(&faces[g.first], g.size);
        const glm::vec3 n = weld.class_normal[g.cls];
        proj_os.resize(g.size);
        proj_ot.resize(g.size);
        for (std::uint32_t m = 0; m < g.size; ++m) {
            proj_os[m] = project_normalized(tris.os[group_faces[m]], n);
            proj_ot[m] = project_normalized(tris.ot[group_faces[m]], n);
        }
        auto together = [&](std::uint32_t a, std::uint32_t b) {
            const std::uint32_t fa = group_faces[a], fb = group_faces[b];
            return a == b || ((tris.flags[fa] | tris.flags[fb]) & kGroupWithAny) ||
                   (dot3(proj_os[a], proj_os[b]) > kThresholdCos &&
                    dot3(proj_ot[a], proj_ot[b]) > kThresholdCos);
        };
        bool all_together = true;
        for (std::uint32_t a = 0; a < g.size && all_together; ++a)
            for (std::uint32_t b = a + 1; b < g.size && all_together; ++b)
                all_together = together(a, b);

        // Member positions within the group sorted by triangle index: the reference sums
        // each subgroup in ascending triangle order.
        auto write = [&](std::uint32_t m, const glm::vec3& tangent) {
            const std::uint32_t f = group_faces[m];
            const int c = corner_of(&tris.cls[3 * std::size_t(f)], g.cls);
            const std::size_t corner = 3 * std::size_t(tris.original[f]) + c;
            out[corner] = glm::vec4(tangent, g.orient_preserving ? -1.0f : 1.0f);
            assigned[corner] = 1;
        };
        auto eval_subgroup = [&](std::span<const std::uint32_t> positions_in_group) {
            sorted.clear();
            member_os.clear();
            for (std::uint32_t m : positions_in_group) sorted.push_back(m);
            std::sort(sorted.begin(), sorted.end(), [&](std::uint32_t a, std::uint32_t b) {
                return group_faces[a] < group_faces[b];
            });
            members.clear();
            for (std::uint32_t m : sorted) {
                members.push_back(group_faces[m]);
                member_os.push_back(proj_os[m]);
            }
            return eval_tangent(in, tris, members, member_os, g.cls, n);
        };
        if (all_together) {
            everyone.resize(g.size);
            for (std::uint32_t m = 0; m < g.size; ++m) everyone[m] = m;
            const glm::vec3 tangent = eval_subgroup(everyone);
            for (std::uint32_t m = 0; m < g.size; ++m) write(m, tangent);
            continue;
        }
        // General case: each corner's subgroup is the set of members it agrees with;
        // equal sets share one evaluation.
        subgroup_members.clear();
        subgroup_first.clear();
        subgroup_tangent.clear();
        for (std::uint32_t a = 0; a < g.size; ++a) {
            local.clear();
            for (std::uint32_t b = 0; b < g.size; ++b)
                if (together(a, b)) local.push_back(b);
            std::sort(local.begin(), local.end());
            std::size_t found = subgroup_first.size();
            for (std::size_t s = 0; s < subgroup_first.size(); ++s) {
                const std::size_t end =
                    s + 1 < subgroup_first.size() ? subgroup_first[s + 1] : subgroup_members.size();
                if (std::equal(local.begin(), local.end(),
                               subgroup_members.begin() + subgroup_first[s],
                               subgroup_members.begin() + end)) {
                    found = s;
                    break;
                }
            }
            if (found == subgroup_first.size()) {
                subgroup_first.push_back(static_cast<std::uint32_t>(subgroup_members.size()));
                subgroup_members.insert(subgroup_members.end(), local.begin(), local.end());
                subgroup_tangent.push_back(eval_subgroup(local));
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
