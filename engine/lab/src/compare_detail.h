#pragma once
// The parts of compare_files, one file each.
#include <vector>

#include <sherpa/lab/compare.h>

namespace sherpa::lab::detail {

std::vector<PrimitiveDiff> compare_primitives(const scene::Scene& a, const scene::Scene& b);

} // namespace sherpa::lab::detail
