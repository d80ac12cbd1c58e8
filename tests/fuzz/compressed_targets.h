#pragma once
// Compressed-geometry targets (see compressed_targets.cpp): meshopt and Draco payloads.
#include "gltf_targets.h"

namespace sherpa::fuzz {

// GLB seeds from tests/data/compressed_seeds whose extensionsUsed names one of the
// target's extensions; cases mutate mostly the compressed streams and the extension
// objects that describe them, then import the file like the glb target.
class CompressedTarget : public GltfTarget {
public:
    bool init(const TargetConfig& config, std::string& error) override;
    std::filesystem::path make_case(Rng& rng) override;

protected:
    explicit CompressedTarget(std::vector<std::string> extensions)
        : extensions_(std::move(extensions)) {}
    // One compressed stream: the extension object (a JSON pointer) and its bytes in BIN.
    struct Payload {
        nlohmann::json::json_pointer extension;
        std::size_t offset = 0, length = 0;
    };
    // The streams of a seed's document (`bin` is its BIN chunk).
    virtual std::vector<Payload> payloads(const nlohmann::json& doc) const = 0;

private:
    std::vector<std::string> extensions_;
    std::vector<std::vector<Payload>> payloads_; // per seed
};

class MeshoptTarget : public CompressedTarget { // EXT_ and KHR_meshopt_compression
public:
    MeshoptTarget() : CompressedTarget({"EXT_meshopt_compression", "KHR_meshopt_compression"}) {}
    std::string name() const override { return "meshopt"; }

protected:
    std::vector<Payload> payloads(const nlohmann::json& doc) const override;
};

class DracoTarget : public CompressedTarget { // KHR_draco_mesh_compression
public:
    DracoTarget() : CompressedTarget({"KHR_draco_mesh_compression"}) {}
    std::string name() const override { return "draco"; }

protected:
    std::vector<Payload> payloads(const nlohmann::json& doc) const override;
};

} // namespace sherpa::fuzz
