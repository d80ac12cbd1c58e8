#pragma once
// Fuzz targets: each makes one mutated case from its seeds (written as files into
// the case directory, since the importer and the cache read files) and runs the code
// under test on it in-process. A crash, sanitizer report or hang is found by the
// supervising process (runner.cpp); a wrong result that does not crash is returned
// as a finding message by run().
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "mutate.h"

namespace sherpa::fuzz {

struct TargetConfig {
    std::filesystem::path assets_dir; // shared/assets: glTF sample models
    std::filesystem::path data_dir;   // tests/data: hand-made malformed files
    std::filesystem::path work_dir;   // scratch space of this target (created)
    std::size_t max_size = 4u << 20;  // no case file grows beyond this
    // Seeds (file plus its buffers) above this are left out: a case's cost grows with
    // its size, and the bugs found so far needed a kilobyte or two.
    std::size_t max_seed_size = 320u << 10;
};

class Target {
public:
    virtual ~Target() = default;
    virtual std::string name() const = 0;
    // Loads or generates the seeds; false with `error` when there are none.
    virtual bool init(const TargetConfig& config, std::string& error) = 0;
    // Writes case `rng` into its directory and returns that directory.
    virtual std::filesystem::path make_case(Rng& rng) = 0;
    // Runs the code under test on the case just made. nullopt: no finding.
    virtual std::optional<std::string> run() = 0;
    // Case files in the case directory (what a reproducer consists of).
    virtual std::vector<std::filesystem::path> case_files() const = 0;
};

// Targets whose case is one byte string: a seed, mutated (spliced with another seed
// now and then), written to `case_name` in the work directory as the reproducer.
// Subclasses fill `seeds_` in init() and run the code under test on `bytes_`.
class ByteTarget : public Target {
public:
    std::filesystem::path make_case(Rng& rng) override;
    std::vector<std::filesystem::path> case_files() const override;

protected:
    explicit ByteTarget(std::string case_name) : case_name_(std::move(case_name)) {}

    TargetConfig config_;
    std::vector<std::vector<std::uint8_t>> seeds_;
    std::vector<std::uint8_t> bytes_; // the case made last

private:
    std::string case_name_;
};

// Replaces `path` (a file left by an earlier case) with `bytes`.
void write_case_file(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

// "gltf", "glb", "tangents", "ktx2", "cache", "basis", "validate", in that order.
std::vector<std::unique_ptr<Target>> make_targets();

} // namespace sherpa::fuzz
