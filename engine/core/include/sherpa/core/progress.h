#pragma once
// Progress reports and cooperative cancellation for long engine operations (scene
// loading, texture preparation). Plain C++: callers on any thread, any toolkit.
#include <atomic>
#include <cstddef>
#include <functional>

namespace sherpa::core {

// Set from any thread; the operation polls it between units of work and, once it
// sees it, stops and returns no partial result.
class CancelToken {
public:
    void cancel() { cancelled_.store(true, std::memory_order_relaxed); }
    bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }

private:
    std::atomic<bool> cancelled_{false};
};

inline bool is_cancelled(const CancelToken* token) {
    return token && token->cancelled();
}

// `done` of `total` units of the current stage; total 0: the stage has no count.
// Called on the thread doing the work (worker threads for parallel stages).
using ProgressCallback = std::function<void(std::size_t done, std::size_t total)>;

} // namespace sherpa::core
