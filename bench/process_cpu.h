#pragma once
// Process CPU time for the GPU benchmarks: on a CPU device (lavapipe) the frame's
// work runs on the driver's threads, so every thread of the process is counted.
#include <sys/resource.h>

namespace sherpa::bench {

inline double process_cpu_ms() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u); // every thread of the process: lavapipe's too
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1e3 +
           double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-3;
}

} // namespace sherpa::bench
