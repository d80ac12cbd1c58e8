#pragma once
// Which SIMD instruction sets this CPU runs, asked once at run time: the scene
// layer's batch culling and the texture layer's block encoders both have kernels
// per level and pick one with best_simd_level().
#include <cstdint>
#include <string_view>

namespace sherpa::core {

enum class SimdLevel : std::uint8_t { Scalar, Avx2, Avx512 };
std::string_view to_string(SimdLevel s);

// Avx512 needs AVX-512 F/BW/VL and BMI2; Avx2 needs AVX2, FMA and BMI2: exactly what
// the kernels are compiled with (engine/texture/CMakeLists.txt).
SimdLevel best_simd_level();

} // namespace sherpa::core
