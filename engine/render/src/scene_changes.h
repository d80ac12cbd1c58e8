#pragma once
// What changes in the loaded scene between frames (private to the render layer): the
// frame's animated properties (KHR_animation_pointer) and the node visibility, applied
// before a frame (renderer_visibility.cpp), and the material variant switch
// (KHR_materials_variants, renderer_variants.cpp). Each reaches the parts of the frame
// recorder it invalidates: the culling's per-instance data, the cached shadow
// cascades, and the frames in flight that still read what is replaced.
#include "frame_slots.h"
#include "passes.h"

namespace sherpa::render {

class SceneChanges : private SceneStateRefs {
public:
    SceneChanges(SceneState& state, FrameSlots& slots, CullingPass& culling, ShadowPass& shadows);
    SceneChanges(const SceneChanges&) = delete;
    SceneChanges& operator=(const SceneChanges&) = delete;

    // Before a frame: the frame's animated properties (KHR_animation_pointer) into the
    // scene state, the materials they change uploaded (after the frames in flight); then
    // the visibility (SceneSetup::hidden_nodes and the nodes the animation hides) into
    // the culling and, with `rt`, the TLAS (every slot must be idle), when it differs
    // from the mask applied last.
    void apply_scene_changes(const FrameRequest& settings, bool rt);
    // set_material_variant() (renderer_variants.cpp): waits for the frames in flight.
    VariantSwitch set_variant(std::int32_t variant);

private:
    // Frames in flight index GPU cullers and draw groups about to be replaced: waits
    // for them, their unread statistics kept in the history now.
    void retire_culling();

    FrameSlots& slots_;
    CullingPass& culling;
    ShadowPass& shadows_;
};

} // namespace sherpa::render
