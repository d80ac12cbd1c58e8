#pragma once
// Seeded mutations for the in-tree fuzzer: byte-level (bit flips, byte sets,
// insert/delete, splice, interesting integers) and JSON-level (values replaced by
// extreme numbers, wrong types and hostile URIs; keys deleted; arrays duplicated;
// deep nesting). Everything is a pure function of the Rng's state, so a case is
// reproduced from (seed, target, case index) alone.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sherpa::fuzz {

// splitmix64: tiny, fast, and the same sequence on every compiler and library
// (std::uniform_int_distribution is not), so a seed replays identically in CI.
class Rng {
public:
    explicit Rng(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    // Uniform in [0, n); n > 0.
    std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }
    bool chance(unsigned one_in) { return below(one_in) == 0; }

private:
    std::uint64_t state_;
};

// The generator of one case: seed, target and case index mixed, so cases are
// independent of how many ran before them (a restarted worker continues exactly).
Rng case_rng(std::uint64_t seed, std::uint64_t target_id, std::uint64_t case_index);

// 1..`max_ops` byte-level mutations in place. `other` (may be empty) is spliced from.
// The result never exceeds `max_size` bytes.
void mutate_bytes(Rng& rng, std::vector<std::uint8_t>& data, std::span<const std::uint8_t> other,
                  std::size_t max_size, int max_ops = 4);

// 1..`max_ops` JSON-level mutations of `doc` in place.
void mutate_json(Rng& rng, nlohmann::json& doc, int max_ops = 3);
// The document as text, with the deep-nesting placeholders mutate_json leaves
// expanded (nesting deep enough to overflow a recursive parser cannot be built as a
// json value: dumping or destroying it would recurse as deep).
std::string dump_json(const nlohmann::json& doc);

} // namespace sherpa::fuzz
