#pragma once
// Posed bounds target (see pose_target.cpp).
#include <sherpa/scene/scene.h>

#include "targets.h"

namespace sherpa::fuzz {

class PoseTarget : public Target { // seeds: the shared motion assets, imported once
public:
    std::string name() const override { return "pose"; }
    bool init(const TargetConfig& config, std::string& error) override;
    std::filesystem::path make_case(Rng& rng) override;
    std::optional<std::string> run() override;
    std::vector<std::filesystem::path> case_files() const override { return {case_path_}; }

private:
    struct Seed {
        std::string model;
        scene::Scene original; // as imported
        scene::Scene scene;    // the case: motion data changed, restored from `original` each case
    };
    void mutate(Rng& rng, scene::Scene& scene, std::string& log);

    TargetConfig config_;
    std::vector<Seed> seeds_;
    Seed* current_ = nullptr;
    std::int32_t animation_ = -1;
    double time_ = 0.0;
    bool tame_ = true;    // every value drawn from everyday magnitudes: containment is checked
    bool freeze_ = false; // also pose the whole scene on the CPU (freeze_pose)
    std::filesystem::path case_path_;
};

} // namespace sherpa::fuzz
