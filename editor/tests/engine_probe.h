#pragma once
// What the window suites read of the engine behind the viewport, on the render thread
// (RenderThread::call): the engine's own objects, reached through
// GpuViewport::renderer(). A translation unit of its own: the engine's Vulkan headers
// and Qt's (QVulkanInstance, which declares no Vulkan prototypes) do not mix.
#include <QStringList>

#include <cstdint>

namespace sherpa::editor {
class GpuViewport;
}

namespace sherpa::editor::test {

// Messages of the Khronos validation layer so far, one "[id] text" each.
QStringList validation_messages(GpuViewport& gpu);
// Buffers, images and samplers alive in the engine, once those retired by earlier
// frames are freed (leak checks).
std::int64_t gpu_object_count(GpuViewport& gpu);
// The latest completed frame pass by pass (GPU timestamps): "NAME MS ms" each, in
// frame order; empty before a frame is presented.
QStringList last_pass_times(GpuViewport& gpu);

} // namespace sherpa::editor::test
