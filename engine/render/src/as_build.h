#pragma once
// What BLAS and TLAS builds share (private to the render layer): a scratch buffer
// whose device address honours the device's scratch alignment, GPU timestamps
// around each build of a submission, and the description of a BLAS build.
#include <cstdint>
#include <span>
#include <vector>

#include <sherpa/gpu/resources.h>
#include <sherpa/gpu/unique_handle.h>
#include <sherpa/render/gpu_scene.h>

namespace sherpa::render {

inline std::uint64_t align_up(std::uint64_t v, std::uint64_t a) {
    return a ? (v + a - 1) / a * a : v;
}

// Device-local scratch, released (deferred) when it goes out of scope.
class ScratchBuffer {
public:
    ScratchBuffer(gpu::ResourceManager& resources, std::uint64_t bytes);
    ~ScratchBuffer() { resources_.destroy(buffer_); }
    ScratchBuffer(const ScratchBuffer&) = delete;
    ScratchBuffer& operator=(const ScratchBuffer&) = delete;
    VkDeviceAddress address() const { return address_; } // aligned
    std::uint64_t bytes() const { return bytes_; }

private:
    gpu::ResourceManager& resources_;
    gpu::BufferHandle buffer_;
    VkDeviceAddress address_ = 0;
    std::uint64_t bytes_ = 0;
};

// Pairs of timestamps (before, after) around `count` builds; empty on devices
// without timestamps.
class BuildTimer {
public:
    BuildTimer(const gpu::Context& context, std::uint32_t count);
    void begin(VkCommandBuffer cmd, std::uint32_t i) const { write(cmd, 2 * i); }
    void end(VkCommandBuffer cmd, std::uint32_t i) const { write(cmd, 2 * i + 1); }
    // Milliseconds per build after the submission completed; -1 where unmeasured.
    std::vector<double> read() const;

private:
    void write(VkCommandBuffer cmd, std::uint32_t query) const;

    const gpu::Context& context_;
    std::uint32_t count_;
    gpu::UniqueQueryPool pool_;
};

struct BlasPlan;

// The Vulkan description of one planned BLAS; stays put while its build is recorded.
struct BlasInput {
    std::vector<VkAccelerationStructureGeometryKHR> geometries;
    std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges;
    std::vector<std::uint32_t> max_primitives;
    VkAccelerationStructureBuildGeometryInfoKHR info{};
    VkAccelerationStructureBuildSizesInfoKHR sizes{};
};

// `plan`'s geometries over `gpu`'s index buffer and position streams, or, per
// geometry k < positions.size(), over positions[k] (posed vertices); mode BUILD.
BlasInput describe_blas(const BlasPlan& plan, const GpuScene& gpu,
                        VkBuildAccelerationStructureFlagsKHR flags,
                        std::span<const VkDeviceAddress> positions = {});

// Orders one build's writes before the next build and before queries and copies
// of the structures it built.
void build_barrier(VkCommandBuffer cmd);

} // namespace sherpa::render
