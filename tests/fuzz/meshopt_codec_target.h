#pragma once
// The meshopt decoders called directly (see meshopt_codec_target.cpp).
#include <optional>

#include "targets.h"

namespace sherpa::fuzz {

class MeshoptCodecTarget : public ByteTarget { // seeds: the meshopt GLB seeds' streams
public:
    MeshoptCodecTarget() : ByteTarget("__case.meshopt") {}
    std::string name() const override { return "meshopt_codec"; }
    bool init(const TargetConfig& config, std::string& error) override;
    std::optional<std::string> run() override;
};

} // namespace sherpa::fuzz
