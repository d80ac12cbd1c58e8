#include <sherpa/texture/texture_cache.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <system_error>
#include <vector>

#include <xxhash.h>

#include <sherpa/core/file_io.h>

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
    std::vector<std::uint8_t> buf(16 + recipe.size());
    for (int i = 0; i < 8; ++i) {
        buf[i] = static_cast<std::uint8_t>(source.high >> (8 * i));
        buf[8 + i] = static_cast<std::uint8_t>(source.low >> (8 * i));
    }
    std::copy(recipe.begin(), recipe.end(), buf.begin() + 16);
    return hash_bytes(buf);
}

std::string level_checksum(const Ktx2Texture& texture) {
    XXH3_state_t* state = XXH3_createState();
    XXH3_64bits_reset(state);
    for (const auto& level : texture.levels) XXH3_64bits_update(state, level.data(), level.size());
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

fs::path TextureCache::file_for(const Hash128& key) const {
    return directory_ / (key.hex() + ".ktx2");
}

CacheLookup TextureCache::load(const Hash128& key, const Hash128& source,
                               std::string_view recipe) const {
    CacheLookup result;
    const fs::path path = file_for(key);
    std::error_code ec;
    if (!fs::exists(path, ec)) return result;
    std::vector<std::uint8_t> bytes;
    std::string error;
    if (!read_file(path, bytes, error)) {
        // Vanished between the check and the read (another process evicted it).
        result.state = fs::exists(path, ec) ? LookupState::Corrupt : LookupState::Missing;
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
    if (!checksum || *checksum != level_checksum(texture)) {
        result.state = LookupState::Corrupt;
        result.problem = path.filename().string() + ": level data checksum mismatch";
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
    texture.metadata.emplace_back(std::string(kKeyChecksum), level_checksum(texture));
    const fs::path path = file_for(key);
    if (!write_file_atomic(path, write_ktx2(texture), error)) return false;
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
        const fs::path& p = it->path();
        const auto bytes = it->file_size(ec);
        const auto used = it->last_write_time(ec);
        if (ec) continue; // removed meanwhile by another process
        if (p.filename().string().find(".ktx2.tmp.") != std::string::npos) {
            if (now - used > std::chrono::hours(1)) fs::remove(p, ec);
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
        total -= e.bytes;
    }
    return removed;
}

} // namespace sherpa::tex
