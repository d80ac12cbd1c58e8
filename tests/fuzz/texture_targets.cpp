// Texture targets: mutated KTX2 files through read_ktx2, and mutated cache entries
// (also a directory, a FIFO or a device where an entry belongs) through
// TextureCache::load, which must never serve a changed entry as a hit.
#include "texture_targets.h"

#include <sys/stat.h>

#include <sherpa/core/file_io.h>

namespace sherpa::fuzz {

namespace fs = std::filesystem;
using namespace sherpa::tex;

namespace {

// Small textures of every format Sherpa writes, with mip chains and metadata.
std::vector<Ktx2Texture> seed_textures() {
    struct Spec {
        VkFormat format;
        std::uint32_t w, h, levels;
    };
    const Spec specs[] = {{VkFormat::Bc7SrgbBlock, 8, 8, 4},
                          {VkFormat::Bc7UnormBlock, 5, 3, 1},
                          {VkFormat::Bc5UnormBlock, 16, 4, 5},
                          {VkFormat::R8G8B8A8Srgb, 3, 5, 3},
                          {VkFormat::R8G8B8A8Unorm, 1, 1, 1}};
    std::vector<Ktx2Texture> out;
    for (const Spec& s : specs) {
        Ktx2Texture t;
        t.format = s.format, t.width = s.w, t.height = s.h;
        for (std::uint32_t l = 0; l < s.levels; ++l) {
            std::vector<std::uint8_t> level(
                level_size(s.format, mip_extent(s.w, l), mip_extent(s.h, l)));
            for (std::size_t i = 0; i < level.size(); ++i) level[i] = std::uint8_t(i * 37 + l);
            t.levels.push_back(std::move(level));
        }
        t.metadata = {{std::string(kKeyPsnr), "41.250000"}};
        out.push_back(std::move(t));
    }
    return out;
}

// What differs between two textures, or "" when they are the same.
std::string difference(const Ktx2Texture& a, const Ktx2Texture& b) {
    if (a.format != b.format || a.width != b.width || a.height != b.height) return "header";
    if (a.levels != b.levels) return "level data";
    if (a.metadata != b.metadata) return "metadata";
    return "";
}

} // namespace

bool Ktx2Target::init(const TargetConfig& config, std::string& error) {
    config_ = config;
    for (const Ktx2Texture& t : seed_textures()) seeds_.push_back(write_ktx2(t));
    fs::create_directories(config.work_dir);
    (void)error;
    return true;
}

std::optional<std::string> Ktx2Target::run() {
    Ktx2Texture texture;
    std::string error;
    if (!read_ktx2(bytes_, texture, error)) {
        if (error.empty()) return "read_ktx2 refused the file without saying why";
        return std::nullopt;
    }
    // Accepted: every level must have the size its format and extent need.
    for (std::uint32_t l = 0; l < texture.levels.size(); ++l)
        if (texture.levels[l].size() !=
            level_size(texture.format, mip_extent(texture.width, l), mip_extent(texture.height, l)))
            return "read_ktx2 accepted level " + std::to_string(l) + " of the wrong size";
    if (texture.levels.empty()) return "read_ktx2 accepted a texture without levels";
    return std::nullopt;
}

bool CacheTarget::init(const TargetConfig& config, std::string& error) {
    config_ = config;
    fs::remove_all(config.work_dir);
    cache_.emplace(config.work_dir / "cache", kDefaultCacheCapBytes);
    const std::string recipe = "fuzz-recipe";
    for (const Ktx2Texture& t : seed_textures()) {
        Entry e;
        e.source = hash_bytes(write_ktx2(t));
        e.key = cache_key(e.source, recipe);
        e.recipe = recipe;
        if (!cache_->store(e.key, e.source, recipe, t, error)) return false;
        const CacheLookup stored = cache_->load(e.key, e.source, recipe);
        if (stored.state != LookupState::Hit) {
            error = "cache seed does not load back: " + stored.problem;
            return false;
        }
        e.texture = stored.texture;
        std::string read_error;
        if (!core::read_file(cache_->file_for(e.key), e.bytes, read_error)) {
            error = read_error;
            return false;
        }
        entries_.push_back(std::move(e));
    }
    return true;
}

fs::path CacheTarget::make_case(Rng& rng) {
    current_ = rng.below(entries_.size());
    const Entry& e = entries_[current_];
    const fs::path path = cache_->file_for(e.key);
    std::error_code ec;
    fs::remove_all(path, ec);
    // Now and then no file at all where the entry belongs: each must be refused
    // with a message, not read forever or served.
    switch (rng.below(64)) {
    case 0:
        fs::create_directory(path, ec);
        return cache_->directory();
    case 1:
        ::mkfifo(path.c_str(), 0600);
        return cache_->directory();
    case 2:
        fs::create_symlink("/dev/zero", path, ec);
        return cache_->directory();
    default:
        break;
    }
    std::vector<std::uint8_t> bytes = e.bytes;
    mutate_bytes(rng, bytes, entries_[rng.below(entries_.size())].bytes, config_.max_size);
    write_case_file(path, bytes);
    return cache_->directory();
}

std::optional<std::string> CacheTarget::run() {
    const Entry& e = entries_[current_];
    const CacheLookup found = cache_->load(e.key, e.source, e.recipe);
    if (found.state == LookupState::Hit) {
        const std::string diff = difference(found.texture, e.texture);
        if (!diff.empty())
            return "a changed cache entry was served as a hit (" + diff + " differs)";
    } else if (found.state != LookupState::Missing && found.problem.empty()) {
        return "a refused cache entry has no message";
    }
    return std::nullopt;
}

std::vector<fs::path> CacheTarget::case_files() const {
    return {cache_->file_for(entries_[current_].key)};
}

} // namespace sherpa::fuzz
