#pragma once
// On-disk cache of compressed textures: one KTX2 file per (source bytes, recipe),
// named by a 128-bit key. Files carry their source hash, recipe and a checksum of
// the level data in KTX2 key/value entries, so a damaged or mismatched file is
// recognised. Writes are atomic (temp file, fsync, rename), which makes concurrent
// writers of the same key safe: each renames a complete file and the last wins.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <sherpa/texture/ktx2.h>

namespace sherpa::tex {

struct Hash128 {
    std::uint64_t high = 0, low = 0;
    std::string hex() const; // 32 lowercase hex digits
    bool operator==(const Hash128&) const = default;
};

// XXH3-128 of the bytes.
Hash128 hash_bytes(std::span<const std::uint8_t> bytes);
// The cache key: XXH3-128 over the source hash and the recipe text, which names
// everything that changes the output (format, encoder version, quality, mips...).
Hash128 cache_key(const Hash128& source, std::string_view recipe);
// XXH3-64 of all levels in order, as 16 hex digits (the KTX2 "sherpa.checksum").
std::string level_checksum(const Ktx2Texture& texture);

// Metadata keys Sherpa writes into its KTX2 files.
inline constexpr std::string_view kKeySourceHash = "sherpa.source-hash";
inline constexpr std::string_view kKeyRecipe = "sherpa.recipe";
inline constexpr std::string_view kKeyChecksum = "sherpa.checksum";
inline constexpr std::string_view kKeyPsnr = "sherpa.psnr";

// $XDG_CACHE_HOME/sherpa/textures, else $HOME/.cache/sherpa/textures, else a
// directory under the system temp directory. Takes the variables as arguments
// (nullopt or empty = unset) so callers decide where they come from.
std::filesystem::path default_cache_dir(std::optional<std::string> xdg_cache_home,
                                        std::optional<std::string> home);
// The same, reading the two variables from the environment.
std::filesystem::path default_cache_dir_from_environment();

inline constexpr std::uint64_t kDefaultCacheCapBytes = 2ull << 30; // 2 GiB

enum class LookupState : std::uint8_t {
    Missing, // no file for this key
    Hit,     // valid file for this source and recipe
    Stale,   // valid file, but written for another source or recipe
    Corrupt, // unreadable, truncated, malformed or failing its checksum
};

struct CacheLookup {
    LookupState state = LookupState::Missing;
    Ktx2Texture texture; // filled on Hit
    std::string problem; // why Stale or Corrupt
    std::uint64_t file_bytes = 0;
};

class TextureCache {
public:
    // `max_bytes`: total size of *.ktx2 files kept; older files (by last use)
    // are evicted after each store.
    TextureCache(std::filesystem::path directory, std::uint64_t max_bytes = kDefaultCacheCapBytes);

    const std::filesystem::path& directory() const { return directory_; }
    std::filesystem::path file_for(const Hash128& key) const;

    // Loads and verifies the file for `key`. A hit refreshes the file's
    // modification time, which is what the LRU eviction orders by.
    CacheLookup load(const Hash128& key, const Hash128& source, std::string_view recipe) const;

    // Adds source hash, recipe and checksum metadata to `texture` and writes it
    // atomically, then evicts least recently used files beyond the cap (never the
    // file just written). Returns false with `error` if the write failed.
    bool store(const Hash128& key, const Hash128& source, std::string_view recipe,
               Ktx2Texture texture, std::string& error) const;

    // Removes least recently used files until the total is within the cap, and
    // temp files abandoned by crashed writers (older than an hour).
    // Returns the number of cache files removed.
    std::size_t evict(const std::filesystem::path& keep = {}) const;

private:
    std::filesystem::path directory_;
    std::uint64_t max_bytes_;
};

} // namespace sherpa::tex
