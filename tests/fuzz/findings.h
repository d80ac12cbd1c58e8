#pragma once
// Where the fuzzer's findings go: one directory per saved reproducer (the case's files
// and finding.txt with what happened, the sanitizer's report and the command that
// replays it), and an index of every finding by signature, shared by the supervisor
// and its workers (appended with O_APPEND), so the summary counts each cause once.
#include <cstdint>
#include <filesystem>
#include <string>

#include "targets.h"

namespace sherpa::fuzz {

class FindingLog {
public:
    explicit FindingLog(std::filesystem::path dir);
    // Records a finding of case `index`; keeps the reproducer of the first few of
    // each signature. `report` (may be empty) is the worker's stderr log.
    void save(const Target& target, std::uint64_t seed, std::uint64_t index,
              const std::string& what, const std::filesystem::path& report);
    // Distinct signatures with their counts and a reproducer, on stdout.
    void print_summary() const;

private:
    std::filesystem::path dir_;
};

} // namespace sherpa::fuzz
