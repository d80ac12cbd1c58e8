#pragma once
// Quality levels of the block encoders. A header of its own so the
// per-instruction-set kernels need nothing else from the engine.

namespace sherpa::tex {

// BC7 quality levels, fastest first. Level 0 uses mode 6 alone; higher levels add
// partitioned modes, more partitions tried and more endpoint refinement.
inline constexpr int kBc7MinLevel = 0;
inline constexpr int kBc7MaxLevel = 4;
inline constexpr int kBc7DefaultLevel = 1;

// BC5 quality levels: 0 fits endpoints by one least-squares pass; 1 runs three and
// then nudges the endpoints (and tries the six-value mode) on blocks still off.
inline constexpr int kBc5MinLevel = 0;
inline constexpr int kBc5MaxLevel = 1;
inline constexpr int kBc5DefaultLevel = 1;

} // namespace sherpa::tex
