#pragma once
// A renderer's frames in flight (private to the render layer): one FrameSlot each
// (frame_context.h: command recorder, frame constants, queries, culling and pose
// buffers), handed out in turn, waited for and marked submitted; and each slot's
// descriptor set 1 (frame constants, the scene's materials, the shadow map, the
// environment's maps, material extensions, the transmission background), pointed at
// what the loaded SceneState holds before a frame binds it. The FrameRecorder, the ray
// tracer and the path tracer record into these slots; renderer.cpp holds their code.
#include "frame_context.h"
#include "scene_state.h"

#include <sherpa/gpu/unique_handle.h>

#include <memory>
#include <vector>

namespace sherpa::render {

class FrameSlots : private SceneStateRefs {
public:
    static constexpr std::uint32_t kFramesInFlight = Renderer::kFramesInFlight;
    explicit FrameSlots(SceneState& state);
    ~FrameSlots();
    FrameSlots(const FrameSlots&) = delete;
    FrameSlots& operator=(const FrameSlots&) = delete;

    FrameSlot& operator[](std::uint32_t index) { return *slots_.at(index); }
    // Every slot, in index order.
    auto begin() { return slots_.begin(); }
    auto end() { return slots_.end(); }
    // The slot the next frame takes; take() hands it out and moves on.
    std::uint32_t next() const { return next_slot_; }
    std::uint32_t take();
    // Waits until the frame last recorded in `slot` has completed (none: returns).
    void wait(FrameSlot& slot);
    void wait_all();
    // Frame slot `index` was submitted with timeline value `submission`; its results
    // are read when the slot comes round again.
    void finish(std::uint32_t index, std::uint64_t submission);
    // Slot `index`'s command recorder (offscreen comparisons, comparison.cpp).
    gpu::CommandRecorder& recorder(std::uint32_t index) { return slots_.at(index)->recorder; }
    // Set 1's layout (the pipelines' and the transmission pass's).
    VkDescriptorSetLayout layout() const { return frame_layout_.get(); }
    // Points the slot's set at its frame data, the loaded scene's materials, the
    // environment's maps and `shadow_map`, where they changed since it was last bound.
    void bind_frame_set(FrameSlot& slot, const VkDescriptorImageInfo& shadow_map);

private:
    void create_frame_sets();

    gpu::UniqueDescriptorSetLayout frame_layout_;
    gpu::UniqueDescriptorPool frame_pool_;
    gpu::BufferHandle no_materials_; // bound while no scene is loaded
    std::vector<std::unique_ptr<FrameSlot>> slots_;
    std::uint32_t next_slot_ = 0;
};

} // namespace sherpa::render
