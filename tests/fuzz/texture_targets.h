#pragma once
// KTX2 reader and texture cache targets (see texture_targets.cpp).
#include <optional>

#include <sherpa/texture/texture_cache.h>

#include "targets.h"

namespace sherpa::fuzz {

class Ktx2Target : public ByteTarget { // seeds: KTX2 files from our writer
public:
    Ktx2Target() : ByteTarget("__case.ktx2") {}
    std::string name() const override { return "ktx2"; }
    bool init(const TargetConfig& config, std::string& error) override;
    std::optional<std::string> run() override;
};

class CacheTarget : public Target {
public:
    std::string name() const override { return "cache"; }
    bool init(const TargetConfig& config, std::string& error) override;
    std::filesystem::path make_case(Rng& rng) override;
    std::optional<std::string> run() override;
    std::vector<std::filesystem::path> case_files() const override;

private:
    struct Entry {
        tex::Hash128 key, source;
        std::string recipe;
        tex::Ktx2Texture texture;        // as the cache served it before any mutation
        std::vector<std::uint8_t> bytes; // the entry's file
    };
    TargetConfig config_;
    std::optional<tex::TextureCache> cache_;
    std::vector<Entry> entries_;
    std::size_t current_ = 0;
};

} // namespace sherpa::fuzz
