#pragma once
// sherpa-bench-validate --passes (validate_passes.cpp).
#include <filesystem>

namespace sherpa::bench {

// Prints the validator's passes' times on `file` (the fastest of `repeat` each, in one
// process) beside the importer's JSON parse and property checks; false when the file
// does not parse.
bool print_passes(const std::filesystem::path& file, int repeat);

} // namespace sherpa::bench
