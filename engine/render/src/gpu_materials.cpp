// GpuMaterials: the material records (GPUMaterialData), their uv transforms and
// workflow (GPUMaterialExtra) and the extension buffer, built from the scene's materials
// with textures resolved to bindless slots; update() re-uploads only the records an
// animation or a variant changed.
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/upload.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/gpu_structs.h>
#include <sherpa/render/material_extensions.h>

#include <cstring>

namespace sherpa::render {
namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                        VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT |
                                        VK_BUFFER_USAGE_TRANSFER_DST_BIT;

} // namespace

GpuMaterials::~GpuMaterials() {
    resources_.destroy(materials_);
    resources_.destroy(extras_);
    if (extension_buffer_.valid()) resources_.destroy(extension_buffer_);
}

void GpuMaterials::build(std::span<const scene::MaterialInstance> materials) {
    data_.clear();
    extras_data_.clear();
    extensions_ = build_material_extensions(
        materials, [this](const scene::TextureSlot& slot, scene::TextureRole role) {
            // A failed texture reads white (the factor alone) or the flat normal, not
            // the checker: the texture pipeline has warned, and a checker would only
            // tint the factor.
            const std::uint32_t fallback =
                role == scene::kRoleNormal ? gpu::kFlatNormalTexture : gpu::kWhiteTexture;
            const std::uint32_t tex = textures_->field_slot(slot, role, fallback);
            return tex == gpu::kCheckerTexture ? fallback : tex;
        });
    for (const scene::MaterialInstance& m : materials) {
        // Texture fields resolved to bindless slots, absent ones to the defaults.
        data_.push_back(textures_->material(m));
        GPUMaterialExtra x{};
        x.uv[kSlotBaseColor] = texture_transform(m.base_color);
        x.uv[kSlotMetallicRoughness] = texture_transform(m.metallic_roughness);
        x.uv[kSlotNormal] = texture_transform(m.normal);
        x.uv[kSlotOcclusion] = texture_transform(m.occlusion);
        x.uv[kSlotEmissive] = texture_transform(m.emissive);
        x.unlit = m.unlit ? 1u : 0u;
        x.specular_glossiness_tex = gpu::kWhiteTexture;
        x.extensions = extensions_.places[data_.size() - 1].index;
        if (const auto& sg = m.specular_glossiness) {
            x.workflow = kWorkflowSpecularGlossiness;
            x.uv[kSlotSpecularGlossiness] = texture_transform(sg->specular_glossiness);
            x.specular_glossiness_tex = textures_->field_slot(
                sg->specular_glossiness, scene::kRoleColor, gpu::kWhiteTexture);
            x.specular_glossiness = glm::vec4(sg->specular_factor, sg->glossiness_factor);
        }
        extras_data_.push_back(x);
    }
    if (data_.empty()) { // keep the addresses valid for scenes without materials
        data_.push_back(scene::to_gpu_material(scene::MaterialInstance{}));
        extras_data_.push_back(GPUMaterialExtra{});
    }
}

void GpuMaterials::upload(const scene::Scene& scene) {
    build(scene.materials);
    const VkDeviceSize bytes = data_.size() * sizeof(scene::GPUMaterialData);
    const VkDeviceSize extra_bytes = extras_data_.size() * sizeof(GPUMaterialExtra);
    // Copied out too: the editor's material dock reads records back from this buffer.
    materials_ = resources_.create_buffer({bytes, kStorage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                           gpu::MemoryUsage::DeviceLocal, "materials"});
    extras_ = resources_.create_buffer(
        {extra_bytes, kStorage, gpu::MemoryUsage::DeviceLocal, "material uv"});
    gpu::UploadBatch batch(resources_);
    batch.upload_buffer(materials_, 0, data_.data(), bytes);
    batch.upload_buffer(extras_, 0, extras_data_.data(), extra_bytes);
    // Only where some material uses a drawn extension (the binding is partially bound).
    if (!extensions_.words.empty()) {
        // Copied out too: the material readback reads a material's blocks.
        extension_buffer_ = resources_.create_buffer(
            {extensions_.bytes(), kStorage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
             gpu::MemoryUsage::DeviceLocal, "material extensions"});
        batch.upload_buffer(extension_buffer_, 0, extensions_.words.data(), extensions_.bytes());
    }
    batch.submit_and_wait();
    bytes_ = bytes + extra_bytes;
}

namespace {

// Uploads the elements of `now` that differ from `before` (same length), runs of
// neighbours as one copy; returns the bytes.
template <class T>
std::uint64_t upload_changed(gpu::UploadBatch& batch, gpu::BufferHandle buffer,
                             const std::vector<T>& before, const std::vector<T>& now) {
    std::uint64_t bytes = 0;
    for (std::size_t i = 0; i < now.size();) {
        if (std::memcmp(&before[i], &now[i], sizeof(T)) == 0) {
            ++i;
            continue;
        }
        std::size_t end = i + 1;
        while (end < now.size() && std::memcmp(&before[end], &now[end], sizeof(T)) != 0) ++end;
        batch.upload_buffer(buffer, i * sizeof(T), &now[i], (end - i) * sizeof(T));
        bytes += (end - i) * sizeof(T);
        i = end;
    }
    return bytes;
}

} // namespace

std::uint64_t GpuMaterials::update(std::span<const scene::MaterialInstance> materials) {
    const std::vector<scene::GPUMaterialData> data = data_;
    const std::vector<GPUMaterialExtra> extras = extras_data_;
    const std::vector<glm::uvec4> words = extensions_.words;
    if (materials.empty() || materials.size() != data.size()) return 0;
    build(materials);
    // Which materials use an extension does not change with values: same layout.
    if (extensions_.words.size() != words.size())
        throw gpu::GpuError("material update: the extension layout changed");
    gpu::UploadBatch batch(resources_);
    std::uint64_t bytes = upload_changed(batch, materials_, data, data_);
    bytes += upload_changed(batch, extras_, extras, extras_data_);
    if (extension_buffer_.valid())
        bytes += upload_changed(batch, extension_buffer_, words, extensions_.words);
    if (bytes) batch.submit_and_wait();
    return bytes;
}

} // namespace sherpa::render
