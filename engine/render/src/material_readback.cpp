#include <sherpa/gpu/commands.h>
#include <sherpa/gpu/context.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/material_extensions.h>
#include <sherpa/render/material_readback.h>
#include <sherpa/render/renderer.h>

#include <cstring>

namespace sherpa::render {

std::optional<MaterialReadback> read_material(Renderer& renderer, const scene::Scene& scene,
                                              int material) {
    const GpuScene* gpu_scene = renderer.scene();
    if (!gpu_scene || material < 0 || static_cast<std::size_t>(material) >= scene.materials.size())
        return std::nullopt;
    gpu::ResourceManager& resources = renderer.resources();
    constexpr VkDeviceSize kSize = sizeof(scene::GPUMaterialData);
    // The material's extension words: its index up to the next material's (blocks
    // follow their material's index, in material order).
    const MaterialExtensionBuffer& ext = gpu_scene->materials().extensions();
    std::uint32_t first = 0, end = 0;
    if (std::size_t(material) < ext.places.size() && ext.places[std::size_t(material)].any()) {
        first = ext.places[std::size_t(material)].index;
        end = static_cast<std::uint32_t>(ext.words.size());
        for (std::size_t m = std::size_t(material) + 1; m < ext.places.size(); ++m)
            if (ext.places[m].any()) {
                end = ext.places[m].index;
                break;
            }
    }
    const VkDeviceSize ext_bytes = VkDeviceSize(end - first) * sizeof(glm::uvec4);
    gpu::BufferHandle staging =
        resources.create_buffer({kSize + ext_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                 gpu::MemoryUsage::Readback, "material readback"});
    // One copy out of the device-local material array (and one of the extension
    // buffer), waited on: a dock refresh, not a frame.
    gpu::CommandRecorder recorder(renderer.context());
    const VkCommandBuffer cmd = recorder.begin();
    const VkBufferCopy region{static_cast<VkDeviceSize>(material) * kSize, 0, kSize};
    vkCmdCopyBuffer(cmd, gpu_scene->materials().buffer(), resources.get(staging).buffer.get(), 1,
                    &region);
    if (ext_bytes) {
        const VkBufferCopy words{VkDeviceSize(first) * sizeof(glm::uvec4), kSize, ext_bytes};
        vkCmdCopyBuffer(cmd, gpu_scene->materials().extensions_buffer(),
                        resources.get(staging).buffer.get(), 1, &words);
    }
    resources.timeline().wait_for(recorder.submit(resources));
    const gpu::Buffer& readback = resources.get(staging);
    // Readback memory may be cached without coherence: make the GPU's writes visible.
    const VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE, nullptr,
                                    readback.memory.get(), 0, VK_WHOLE_SIZE};
    vkInvalidateMappedMemoryRanges(renderer.context().device(), 1, &range);
    MaterialReadback out;
    std::memcpy(&out.record, readback.mapped, kSize);
    out.extension_first = first;
    out.extension_words.resize(end - first);
    if (ext_bytes)
        std::memcpy(out.extension_words.data(),
                    static_cast<const std::uint8_t*>(readback.mapped) + kSize, ext_bytes);
    resources.destroy(staging);

    // Every (texture, role) slot the scene registered, inverted.
    for (std::size_t t = 0; t < scene.textures.size(); ++t)
        for (scene::TextureRole role :
             {scene::kRoleColor, scene::kRoleLinear, scene::kRoleNormal}) {
            const std::uint32_t slot =
                gpu_scene->materials().textures().slot(static_cast<std::int32_t>(t), role);
            if (slot == scene::kTextureSentinel) continue;
            if (slot >= out.bindless_to_texture.size())
                out.bindless_to_texture.resize(slot + 1, -1);
            out.bindless_to_texture[slot] = static_cast<int>(t);
        }
    return out;
}

} // namespace sherpa::render
