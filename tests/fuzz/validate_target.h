#pragma once
// The glTF validator as a fuzz target (see validate_target.cpp).
#include "targets.h"

namespace sherpa::fuzz {

class ValidateTarget : public ByteTarget {
public:
    ValidateTarget() : ByteTarget("__case_validate") {}
    std::string name() const override { return "validate"; }
    bool init(const TargetConfig& config, std::string& error) override;
    std::optional<std::string> run() override;
};

} // namespace sherpa::fuzz
