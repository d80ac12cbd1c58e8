#pragma once
// The growth of this process's peak resident memory while a callable runs: how the
// oversized-input tests show that a file's declared sizes were not allocated.
#include <cstring>
#include <fstream>
#include <string>

namespace sherpa::test {

// In KiB: the kernel's high-water mark (VmHWM) after `run`, less the resident size
// before it, the mark having been reset through /proc/self/clear_refs (Linux 4.0 on).
// Negative when the mark cannot be reset.
template <typename Run> long peak_rss_growth_kib(Run&& run) {
    auto status = [](const char* key) {
        std::ifstream in("/proc/self/status");
        for (std::string line; std::getline(in, line);)
            if (line.rfind(key, 0) == 0) return std::stol(line.substr(std::strlen(key)));
        return -1L;
    };
    if (!(std::ofstream("/proc/self/clear_refs") << "5" << std::flush)) return -1;
    const long before = status("VmRSS:");
    run();
    return status("VmHWM:") - before;
}

} // namespace sherpa::test
