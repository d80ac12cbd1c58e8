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
// What differs is the data layout and the work avoided: welding hashes indexed vertices
// instead of gridding corners, edges are bucketed instead of quicksorted, per-group
// projections are computed once instead of once per pair, the subgroup search is skipped
// when every pair in a group provably agrees (the common case), and acos is a polynomial.
// Results equal the reference's to float rounding (about 1e-5 degrees), except where the
// reference returns nothing usable, on purpose:
//  - lengths are computed without overflow/underflow (coordinates beyond ~1e19 or below
//    ~1e-19 lose their triangles in the reference);
//  - normals further than kNormalUnitTolerance from unit length are rescaled before
//    projecting (the reference's projection is then not orthogonal);
//  - a corner whose tangent would come only from zero-area triangles is left to the
//    guard (the reference returns dP/du along a collinear line, or zero).
#include <algorithm>

#include "tangent_corner_angles.h"
#include "tangent_internal.h"

namespace sherpa::scene::tangent_detail {
namespace {

constexpr std::uint8_t kOrientPreserving = 1; // uv winding agrees with position winding
constexpr std::uint8_t kGroupWithAny = 2;     // zero uv area or zero tangent magnitude
// Zero area in position space (collinear or coincident corners). The reference still
// uses such triangles; a corner whose tangent comes from nothing but them gets the
// fallback instead (its dP/du only runs along a line, or nowhere).
constexpr std::uint8_t kZeroArea = 4;
constexpr std::uint32_t kNoGroup = ~0u;

// Per kept triangle: unit dP/du and dP/dv with orientation and degeneracy flags (the
// reference's InitTriInfo), and the weight of each corner: the angle between its two
// edges projected onto the tangent plane of the corner's normal (computed here, in one
// streaming pass, rather than from inside the groups).
void compute_triangle_frames(const TangentInput& in, const WeldedCorners& weld, TriangleSet& tris) {
    const std::size_t count = tris.original.size();
    tris.angle.resize(3 * count);
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
        if (zero_area(p1, p2, p3)) flags |= kZeroArea;
        if (not_zero(signed_area_x2)) {
            const float abs_area = std::fabs(signed_area_x2);
            const float len_os = robust_length(os), len_ot = robust_length(ot);
            const float sign = (flags & kOrientPreserving) ? 1.0f : -1.0f;
            if (not_zero(len_os)) tris.os[f] = (sign / len_os) * os;
            if (not_zero(len_ot)) tris.ot[f] = (sign / len_ot) * ot;
            if (not_zero(len_os / abs_area) && not_zero(len_ot / abs_area)) flags &= ~kGroupWithAny;
        }
        tris.flags[f] = flags;
        const glm::vec3 p[3] = {p1, p2, p3};
        const glm::vec3 n[3] = {weld.class_normal[tris.cls[3 * f]],
                                weld.class_normal[tris.cls[3 * f + 1]],
                                weld.class_normal[tris.cls[3 * f + 2]]};
        if (!triangle_corner_angles(p, n, &tris.angle[3 * f]))
            for (int c = 0; c < 3; ++c)
                tris.angle[3 * f + c] =
                    corner_angle(p[(c + 2) % 3] - p[c], p[(c + 1) % 3] - p[c], n[c]);
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
void build_groups(TriangleSet& tris, GroupScratch& scratch) {
    const std::size_t count = tris.original.size();
    tris.group_of.assign(3 * count, kNoGroup);
    // Sized up front to their bounds (every corner joins at most one group; a group holds
    // a triangle at most once, and each triangle it takes pushes two neighbours), so the
    // walk below needs no capacity checks.
    scratch.members.resize(3 * count);
    scratch.stack.resize(2 * count + 2);
    std::uint32_t* members = scratch.members.data();
    std::int32_t* stack = scratch.stack.data();
    std::size_t member_count = 0;
    auto& groups = scratch.groups;
    groups.clear();
    groups.reserve(count); // typically about one group per vertex: half the triangles
    for (std::size_t f = 0; f < count; ++f) {
        if (tris.flags[f] & kGroupWithAny) continue;
        for (int i = 0; i < 3; ++i) {
            if (tris.group_of[3 * f + i] != kNoGroup) continue;
            const auto id = static_cast<std::uint32_t>(groups.size());
            Group g{tris.cls[3 * f + i], static_cast<std::uint32_t>(member_count), 0,
                    (tris.flags[f] & kOrientPreserving) != 0};
            members[member_count++] = member(f, i);
            tris.group_of[3 * f + i] = id;
            std::size_t top = 0;
            stack[top++] = tris.neighbour[3 * f + (i + 2) % 3];
            stack[top++] = tris.neighbour[3 * f + i];
            while (top > 0) {
                const std::int32_t t = stack[--top];
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
                members[member_count++] = member(std::size_t(t), c);
                assigned[c] = id;
                const std::int32_t* nb = &tris.neighbour[3 * std::size_t(t)];
                stack[top++] = nb[(c + 2) % 3]; // right, visited after all of left
                stack[top++] = nb[c];           // left
            }
            g.size = static_cast<std::uint32_t>(member_count) - g.first;
            groups.push_back(g);
        }
    }
    scratch.members.resize(member_count);
}

// For four group members: dP/du projected onto the tangent plane of n and normalised,
// and dP/dv projected only, in SIMD lanes with the scalar code's operations. Returns
// false (writing nothing) where a length needs robust_length's rescaling.
bool project_members(const TriangleSet& tris, const std::uint32_t* members, const glm::vec3& n,
                     glm::vec3* os_out, glm::vec3* ot_out) {
    const glm::vec3 &s0 = tris.os[members[0] >> 2], &s1 = tris.os[members[1] >> 2],
                    &s2 = tris.os[members[2] >> 2], &s3 = tris.os[members[3] >> 2];
    const glm::vec3 &t0 = tris.ot[members[0] >> 2], &t1 = tris.ot[members[1] >> 2],
                    &t2 = tris.ot[members[2] >> 2], &t3 = tris.ot[members[3] >> 2];
    const LaneVec normal{Lanes{} + n.x, Lanes{} + n.y, Lanes{} + n.z};
    const LaneVec os{Lanes{s0.x, s1.x, s2.x, s3.x}, Lanes{s0.y, s1.y, s2.y, s3.y},
                     Lanes{s0.z, s1.z, s2.z, s3.z}};
    const LaneVec ot{Lanes{t0.x, t1.x, t2.x, t3.x}, Lanes{t0.y, t1.y, t2.y, t3.y},
                     Lanes{t0.z, t1.z, t2.z, t3.z}};
    LaneMask in_range = LaneMask{} == 0;
    const LaneVec u = lane_project_normalized(os, normal, in_range);
    if (!(in_range[0] & in_range[1] & in_range[2] & in_range[3])) return false;
    const Lanes d = lane_dot(normal, ot);
    const LaneVec v{ot.x - normal.x * d, ot.y - normal.y * d, ot.z - normal.z * d};
    for (int k = 0; k < 4; ++k) {
        os_out[k] = glm::vec3(u.x[k], u.y[k], u.z[k]);
        ot_out[k] = glm::vec3(v.x[k], v.y[k], v.z[k]);
    }
    return true;
}

// Angle-weighted average of the projected dP/du over `sorted` (members, in ascending
// triangle order to sum like the reference; `proj_os[k]` belongs to sorted[k]): the
// reference's EvalTspace.
glm::vec3 eval_tangent(const TriangleSet& tris, std::span<const std::uint32_t> sorted,
                       std::span<const glm::vec3> proj_os) {
    glm::vec3 sum(0.0f);
    bool any_area = false;
    for (std::size_t k = 0; k < sorted.size(); ++k) {
        const std::uint32_t f = sorted[k] >> 2, c = sorted[k] & 3;
        if (tris.flags[f] & kGroupWithAny) continue;
        sum += tris.angle[3 * std::size_t(f) + c] * proj_os[k];
        any_area = any_area || !(tris.flags[f] & kZeroArea);
    }
    if (!any_area) return glm::vec3(0.0f); // see kZeroArea
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
                        std::span<std::uint8_t> assigned, std::uint64_t& rescaled_normals,
                        TangentWorkspace::Buffers& buffers) {
    const std::size_t tri_count = in.indices.size() / 3;
    WeldedCorners& weld = buffers.weld;
    weld_corners(in, weld);
    rescaled_normals = weld.rescaled_normals;

    // Unassigned corners keep the reference's default: tangent +x, bitangent sign -1
    // (+1 once flipped to glTF's v-down convention below).
    std::fill(out.begin(), out.end(), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    std::fill(assigned.begin(), assigned.end(), std::uint8_t{0});

    TriangleSet& tris = buffers.tris;
    tris.original.clear();
    tris.dropped.clear();
    tris.cls.clear();
    tris.original.reserve(tri_count);
    tris.cls.reserve(3 * tri_count);
    for (std::size_t t = 0; t < tri_count; ++t) {
        const std::uint32_t* c = &weld.corner_class[3 * t];
        if (c[0] == c[1] || c[0] == c[2] || c[1] == c[2]) {
            tris.dropped.push_back(static_cast<std::uint32_t>(t));
            continue;
        }
        tris.original.push_back(static_cast<std::uint32_t>(t));
        tris.cls.insert(tris.cls.end(), c, c + 3);
    }
    compute_triangle_frames(in, weld, tris);
    tris.neighbour.resize(tris.cls.size());
    build_neighbours(tris.cls, static_cast<std::uint32_t>(weld.class_normal.size()), tris.neighbour,
                     buffers.neighbours);
    GroupScratch& scratch = buffers.groups;
    build_groups(tris, scratch);
    const auto& members = scratch.members;

    // The reference's threshold is cos(180°) computed in float, i.e. exactly -1: two
    // triangles stay in one subgroup unless their projected tangents point exactly apart.
    constexpr float kThresholdCos = -1.0f;
    auto &proj_os = scratch.proj_os, &proj_ot = scratch.proj_ot, &sorted_os = scratch.sorted_os,
         &subgroup_tangent = scratch.subgroup_tangent;
    auto &sorted = scratch.sorted, &subgroup_members = scratch.subgroup_members,
         &subgroup_first = scratch.subgroup_first;
    for (const Group& g : scratch.groups) {
        const std::span<const std::uint32_t> group(&members[g.first], g.size);
        const glm::vec3 n = weld.class_normal[g.cls];
        const bool usable = weld.class_normal_usable[g.cls] != 0;
        // Projected dP/du, normalised: what the tangent averages. dP/dv only matters for
        // the subgroup test, and only normalised when that test cannot be settled cheaply.
        proj_os.resize(g.size);
        proj_ot.resize(g.size);
        std::uint32_t done = 0;
        for (; done + 4 <= g.size; done += 4) // four members at a time where lengths allow
            if (!project_members(tris, &group[done], n, &proj_os[done], &proj_ot[done])) break;
        for (; done < g.size; ++done) {
            proj_os[done] = project_normalized(tris.os[group[done] >> 2], n);
            const glm::vec3& ot = tris.ot[group[done] >> 2];
            proj_ot[done] = ot - n * dot3(n, ot);
        }
        // The reference's subgroup relation (needs proj_ot normalised).
        auto together = [&](std::uint32_t a, std::uint32_t b) {
            return a == b ||
                   ((tris.flags[group[a] >> 2] | tris.flags[group[b] >> 2]) & kGroupWithAny) ||
                   (dot3(proj_os[a], proj_os[b]) > kThresholdCos &&
                    dot3(proj_ot[a], proj_ot[b]) > kThresholdCos);
        };
        // Usually every pair is together, and that is cheap to prove: unit vectors all
        // within 89.4° of one of them (cosine > 0.01) are at most 178.9° apart pairwise,
        // so their dot products stay far above the threshold of -1. The dP/dv test runs
        // on unnormalised projections: cos > 0.01 <=> d > 0 and d^2 > 1e-4 |a|^2 |b|^2.
        bool all_together = true;
        const float ot0 = dot3(proj_ot[0], proj_ot[0]);
        for (std::uint32_t m = 1; m < g.size && all_together; ++m) {
            const float d = dot3(proj_ot[0], proj_ot[m]);
            all_together = dot3(proj_os[0], proj_os[m]) > 0.01f && d > 0.0f &&
                           d * d > 1e-4f * ot0 * dot3(proj_ot[m], proj_ot[m]);
        }
        if (!all_together) {
            for (glm::vec3& ot : proj_ot)
                if (not_zero(ot)) ot = normalized(ot); // as the reference has them
            all_together = true;
            for (std::uint32_t a = 0; a < g.size && all_together; ++a)
                for (std::uint32_t b = a + 1; b < g.size && all_together; ++b)
                    all_together = together(a, b);
        }

        auto write = [&](std::uint32_t m, const glm::vec3& tangent) {
            const std::size_t corner =
                3 * std::size_t(tris.original[group[m] >> 2]) + (group[m] & 3);
            out[corner] = glm::vec4(tangent, g.orient_preserving ? -1.0f : 1.0f);
            // A zero or non-finite result (cancelled sums, NaN input) and an unusable
            // normal count as not computed: the guard replaces them.
            assigned[corner] = usable && finite(tangent) && not_zero(tangent) ? 1 : 0;
        };
        if (all_together) {
            // One subgroup: the whole group. The reference sums it in ascending triangle
            // order; summing in group order instead changes results by float rounding
            // only (about 1e-7 relative) and saves sorting every group.
            const glm::vec3 tangent = eval_tangent(tris, group, proj_os);
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
    if (!tris.dropped.empty()) {
        auto& first_kept = scratch.first_kept;
        first_kept.assign(weld.class_normal.size(), ~0u);
        for (std::size_t f = 0; f < tris.original.size(); ++f)
            for (int i = 0; i < 3; ++i) {
                std::uint32_t& first = first_kept[tris.cls[3 * f + i]];
                if (first == ~0u) first = 3 * tris.original[f] + i;
            }
        for (std::uint32_t t : tris.dropped)
            for (int i = 0; i < 3; ++i) {
                const std::size_t corner = 3 * std::size_t(t) + i;
                const std::uint32_t source = first_kept[weld.corner_class[corner]];
                if (source == ~0u) continue;
                out[corner] = out[source];
                assigned[corner] = assigned[source];
            }
    }
}

} // namespace sherpa::scene::tangent_detail
