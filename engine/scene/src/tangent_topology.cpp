// MikkTSpace's topology steps: welding corners by value and finding adjacent triangles.
// The reference welds with a spatial grid and finds neighbours by quicksorting all edges;
// both results depend only on which corners are equal and on triangle order, so we get
// them with a hash over the (far fewer) distinct indexed vertices and a counting sort of
// edges by their lower vertex.
#include <algorithm>
#include <bit>
#include <cstring>

#include "tangent_internal.h"

namespace sherpa::tangent_detail {
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

WeldedCorners weld_corners(const TangentInput& in) {
    const std::size_t corners = in.indices.size();
    WeldedCorners out;
    out.corner_class.resize(corners);
    out.class_normal.reserve(in.positions.size());

    // Corners sharing an index are equal unless the vertex holds a NaN, so only distinct
    // indexed vertices need hashing.
    std::vector<std::uint32_t> vertex_class(in.positions.size(), kNone);
    std::vector<WeldKey> class_key;
    class_key.reserve(in.positions.size());
    std::size_t capacity = 16;
    while (capacity < in.positions.size() * 2) capacity *= 2;
    std::vector<std::uint32_t> table(capacity, kNone); // class ids
    const std::size_t mask = capacity - 1;

    auto new_class = [&](const glm::vec3& normal, const WeldKey& key) {
        bool rescaled = false;
        out.class_normal.push_back(projection_normal(normal, rescaled));
        out.rescaled_normals += rescaled ? 1 : 0;
        class_key.push_back(key);
        return static_cast<std::uint32_t>(out.class_normal.size() - 1);
    };

    for (std::size_t c = 0; c < corners; ++c) {
        const std::uint32_t v = in.indices[c];
        if (vertex_class[v] != kNone) {
            out.corner_class[c] = vertex_class[v];
            continue;
        }
        const WeldKey key = weld_key(in.positions[v], in.normals[v], in.uvs[v]);
        if (has_nan(key)) { // never equal to anything, not even to another corner of v
            out.corner_class[c] = new_class(in.normals[v], key);
            continue;
        }
        std::size_t slot = hash_key(key) & mask;
        std::uint32_t cls = kNone;
        while (table[slot] != kNone) {
            if (std::memcmp(&class_key[table[slot]], &key, sizeof key) == 0) {
                cls = table[slot];
                break;
            }
            slot = (slot + 1) & mask;
        }
        if (cls == kNone) {
            cls = new_class(in.normals[v], key);
            table[slot] = cls;
        }
        vertex_class[v] = cls;
        out.corner_class[c] = cls;
    }
    return out;
}

void build_neighbours(std::span<const std::uint32_t> tri_class, std::uint32_t class_count,
                      std::span<std::int32_t> neighbour) {
    const std::size_t edges = tri_class.size();
    std::fill(neighbour.begin(), neighbour.end(), -1);
    auto edge_from = [&](std::size_t e) { return tri_class[e]; };
    auto edge_to = [&](std::size_t e) { return tri_class[e - e % 3 + (e % 3 + 1) % 3]; };

    // Counting sort by the lower class; within a bucket edges stay in triangle order.
    std::vector<std::uint32_t> bucket_start(std::size_t(class_count) + 1, 0);
    for (std::size_t e = 0; e < edges; ++e) ++bucket_start[std::min(edge_from(e), edge_to(e)) + 1];
    for (std::size_t i = 1; i <= class_count; ++i) bucket_start[i] += bucket_start[i - 1];
    // Each entry: upper class in the high half, edge id in the low half, so sorting a
    // bucket orders it by (upper class, triangle) like the reference's three-key sort.
    std::vector<std::uint64_t> sorted(edges);
    {
        std::vector<std::uint32_t> fill(bucket_start.begin(), bucket_start.end() - 1);
        for (std::size_t e = 0; e < edges; ++e) {
            const std::uint32_t a = edge_from(e), b = edge_to(e);
            sorted[fill[std::min(a, b)]++] = (std::uint64_t(std::max(a, b)) << 32) | e;
        }
    }
    for (std::size_t k = 0; k < class_count; ++k) {
        auto first = sorted.begin() + bucket_start[k], last = sorted.begin() + bucket_start[k + 1];
        if (last - first <= 1) continue;
        if (last - first <= 16) { // typical valence: insertion sort beats std::sort setup
            for (auto it = first + 1; it < last; ++it)
                for (auto j = it; j > first && *(j - 1) > *j; --j) std::iter_swap(j - 1, j);
        } else {
            std::sort(first, last);
        }
    }
    // Pair within runs of equal (lower, upper): each unpaired edge takes the first later
    // unpaired edge that runs the opposite way.
    for (std::size_t i = 0; i < edges; ++i) {
        const std::uint32_t a = static_cast<std::uint32_t>(sorted[i]);
        if (neighbour[a] != -1) continue;
        const std::uint64_t upper = sorted[i] >> 32;
        const std::uint32_t a_from = edge_from(a);
        const std::uint32_t a_low = std::min(a_from, edge_to(a));
        for (std::size_t j = i + 1; j < edges && (sorted[j] >> 32) == upper; ++j) {
            const std::uint32_t b = static_cast<std::uint32_t>(sorted[j]);
            if (std::min(edge_from(b), edge_to(b)) != a_low) break;
            if (edge_to(b) == a_from && neighbour[b] == -1) {
                neighbour[a] = static_cast<std::int32_t>(b / 3);
                neighbour[b] = static_cast<std::int32_t>(a / 3);
                break;
            }
        }
    }
}

} // namespace sherpa::tangent_detail
