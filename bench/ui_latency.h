#pragma once
// UI event latency for the editor's benchmarks (sherpa-bench-orbit, sherpa-bench-lab):
// a second thread posts an event to the GUI thread every 10 ms while some work runs;
// the delay until each event runs is what a user's input would wait.
#include <QCoreApplication>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace sherpa::bench {

inline double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<std::size_t>(p * double(v.size())))];
}

// Delays of events posted to the GUI thread every 10 ms while `work` runs.
inline std::vector<double> latencies_during(const std::function<void()>& work) {
    std::vector<double> delays;
    std::mutex m;
    std::atomic<bool> stop{false};
    std::thread poster([&] {
        while (!stop) {
            const auto posted = std::chrono::steady_clock::now();
            QMetaObject::invokeMethod(qApp, [&, posted] {
                const double ms = std::chrono::duration<double, std::milli>(
                                      std::chrono::steady_clock::now() - posted)
                                      .count();
                std::lock_guard lock(m);
                delays.push_back(ms);
            });
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
    });
    work();
    stop = true;
    poster.join();
    QCoreApplication::processEvents();
    std::lock_guard lock(m);
    return delays;
}

} // namespace sherpa::bench
