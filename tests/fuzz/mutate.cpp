#include "mutate.h"

#include <array>
#include <cstring>
#include <limits>
#include <string>

namespace sherpa::fuzz {

namespace {

// Integers that sit on the edges of signed/unsigned 8..64-bit arithmetic.
constexpr std::array<std::uint64_t, 16> kInterestingIntegers{
    0,          1,          0x7f,       0x80,         0xff,       0x7fff,
    0x8000,     0xffff,     0x7fffffff, 0x80000000,   0xffffffff, 0x100000000ull,
    1ull << 62, 1ull << 63, ~0ull,      0xfffffffeull};

// Numbers a glTF reader must reject or survive; as JSON numbers of each kind.
nlohmann::json interesting_number(Rng& rng) {
    switch (rng.below(18)) {
    case 0:
        return 0;
    case 1:
        return -1;
    case 2:
        return 1;
    case 3:
        return 2147483647;
    case 4:
        return 2147483648ll;
    case 5:
        return -2147483648ll;
    case 6:
        return 4294967295ll;
    case 7:
        return 4294967296ll;
    case 8:
        return 9223372036854775807ll;
    case 9:
        return std::numeric_limits<std::uint64_t>::max();
    case 10:
        return 9223372036854775808ull;
    case 11:
        return 1e308;
    case 12:
        return -1e308;
    case 13:
        return 1e-320; // subnormal
    case 14:
        return 0.5;
    case 15:
        return -0.0;
    case 16:
        return 3.4e38;
    default:
        return static_cast<std::int64_t>(rng.next() % 100000) - 1000;
    }
}

// URIs that name directories, escape the folder, or hide NULs and bad escapes.
nlohmann::json interesting_string(Rng& rng) {
    static const std::array<const char*, 16> kStrings{".",
                                                      "..",
                                                      "/",
                                                      "%2e%2e/",
                                                      "%00",
                                                      "a%00.bin",
                                                      "%",
                                                      "%zz",
                                                      "../../../../etc/passwd",
                                                      "data:application/octet-stream;base64,",
                                                      "data:application/octet-stream;base64,!!!!",
                                                      "data:image/png;base64,iVBORw0KGgo=",
                                                      "",
                                                      "file:///dev/zero",
                                                      "/dev/zero",
                                                      "\xff\xfe"};
    if (rng.chance(16)) return std::string(1 + rng.below(70000), 'A');
    return kStrings[rng.below(kStrings.size())];
}

constexpr std::string_view kNestMarker = "\u0001nest:";

// Values nested deeper than this are not picked for mutation: a pointer holds one
// string per level, so collecting every value of a document that earlier operations
// nested thousands deep took O(depth^2) memory (12 GB, minutes: the "hang" CI found at
// gltf case 424). Deep nesting is still made, by the nesting operation itself.
constexpr std::size_t kMaxPointerDepth = 64;

// Every value of the document down to kMaxPointerDepth, as JSON pointers, so one can
// be picked uniformly.
void collect_pointers(const nlohmann::json& j, const nlohmann::json::json_pointer& at,
                      std::size_t depth, std::vector<nlohmann::json::json_pointer>& out,
                      std::size_t limit) {
    if (out.size() >= limit) return;
    out.push_back(at);
    if (depth >= kMaxPointerDepth) return;
    if (j.is_object())
        for (auto it = j.begin(); it != j.end(); ++it)
            collect_pointers(*it, at / it.key(), depth + 1, out, limit);
    else if (j.is_array())
        for (std::size_t i = 0; i < j.size(); ++i)
            collect_pointers(j[i], at / i, depth + 1, out, limit);
}

nlohmann::json nested(std::size_t depth, bool arrays) {
    nlohmann::json v = 0;
    for (std::size_t i = 0; i < depth; ++i)
        v = arrays ? nlohmann::json::array({std::move(v)}) : nlohmann::json{{"a", std::move(v)}};
    return v;
}

void mutate_value(Rng& rng, nlohmann::json& doc, const nlohmann::json::json_pointer& at,
                  const std::vector<nlohmann::json::json_pointer>& all) {
    nlohmann::json& v = doc[at];
    switch (rng.below(10)) {
    case 0: // a number of the wrong size or sign
    case 1:
        v = interesting_number(rng);
        return;
    case 2: // a hostile string
        v = interesting_string(rng);
        return;
    case 3: { // the wrong type
        static const std::array<nlohmann::json, 5> kTypes{
            nullptr, true, "x", nlohmann::json::array(), nlohmann::json::object()};
        v = kTypes[rng.below(kTypes.size())];
        return;
    }
    case 4: // delete this key or element
        if (!at.empty()) {
            nlohmann::json& parent = doc[at.parent_pointer()];
            if (parent.is_object())
                parent.erase(at.back());
            else if (parent.is_array() && !parent.empty())
                parent.erase(parent.begin() + long(rng.below(parent.size())));
        }
        return;
    case 5: // duplicate array contents (instances, primitives, nodes multiplied)
        if (v.is_array() && !v.empty() && v.size() < 4096) {
            const nlohmann::json copy = v;
            for (const auto& e : copy) v.push_back(e);
        }
        return;
    case 6: // another value of the document here (indices and objects out of place)
        v = doc[all[rng.below(all.size())]];
        return;
    case 7:                // deep nesting, now and then deeper than a recursive parser's stack
        if (rng.chance(8)) // as a placeholder: our own dump() would recurse that deep too
            v = std::string(kNestMarker) + std::to_string(20000 + rng.below(20000)) +
                (rng.chance(2) ? "[" : "{");
        else
            v = nested(1 + rng.below(200), rng.chance(2));
        return;
    case 8:                        // a nearby integer
        if (v.is_number_integer()) // wrapping (unsigned) arithmetic: INT64_MAX + 1 is wanted
            v = std::int64_t(std::uint64_t(v.get<std::int64_t>()) + rng.below(9) - 4);
        else if (v.is_number_float())
            v = v.get<double>() * -1e30;
        return;
    default: // an extra unknown key
        if (v.is_object()) v["fuzz" + std::to_string(rng.below(4))] = interesting_number(rng);
        return;
    }
}

} // namespace

Rng case_rng(std::uint64_t seed, std::uint64_t target_id, std::uint64_t case_index) {
    Rng mix(seed ^ (target_id * 0x9e3779b97f4a7c15ull));
    mix.next();
    return Rng(mix.next() ^ (case_index * 0xd1342543de82ef95ull));
}

void mutate_bytes(Rng& rng, std::vector<std::uint8_t>& data, std::span<const std::uint8_t> other,
                  std::size_t max_size, int max_ops) {
    const int ops = 1 + int(rng.below(std::size_t(max_ops)));
    for (int op = 0; op < ops; ++op) {
        const std::size_t n = data.size();
        switch (rng.below(7)) {
        case 0: // bit flip
            if (n) data[rng.below(n)] ^= std::uint8_t(1u << rng.below(8));
            break;
        case 1: // byte set
            if (n) data[rng.below(n)] = std::uint8_t(rng.next());
            break;
        case 2: { // interesting integer, little-endian, 1/2/4/8 bytes wide
            const std::size_t width = std::size_t(1) << rng.below(4);
            if (n < width) break;
            std::uint64_t v = kInterestingIntegers[rng.below(kInterestingIntegers.size())];
            if (rng.chance(4)) v = ~v + 1; // negated
            const std::size_t at = rng.below(n - width + 1);
            for (std::size_t i = 0; i < width; ++i) data[at + i] = std::uint8_t(v >> (8 * i));
            break;
        }
        case 3: { // insert random bytes
            const std::size_t count = 1 + rng.below(rng.chance(8) ? 4096 : 16);
            if (n + count > max_size) break;
            std::vector<std::uint8_t> bytes(count);
            for (auto& b : bytes) b = std::uint8_t(rng.next());
            data.insert(data.begin() + long(rng.below(n + 1)), bytes.begin(), bytes.end());
            break;
        }
        case 4: { // delete a range (truncation included)
            if (!n) break;
            const std::size_t at = rng.below(n);
            const std::size_t count =
                rng.chance(8) ? n - at : 1 + rng.below(std::min<std::size_t>(n - at, 64));
            data.erase(data.begin() + long(at), data.begin() + long(at + count));
            break;
        }
        case 5: { // splice: a range of `other` (or of itself) over or into the data
            const std::span<const std::uint8_t> src =
                other.empty() ? std::span<const std::uint8_t>(data) : other;
            if (src.empty() || !n) break;
            const std::size_t from = rng.below(src.size());
            const std::size_t count = 1 + rng.below(std::min<std::size_t>(src.size() - from, 256));
            const std::vector<std::uint8_t> piece(src.begin() + long(from),
                                                  src.begin() + long(from + count));
            const std::size_t at = rng.below(n);
            if (rng.chance(2) && n + count <= max_size)
                data.insert(data.begin() + long(at), piece.begin(), piece.end());
            else
                for (std::size_t i = 0; i < count && at + i < n; ++i) data[at + i] = piece[i];
            break;
        }
        default: { // duplicate a range in place (repeated structures)
            if (!n) break;
            const std::size_t at = rng.below(n);
            const std::size_t count = 1 + rng.below(std::min<std::size_t>(n - at, 128));
            if (n + count > max_size) break;
            const std::vector<std::uint8_t> piece(data.begin() + long(at),
                                                  data.begin() + long(at + count));
            data.insert(data.begin() + long(at), piece.begin(), piece.end());
            break;
        }
        }
    }
}

std::string dump_json(const nlohmann::json& doc) {
    std::string text = doc.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    // The marker as dump() writes it: opening quote and escaped text, no closing quote.
    std::string quoted = nlohmann::json(std::string(kNestMarker)).dump();
    quoted.pop_back();
    for (std::size_t at = text.find(quoted); at != std::string::npos; at = text.find(quoted, at)) {
        const std::size_t end = text.find('"', at + quoted.size());
        if (end == std::string::npos) break;
        const std::string spec = text.substr(at + quoted.size(), end - at - quoted.size());
        const std::size_t depth = std::strtoull(spec.c_str(), nullptr, 10);
        const bool arrays = !spec.empty() && spec.back() == '[';
        std::string nest;
        for (std::size_t i = 0; i < depth; ++i) nest += arrays ? "[" : "{\"a\":";
        nest += "0";
        nest.append(depth, arrays ? ']' : '}');
        text.replace(at, end + 1 - at, nest);
        at += nest.size();
    }
    return text;
}

void mutate_json(Rng& rng, nlohmann::json& doc, int max_ops) {
    const int ops = 1 + int(rng.below(std::size_t(max_ops)));
    for (int op = 0; op < ops; ++op) {
        std::vector<nlohmann::json::json_pointer> all;
        collect_pointers(doc, nlohmann::json::json_pointer(), 0, all, 20000);
        // Uniform over every value: leaves dominate, which is where the numbers are.
        const auto& at = all[rng.below(all.size())];
        mutate_value(rng, doc, at, all);
    }
}

} // namespace sherpa::fuzz
