#pragma once
// Basis Universal transcoder target (see basis_target.cpp).
#include <optional>

#include <sherpa/texture/basis.h>

#include "targets.h"

namespace sherpa::fuzz {

class BasisTarget : public ByteTarget { // seeds: KTX2 files from the reference encoder
public:
    BasisTarget() : ByteTarget("__case.ktx2") {}
    std::string name() const override { return "basis"; }
    bool init(const TargetConfig& config, std::string& error) override;
    std::optional<std::string> run() override;
};

} // namespace sherpa::fuzz
