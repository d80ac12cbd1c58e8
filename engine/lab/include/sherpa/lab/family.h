#pragma once
// The Lab: families of methods that trade speed for accuracy, each run on the loaded
// scene and measured against the family's reference. One small interface for every
// family (tangents, texture compression, culling; shadows, mesh compression, LOD later)
// so that the CLI (`sherpa-cli lab`) and an editor dock read the same numbers.
//
// A family lists its methods, then run() measures every method on one scene and
// returns per method its time, its error figures against the reference and its
// failures by cause (which primitive, texture or camera, and why). run() is
// synchronous and may take seconds: callers off the UI thread cancel it through
// RunControl::cancel and follow it through RunControl::progress.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <sherpa/core/progress.h>
#include <sherpa/scene/scene.h>
#include <sherpa/scene/scene_loader.h>

namespace sherpa::lab {

// One method of a family and the parameter that sets it apart ("level=2"; empty
// when the method has none). Methods measured on different inputs (BC7 on colour
// textures, BC5 on normal maps) are in different groups: only methods of one group
// are compared with each other (Pareto front).
struct MethodInfo {
    std::string name;
    std::string parameters;
    std::string description;
    std::string group;
};

// A named error figure. Lower is better unless `higher_is_better` (PSNR).
struct ErrorFigure {
    std::string name; // "angle_mean_deg", "psnr_db", "false_positives", ...
    double value = 0.0;
    bool higher_is_better = false;
};

// Where a method failed and why: `count` units (corners, texels, objects) with cause
// `cause` at `where` ("mesh 0 primitive 1 'Helmet'", "image 2 'normal.png'",
// "camera 3 instance 17").
struct Failure {
    std::string cause;
    std::string where;
    std::uint64_t count = 0;
};

struct MethodResult {
    MethodInfo method;
    bool ran = false;    // false: not applicable or not possible here (see `note`)
    std::string note;    // why it did not run, or what it ran on
    double time = 0.0;   // in FamilyReport::time_unit
    double total_ms = 0; // CPU (or GPU) milliseconds of the whole measurement
    // The family's chart error first (FamilyReport::chart_error), then the others.
    std::vector<ErrorFigure> errors;
    std::vector<Failure> failures;

    // The figure named `name`, or nullptr.
    const ErrorFigure* error(std::string_view name) const;
};

struct FamilyReport {
    std::string family;
    std::string reference;   // what the errors are measured against
    std::string time_unit;   // "ms/Mtri", "ms/MPix", "ns/object"
    std::string chart_error; // the figure a time-vs-error chart plots
    // The figure on the chart's x axis instead of time (mesh compression: "bytes");
    // empty: time. The Pareto front is taken over the same two.
    std::string chart_x;
    std::vector<MethodResult> methods;
    std::vector<std::string> notes; // what was measured (inputs skipped, sampling)
    // What the user should know the methods or reference could not do as the file asks
    // (the path tracer's emitters it cannot sample as lights: file, JSON pointer, problem).
    std::vector<std::string> warnings;
    bool cancelled = false; // RunControl::cancel stopped it: no methods
};

struct RunControl {
    // Units of work done of the total (methods x inputs); called on the running thread.
    core::ProgressCallback progress;
    // Polled between units of work; once cancelled run() returns a report with
    // `cancelled` set and no methods.
    const core::CancelToken* cancel = nullptr;
};

class Family {
public:
    virtual ~Family() = default;
    virtual std::string_view name() const = 0;
    virtual std::vector<MethodInfo> methods() const = 0;
    // Measures every method on `scene`. Never throws for bad scene content: what a
    // method cannot handle is a Failure, what cannot run at all a method with ran false.
    virtual FamilyReport run(const scene::Scene& scene, const RunControl& control) const = 0;
};

// How the Lab loads a scene: tangents as in the file (no generation at load, whose
// vertex splits would make welded MikkTSpace equal the exact one everywhere).
scene::LoadOptions lab_load_options();

// "tangents", "textures", "culling", "mesh-compression", "shadows", "lighting".
std::vector<std::string_view> family_names();
// The family with default options, or nullptr for an unknown name.
std::unique_ptr<Family> make_family(std::string_view name);

} // namespace sherpa::lab
