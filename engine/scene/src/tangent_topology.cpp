// MikkTSpace's topology steps: welding corners by value and finding adjacent triangles.
// The reference welds with a spatial grid and finds neighbours by quicksorting all edges;
// both results depend only on which corners are equal and on triangle order, so we get
// them with a hash over the (far fewer) distinct indexed vertices and a counting sort of
// edges by their lower vertex.
#include <algorithm>
#include <bit>
#include <cstring>

#include "tangent_internal.h"

namespace sherpa::scene::tangent_detail {
namespace {

constexpr std::uint32_t kNone = ~0u;

// The 8 floats MikkTSpace compares, with -0 folded into +0 so equal floats hash equally.
struct WeldKey {
    std::uint32_t bits[8];
};

WeldKey weld_key(const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv) {
    const float values[8] = {p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y};
    WeldKey key{};
    for (int i = 0; i < 8; ++i)
        key.bits[i] = values[i] == 0.0f ? 0u : std::bit_cast<std::uint32_t>(values[i]);
    return key;
}

bool has_nan(const WeldKey& key) {
    for (std::uint32_t b : key.bits)
        if ((b & 0x7fffffffu) > 0x7f800000u) return true;
    return false;
}

std::uint64_t hash_key(const WeldKey& key) {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (int i = 0; i < 8; i += 2) {
        const std::uint64_t word = (std::uint64_t(key.bits[i]) << 32) | key.bits[i + 1];
        h = (h ^ word) * 0xff51afd7ed558ccdull;
        h ^= h >> 32;
    }
    return h;
}

} // namespace

void weld_corners(const TangentInput& in, WeldedCorners& out) {
    const std::size_t corners = in.indices.size(), vertices = in.positions.size();
    out.corner_class.resize(corners);
    out.class_normal.clear();
    out.class_normal_usable.clear();
    out.class_vertex.clear();
    out.rescaled_normals = 0;
    // Reserved at their bound (one class per vertex, plus corners of vertices with NaN),
    // so growth never copies and re-faults the buffers.
    out.class_normal.reserve(vertices);
    out.class_normal_usable.reserve(vertices);
    out.class_vertex.reserve(vertices);
    auto new_class = [&](std::uint32_t v) {
        bool rescaled = false;
        out.class_normal.push_back(projection_normal(in.normals[v], rescaled));
        out.class_normal_usable.push_back(usable_normal(in.normals[v]) ? 1 : 0);
        out.rescaled_normals += rescaled ? 1 : 0;
        out.class_vertex.push_back(v);
        return static_cast<std::uint32_t>(out.class_normal.size() - 1);
    };

    // Corners sharing an index are equal unless the vertex holds a NaN, so only the
    // referenced vertices are hashed, in vertex order so that the hash-table slot of a
    // vertex a few steps ahead can be prefetched. Class ids are arbitrary labels: nothing
    // downstream depends on their order, only on which corners share one.
    constexpr std::uint32_t kReferenced = kNone - 1, kHasNan = kNone - 2;
    out.vertex_class.assign(vertices, kNone);
    for (std::uint32_t v : in.indices) out.vertex_class[v] = kReferenced;
    out.vertex_hash.resize(vertices);
    for (std::size_t v = 0; v < vertices; ++v) {
        if (out.vertex_class[v] != kReferenced) continue;
        const WeldKey key = weld_key(in.positions[v], in.normals[v], in.uvs[v]);
        if (has_nan(key))
            out.vertex_class[v] = kHasNan;
        else
            out.vertex_hash[v] = hash_key(key);
    }
    std::size_t capacity = 16;
    while (capacity < vertices * 2) capacity *= 2;
    constexpr std::uint64_t kEmpty = ~0ull, kTagMask = 0xffffffff00000000ull;
    out.table.assign(capacity, kEmpty); // tag (hash high half) | class id
    const std::size_t mask = capacity - 1;
    constexpr std::size_t kPrefetchDistance = 8;
    for (std::size_t v = 0; v < vertices; ++v) {
        if (v + kPrefetchDistance < vertices)
            __builtin_prefetch(&out.table[out.vertex_hash[v + kPrefetchDistance] & mask]);
        if (out.vertex_class[v] != kReferenced) continue;
        const std::uint64_t hash = out.vertex_hash[v], tag = hash & kTagMask;
        const WeldKey key = weld_key(in.positions[v], in.normals[v], in.uvs[v]);
        std::size_t slot = hash & mask;
        std::uint32_t cls = kNone;
        for (; out.table[slot] != kEmpty; slot = (slot + 1) & mask) {
            if ((out.table[slot] & kTagMask) != tag) continue;
            const auto candidate = static_cast<std::uint32_t>(out.table[slot]);
            const std::uint32_t u = out.class_vertex[candidate];
            if (std::memcmp(&key, weld_key(in.positions[u], in.normals[u], in.uvs[u]).bits,
                            sizeof key) == 0) {
                cls = candidate;
                break;
            }
        }
        if (cls == kNone) {
            cls = new_class(static_cast<std::uint32_t>(v));
            out.table[slot] = tag | cls;
        }
        out.vertex_class[v] = cls;
    }
    for (std::size_t c = 0; c < corners; ++c) {
        const std::uint32_t v = in.indices[c];
        // A NaN never equals anything, not even another corner of the same vertex.
        out.corner_class[c] = out.vertex_class[v] == kHasNan ? new_class(v) : out.vertex_class[v];
    }
}

void build_neighbours(std::span<const std::uint32_t> tri_class, std::uint32_t class_count,
                      std::span<std::int32_t> neighbour, NeighbourScratch& scratch) {
    const std::size_t edges = tri_class.size();
    std::fill(neighbour.begin(), neighbour.end(), -1);

    // Counting sort by the lower class; within a bucket edges stay in triangle order.
    auto& bucket_start = scratch.bucket_start;
    bucket_start.assign(std::size_t(class_count) + 1, 0);
    for (std::size_t t = 0; t < edges; t += 3) {
        const std::uint32_t a = tri_class[t], b = tri_class[t + 1], c = tri_class[t + 2];
        ++bucket_start[std::min(a, b) + 1];
        ++bucket_start[std::min(b, c) + 1];
        ++bucket_start[std::min(c, a) + 1];
    }
    for (std::size_t i = 1; i <= class_count; ++i) bucket_start[i] += bucket_start[i - 1];
    // Each entry: upper class in the high half; below it the edge id and one bit saying
    // whether the edge runs from the lower class to the upper. Sorting a bucket orders it
    // by (upper class, triangle) like the reference's three-key sort, and two edges of a
    // run are opposite exactly when their direction bits differ.
    auto& sorted = scratch.sorted;
    sorted.resize(edges);
    {
        auto& fill = scratch.fill;
        fill.assign(bucket_start.begin(), bucket_start.end() - 1);
        for (std::size_t e = 0; e < edges; ++e) {
            const std::uint32_t from = tri_class[e];
            const std::uint32_t to = tri_class[e % 3 == 2 ? e - 2 : e + 1];
            const std::uint64_t low_to_high = from < to ? 1 : 0;
            sorted[fill[std::min(from, to)]++] =
                (std::uint64_t(std::max(from, to)) << 32) | (std::uint64_t(e) << 1) | low_to_high;
        }
    }
    for (std::size_t k = 0; k < class_count; ++k) {
        auto first = sorted.begin() + bucket_start[k], last = sorted.begin() + bucket_start[k + 1];
        if (last - first <= 16) { // typical valence: insertion sort beats std::sort setup
            for (auto it = first + 1; it < last; ++it)
                for (auto j = it; j > first && *(j - 1) > *j; --j) std::iter_swap(j - 1, j);
        } else {
            std::sort(first, last);
        }
        // Pair within runs of equal upper class: each unpaired edge takes the first later
        // unpaired edge that runs the opposite way.
        for (auto i = first; i < last; ++i) {
            const auto a = static_cast<std::uint32_t>(*i) >> 1;
            if (neighbour[a] != -1) continue;
            for (auto j = i + 1; j < last && (*j >> 32) == (*i >> 32); ++j) {
                const auto b = static_cast<std::uint32_t>(*j) >> 1;
                if (((*i ^ *j) & 1) && neighbour[b] == -1) {
                    neighbour[a] = static_cast<std::int32_t>(b / 3);
                    neighbour[b] = static_cast<std::int32_t>(a / 3);
                    break;
                }
            }
        }
    }
}

} // namespace sherpa::scene::tangent_detail
