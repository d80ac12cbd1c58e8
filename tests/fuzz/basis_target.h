#pragma once
// Basis Universal transcoder target (see basis_target.cpp).
#include <optional>

#include <sherpa/texture/basis.h>

#include "targets.h"

namespace sherpa::fuzz {

class BasisTarget : public Target {
public:
    std::string name() const override { return "basis"; }
    bool init(const TargetConfig& config, std::string& error) override;
    std::filesystem::path make_case(Rng& rng) override;
    std::optional<std::string> run() override;
    std::vector<std::filesystem::path> case_files() const override;

private:
    TargetConfig config_;
    std::vector<std::vector<std::uint8_t>> seeds_; // KTX2 files from the reference encoder
    std::vector<std::uint8_t> bytes_;
};

} // namespace sherpa::fuzz
