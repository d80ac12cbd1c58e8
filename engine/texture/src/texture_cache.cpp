#include <sherpa/texture/texture_cache.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <system_error>
#include <vector>

#include <xxhash.h>

#include <sherpa/core/file_io.h>

#include "cache_files.h"

namespace sherpa::tex {

namespace fs = std::filesystem;

std::string Hash128::hex() const {
    char buf[33];
    std::snprintf(buf, sizeof buf, "%016llx%016llx", static_cast<unsigned long long>(high),
                  static_cast<unsigned long long>(low));
    return buf;
}

Hash128 hash_bytes(std::span<const std::uint8_t> bytes) {
    const XXH128_hash_t h = XXH3_128bits(bytes.data(), bytes.size());
    return {h.high64, h.low64};
}

Hash128 cache_key(const Hash128& source, std::string_view recipe) {
    std::vector<std::uint8_t> buf(20 + recipe.size());
    for (int i = 0; i < 8; ++i) {
        buf[i] = static_cast<std::uint8_t>(source.high >> (8 * i));
        buf[8 + i] = static_cast<std::uint8_t>(source.low >> (8 * i));
    }
    for (int i = 0; i < 4; ++i)
        buf[16 + i] = static_cast<std::uint8_t>(kCacheFormatVersion >> (8 * i));
    std::copy(recipe.begin(), recipe.end(), buf.begin() + 20);
    return hash_bytes(buf);
}

namespace {

void hash_u64(XXH3_state_t* state, std::uint64_t v) {
    std::uint8_t bytes[8];
    for (int i = 0; i < 8; ++i) bytes[i] = static_cast<std::uint8_t>(v >> (8 * i));
    XXH3_64bits_update(state, bytes, sizeof bytes);
}

void hash_sized(XXH3_state_t* state, const void* data, std::size_t size) {
    hash_u64(state, size);
    XXH3_64bits_update(state, data, size);
}

} // namespace

std::string entry_checksum(const Ktx2Texture& texture) {
    std::vector<std::pair<std::string, std::string>> metadata;
    for (const auto& kv : texture.metadata)
        if (kv.first != kKeyChecksum) metadata.push_back(kv);
    std::sort(metadata.begin(), metadata.end()); // the order the KTX2 writer stores
    XXH3_state_t* state = XXH3_createState();
    XXH3_64bits_reset(state);
    hash_u64(state, static_cast<std::uint64_t>(texture.format));
    hash_u64(state, texture.width);
    hash_u64(state, texture.height);
    hash_u64(state, texture.levels.size());
    for (const auto& level : texture.levels) hash_sized(state, level.data(), level.size());
    for (const auto& [key, value] : metadata) {
        hash_sized(state, key.data(), key.size());
        hash_sized(state, value.data(), value.size());
    }
    const XXH64_hash_t h = XXH3_64bits_digest(state);
    XXH3_freeState(state);
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

fs::path default_cache_dir(std::optional<std::string> xdg_cache_home,
                           std::optional<std::string> home) {
    // XDG: the variable must hold an absolute path to count.
    if (xdg_cache_home && !xdg_cache_home->empty() && fs::path(*xdg_cache_home).is_absolute())
        return fs::path(*xdg_cache_home) / "sherpa" / "textures";
    if (home && !home->empty()) return fs::path(*home) / ".cache" / "sherpa" / "textures";
    return fs::temp_directory_path() / "sherpa-cache" / "textures";
}

fs::path default_cache_dir_from_environment() {
    auto env = [](const char* name) -> std::optional<std::string> {
        const char* v = std::getenv(name);
        return v ? std::optional<std::string>(v) : std::nullopt;
    };
    return default_cache_dir(env("XDG_CACHE_HOME"), env("HOME"));
}

TextureCache::TextureCache(fs::path directory, std::uint64_t max_bytes)
    : directory_(std::move(directory)), max_bytes_(max_bytes) {}

std::string TextureCache::directory_problem() const {
    std::error_code ec;
    const fs::file_status status = fs::status(directory_, ec);
    if (fs::is_directory(status)) return {};
    if (fs::exists(status)) {
        const char* what = fs::is_regular_file(status) ? "a regular file"
                           : fs::is_fifo(status)       ? "a FIFO"
                           : fs::is_socket(status)     ? "a socket"
                                                       : "a device or other special file";
        return directory_.string() + ": is " + what + ", not a directory";
    }
    fs::create_directories(directory_, ec);
    if (ec) return directory_.string() + ": cannot create the directory: " + ec.message();
    return {};
}

fs::path TextureCache::file_for(const Hash128& key) const {
    return directory_ / (key.hex() + ".ktx2");
}

CacheLookup TextureCache::load(const Hash128& key, const Hash128& source,
                               std::string_view recipe) const {
    CacheLookup result;
    const fs::path path = file_for(key);
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(path, ec))) return result;
    std::vector<std::uint8_t> bytes;
    std::string error;
    // read_file refuses directories, FIFOs and devices (with their path) unread.
    if (!core::read_file(path, bytes, error)) {
        // Vanished between the check and the read (another process evicted it).
        result.state =
            fs::exists(fs::symlink_status(path, ec)) ? LookupState::Corrupt : LookupState::Missing;
        result.problem = error;
        return result;
    }
    result.file_bytes = bytes.size();
    Ktx2Texture texture;
    if (!read_ktx2(bytes, texture, error)) {
        result.state = LookupState::Corrupt;
        result.problem = path.filename().string() + ": " + error;
        return result;
    }
    const std::string* checksum = texture.find(kKeyChecksum);
    if (!checksum || *checksum != entry_checksum(texture)) {
        result.state = LookupState::Corrupt;
        result.problem = path.filename().string() + ": checksum mismatch (damaged file)";
        return result;
    }
    const std::string* stored_source = texture.find(kKeySourceHash);
    const std::string* stored_recipe = texture.find(kKeyRecipe);
    if (!stored_source || *stored_source != source.hex() || !stored_recipe ||
        *stored_recipe != recipe) {
        result.state = LookupState::Stale;
        result.problem = path.filename().string() + ": written for another source or recipe";
        return result;
    }
    fs::last_write_time(path, fs::file_time_type::clock::now(), ec); // LRU: mark as used
    result.state = LookupState::Hit;
    result.texture = std::move(texture);
    return result;
}

