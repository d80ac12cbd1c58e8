#pragma once
// PNG/JPEG/WebP decoding target (see image_target.cpp).
#include "targets.h"

namespace sherpa::fuzz {

class ImageTarget : public Target { // seeds: tests/data/image_seeds
public:
    std::string name() const override { return "image"; }
    bool init(const TargetConfig& config, std::string& error) override;
    std::filesystem::path make_case(Rng& rng) override;
    std::optional<std::string> run() override;
    std::vector<std::filesystem::path> case_files() const override { return {case_path_}; }

private:
    struct Seed {
        std::string extension; // ".png", ".jpg", ".webp": the name hint picks the reader
        std::vector<std::uint8_t> bytes;
    };
    TargetConfig config_;
    std::vector<Seed> seeds_;
    std::vector<std::uint8_t> bytes_;
    std::filesystem::path case_path_;
};

} // namespace sherpa::fuzz
