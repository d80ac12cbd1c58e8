#pragma once
// The path tracer's accumulation across frames (private to the render layer; code in
// renderer_path.cpp): the lit view traced by PathTracePass (path_trace_pass.h), its
// constants, when the per-pixel sums continue and when they start over (a hash of
// everything the image depends on), and the sums read back (read_path_trace()).
#include "frame_slots.h"
#include "path_trace_pass.h"

namespace sherpa::render {

class PathTracer : private SceneStateRefs {
public:
    PathTracer(SceneState& state, FrameSlots& slots);
    PathTracer(const PathTracer&) = delete;
    PathTracer& operator=(const PathTracer&) = delete;

    // The samples of `settings` (view lit; the TLAS must exist) into `cmd`, its
    // constants into `slot` (no frame in flight): continues the accumulation or starts
    // it over.
    PathTraceFrame record(VkCommandBuffer cmd, FrameSlot& slot, const FrameRequest& settings,
                          bool readback);
    // The accumulation read back after the frames in flight (empty before the first
    // path-traced frame).
    PathTraceImage image();
    // The shown image (after record() with `readback`) and its view (GENERAL layout).
    void read(std::vector<std::uint8_t>& rgba) const { path_->read(rgba); }
    VkImageView view() const { return path_->view(); }

private:
    FrameSlots& slots_;

    std::unique_ptr<PathTracePass> path_;
    std::uint64_t path_environment_ = ~0ull; // environment generation path_ samples
    std::uint64_t path_lights_ = ~0ull;      // scene generation path_'s light list is of
    std::uint64_t path_key_ = 0;             // what the accumulation is of
    std::uint32_t path_samples_ = 0;
};

} // namespace sherpa::render