bool TextureCache::store(const Hash128& key, const Hash128& source, std::string_view recipe,
                         Ktx2Texture texture, std::string& error) const {
    std::error_code ec;
    fs::create_directories(directory_, ec);
    if (ec) {
        error = directory_.string() + ": cannot create cache directory: " + ec.message();
        return false;
    }
    std::erase_if(texture.metadata, [](const auto& kv) {
        return kv.first == kKeySourceHash || kv.first == kKeyRecipe || kv.first == kKeyChecksum;
    });
    texture.metadata.emplace_back(std::string(kKeySourceHash), source.hex());
    texture.metadata.emplace_back(std::string(kKeyRecipe), std::string(recipe));
    // Named here rather than by the writer, so the checksum covers it too.
    if (!texture.find(kKeyKtxWriter))
        texture.metadata.emplace_back(std::string(kKeyKtxWriter), std::string(kKtxWriterName));
    texture.metadata.emplace_back(std::string(kKeyChecksum), entry_checksum(texture));
    const fs::path path = file_for(key);
    if (!core::write_file_atomic(path, write_ktx2(texture), error)) return false;
    evict(path);
    return true;
}

std::size_t TextureCache::evict(const fs::path& keep) const {
    struct Entry {
        fs::path path;
        std::uint64_t bytes;
        fs::file_time_type used;
    };
    std::vector<Entry> entries;
    std::uint64_t total = 0;
    std::error_code ec;
    const auto now = fs::file_time_type::clock::now();
    for (fs::directory_iterator it(directory_, ec), end; !ec && it != end; it.increment(ec)) {
        std::error_code entry_ec;
        const fs::path& p = it->path();
        if (!it->is_regular_file(entry_ec)) continue; // not ours to count or remove
        const auto bytes = it->file_size(entry_ec);
        const auto used = it->last_write_time(entry_ec);
        if (entry_ec) continue; // removed meanwhile by another process
        if (p.filename().string().find(".ktx2.tmp.") != std::string::npos) {
            if (abandoned_temp_file(p.filename().string(), now - used)) {
                fs::remove(p, entry_ec);
                continue;
            }
            total += bytes; // a live writer's file takes its room under the cap too
            continue;
        }
        if (p.extension() == ".lock") {
            // Empty lock files outlive their entries' making; one a minute old that
            // nobody holds is stale (a waiter takes a fresh lock just as well).
            if (now - used > std::chrono::minutes(1)) remove_lock_if_unused(p);
            continue;
        }
        if (p.extension() != ".ktx2") continue;
        entries.push_back({p, bytes, used});
        total += bytes;
    }
    std::sort(entries.begin(), entries.end(),
              [](const Entry& a, const Entry& b) { return a.used < b.used; });
    std::size_t removed = 0;
    for (const Entry& e : entries) {
        if (total <= max_bytes_) break;
        if (e.path == keep) continue;
        if (fs::remove(e.path, ec)) ++removed;
        remove_unused_lock(e.path);
        total -= e.bytes;
    }
    return removed;
}

} // namespace sherpa::tex
