#pragma once
// sherpa-texture-sweep --decode: BC7 decode throughput on the DamagedHelmet maps.
#include <ctime>
#include <filesystem>

namespace sherpa::bench {

// CPU time of the whole process (every thread), in ms.
inline double cpu_ms() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) / 1e6;
}

// Encodes the four DamagedHelmet 2048^2 maps to BC7 at the default level, then
// times decoding them with the reference per-block decoder (decode_bc7_block
// plus a copy: decode_image before the fast path) and with decode_image on one
// thread (CPU time: MPix/s per core) and on `threads` threads (wall time; 0 or 1
// skips that row). Checks all outputs are identical; returns 1 when they differ.
int run_decode_bench(const std::filesystem::path& assets, int threads);

} // namespace sherpa::bench
