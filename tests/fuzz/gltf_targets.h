#pragma once
// Importer targets (see gltf_targets.cpp).
#include <sherpa/scene/scene_loader.h>

#include "targets.h"

namespace sherpa::fuzz {

// A GLB container (glTF 2.0 spec, section 4.4): header, JSON chunk padded with
// spaces, optional BIN chunk padded with zeros.
std::vector<std::uint8_t> make_glb(const std::string& json, std::span<const std::uint8_t> bin);
// The JSON and BIN chunks of a well-formed GLB (false when the header or JSON chunk
// is not); a BIN chunk longer than the file is cut at its end.
bool split_glb(std::span<const std::uint8_t> glb, std::string& json,
               std::vector<std::uint8_t>& bin);

class GltfTarget : public Target {
public:
    std::string name() const override { return "gltf"; }
    bool init(const TargetConfig& config, std::string& error) override;
    std::filesystem::path make_case(Rng& rng) override;
    std::optional<std::string> run() override;
    std::vector<std::filesystem::path> case_files() const override { return written_; }

protected:
    struct Seed {
        std::filesystem::path source;                // the seed file
        std::filesystem::path case_dir;              // its siblings linked, cases written here
        std::vector<std::uint8_t> text;              // the file's bytes (for .glb targets: the GLB)
        nlohmann::json doc;                          // parsed, or discarded when not JSON
        std::vector<std::vector<std::uint8_t>> bins; // per buffer; empty: not local/too big
    };
    // Accepts (and possibly converts) a seed; false: not a seed of this target.
    virtual bool add_seed(Seed seed);
    // Writes the case's main file beside the seed's files; returns the directory.
    std::filesystem::path write_case(const Seed& seed, const std::string& name,
                                     std::span<const std::uint8_t> bytes);
    // Imports the case with `options` and checks what a loaded scene promises.
    std::optional<std::string> load(const scene::LoadOptions& options);

    TargetConfig config_;
    std::vector<Seed> seeds_;
    std::filesystem::path case_path_;
    std::vector<std::filesystem::path> written_;
};

class GlbTarget : public GltfTarget {
public:
    std::string name() const override { return "glb"; }
    std::filesystem::path make_case(Rng& rng) override;

protected:
    bool add_seed(Seed seed) override;
};

class TangentsTarget : public GltfTarget {
public:
    std::string name() const override { return "tangents"; }
    std::filesystem::path make_case(Rng& rng) override;
    std::optional<std::string> run() override;

private:
    scene::TangentMethod method_ = scene::TangentMethod::MikkTSpace;
};

} // namespace sherpa::fuzz
