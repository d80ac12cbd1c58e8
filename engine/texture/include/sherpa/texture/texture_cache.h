#pragma once
// On-disk cache of compressed textures: one KTX2 file per (source bytes, recipe),
// named by a 128-bit key. Files carry their source hash, recipe and a checksum of
// header, levels and metadata in KTX2 key/value entries, so a damaged or mismatched
// file is recognised. Writes are atomic (temp file, fsync, rename), which makes
// concurrent writers of the same key safe: each renames a complete file and the last
// wins; a per-entry lock file lets a second writer wait for the first instead.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include <sherpa/texture/ktx2.h>

namespace sherpa::tex {

struct Hash128 {
    std::uint64_t high = 0, low = 0;
    std::string hex() const; // 32 lowercase hex digits
    bool operator==(const Hash128&) const = default;
};

// XXH3-128 of the bytes.
Hash128 hash_bytes(std::span<const std::uint8_t> bytes);
// Bumped when the file layout or what the checksum covers changes. Part of every
// key, so files of older formats are never read (LRU eviction removes them).
// 2: the checksum covers header and metadata too (a flipped PSNR digit was a hit).
inline constexpr int kCacheFormatVersion = 2;
// The cache key: XXH3-128 over the cache format, the source hash and the recipe
// text, which names everything that changes the output (format, encoder version,
// quality, mips...).
Hash128 cache_key(const Hash128& source, std::string_view recipe);
// XXH3-64 as 16 hex digits (the KTX2 "sherpa.checksum") over format, size, every
// level and every metadata entry except the checksum itself (in key order, as the
// KTX2 writer stores them), each length-prefixed so no two entries hash alike.
std::string entry_checksum(const Ktx2Texture& texture);

// Metadata keys Sherpa writes into its KTX2 files.
inline constexpr std::string_view kKeySourceHash = "sherpa.source-hash";
inline constexpr std::string_view kKeyRecipe = "sherpa.recipe";
inline constexpr std::string_view kKeyChecksum = "sherpa.checksum";
inline constexpr std::string_view kKeyPsnr = "sherpa.psnr";
// An emissive image's luminance grid (encode_luminance_grid(): binary, not text).
inline constexpr std::string_view kKeyLuminance = "sherpa.emissive-luminance";

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

// An exclusive lock on one cache entry (flock on "<key>.ktx2.lock"), held while the
// entry is being made, so a second process making the same entry waits and reuses
// it. Released when destroyed, or by the kernel when its holder dies.
class EntryLock {
public:
    EntryLock() = default;
    explicit EntryLock(int fd) : fd_(fd) {}
    EntryLock(EntryLock&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
    EntryLock& operator=(EntryLock&& other) noexcept;
    EntryLock(const EntryLock&) = delete;
    EntryLock& operator=(const EntryLock&) = delete;
    ~EntryLock();
    bool held() const { return fd_ >= 0; }

private:
    int fd_ = -1;
};

class TextureCache {
public:
    // `max_bytes`: total size of *.ktx2 files kept; older files (by last use)
    // are evicted after each store.
    TextureCache(std::filesystem::path directory, std::uint64_t max_bytes = kDefaultCacheCapBytes);

    const std::filesystem::path& directory() const { return directory_; }
    // Creates the directory if need be; "" when it is a usable directory, else what
    // is wrong, naming it ("PATH: is a regular file, not a directory").
    std::string directory_problem() const;
    std::filesystem::path file_for(const Hash128& key) const;

    // Loads and verifies the file for `key`. A hit refreshes the file's
    // modification time, which is what the LRU eviction orders by.
    CacheLookup load(const Hash128& key, const Hash128& source, std::string_view recipe) const;

    // Adds source hash, recipe and checksum metadata to `texture` and writes it
    // atomically, then evicts least recently used files beyond the cap (never the
    // file just written). Returns false with `error` if the write failed.
    bool store(const Hash128& key, const Hash128& source, std::string_view recipe,
               Ktx2Texture texture, std::string& error) const;

    // Takes the entry's lock, waiting up to `timeout` while another process (or
    // thread) holds it. Not held on timeout or when the lock file cannot be made:
    // the caller then makes the entry itself (duplicate work, never a torn file).
    EntryLock lock_entry(const Hash128& key, std::chrono::milliseconds timeout) const;

    // Removes temp files abandoned by dead writers (see write_file_atomic: the name
    // holds the writer's PID; a minute old and that process gone, or an hour old) and
    // entry lock files nobody holds that are a minute old, then least recently used files until
    // cache files plus live temp files are within the cap. Returns the number of cache files
    // removed.
    std::size_t evict(const std::filesystem::path& keep = {}) const;

private:
    std::filesystem::path directory_;
    std::uint64_t max_bytes_;
};

} // namespace sherpa::tex
