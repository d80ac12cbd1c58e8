#pragma once
// Entry points of the per-instruction-set encoder kernels. Each namespace is one
// compilation of encode_bc7.cpp / encode_bc5.cpp with its own -m flags; the
// dispatcher in encode_dispatch.cpp picks one at run time.
#include <cstdint>

#define SHERPA_DECLARE_ENCODE_KERNELS(ns)                                                          \
    namespace sherpa::tex::ns {                                                                    \
    void encode_bc7_block_kernel(const std::uint8_t rgba[64], int level, std::uint8_t out[16]);    \
    void encode_bc5_block_kernel(const std::uint8_t rgba[64], int level, std::uint8_t out[16]);    \
    }

SHERPA_DECLARE_ENCODE_KERNELS(scalar)
SHERPA_DECLARE_ENCODE_KERNELS(avx2)
SHERPA_DECLARE_ENCODE_KERNELS(avx512)

#undef SHERPA_DECLARE_ENCODE_KERNELS
