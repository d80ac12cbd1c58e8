#include <sherpa/core/cpu_features.h>

namespace sherpa::core {

std::string_view to_string(SimdLevel s) {
    switch (s) {
    case SimdLevel::Scalar:
        return "scalar";
    case SimdLevel::Avx2:
        return "avx2";
    case SimdLevel::Avx512:
        return "avx512";
    }
    return "?";
}

SimdLevel best_simd_level() {
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
        __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("bmi2"))
        return SimdLevel::Avx512;
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
        __builtin_cpu_supports("bmi2"))
        return SimdLevel::Avx2;
    return SimdLevel::Scalar;
}

} // namespace sherpa::core
