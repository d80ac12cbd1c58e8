#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/upload.h>
#include <sherpa/render/gpu_structs.h>
#include <sherpa/render/scene_textures.h>

#include <sherpa/texture/block_codecs.h>

#include <algorithm>

namespace sherpa::render {

namespace {

VkSamplerCreateInfo sampler_info(const scene::SamplerDesc& d, const gpu::DeviceInfo& device) {
    auto filter = [](scene::Filter f) {
        return f == scene::Filter::Nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
    };
    auto address = [](scene::AddressMode m) {
        switch (m) {
        case scene::AddressMode::MirroredRepeat:
            return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
        case scene::AddressMode::ClampToEdge:
            return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        case scene::AddressMode::Repeat:
            break;
        }
        return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    };
    auto si = gpu::vk_init<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    si.magFilter = filter(d.mag_filter);
    si.minFilter = filter(d.min_filter);
    // Trilinear filtering doubles the texel fetches of every sample; on a CPU
    // rasterizer (lavapipe) that is the largest cost of a frame, so CPU devices
    // filter within the nearest mip level. GPUs get the sampler as glTF asks.
    si.mipmapMode = d.mipmap_mode == scene::MipmapMode::Nearest || device.is_cpu()
                        ? VK_SAMPLER_MIPMAP_MODE_NEAREST
                        : VK_SAMPLER_MIPMAP_MODE_LINEAR;
    si.addressModeU = address(d.wrap_u);
    si.addressModeV = address(d.wrap_v);
    si.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    si.maxLod = d.max_lod;
    // Anisotropy costs many texel fetches per sample on a CPU rasterizer; GPUs get 8x.
    if (device.anisotropy && !device.is_cpu() && d.max_lod > 0.0f &&
        d.min_filter == scene::Filter::Linear) {
        si.anisotropyEnable = VK_TRUE;
        si.maxAnisotropy = std::min(8.0f, device.max_anisotropy);
    }
    return si;
}

// A set prepared for another scene or device, or whose levels were released after an
// earlier upload, would create invalid images: refuse it.
void check_prepared(const tex::PreparedTexture& t, const scene::Scene& scene,
                    const gpu::DeviceInfo& device) {
    const std::string what =
        "prepared texture '" + t.source + "' (" + std::string(tex::role_name(t.role)) + ")";
    for (std::int32_t texture : t.textures)
        if (texture < 0 || std::size_t(texture) >= scene.textures.size())
            throw gpu::GpuError(what + " names glTF texture " + std::to_string(texture) + " of " +
                                std::to_string(scene.textures.size()) +
                                ": prepared for another scene?");
    if (tex::is_block_compressed(t.format) && !device.bc_textures)
        throw gpu::GpuError(what + " is " + std::string(tex::vk_format_name(t.format)) + " but " +
                            device.name + " cannot sample BC formats: prepare with its DeviceInfo");
    if (t.levels.empty() || t.width == 0 || t.height == 0)
        throw gpu::GpuError(what + " has no levels (released after an earlier upload?)");
    for (std::size_t l = 0; l < t.levels.size(); ++l) {
        const auto level = static_cast<std::uint32_t>(l);
        if (t.levels[l].size() != tex::level_size(t.format, tex::mip_extent(t.width, level),
                                                  tex::mip_extent(t.height, level)))
            throw gpu::GpuError(what + ": mip level " + std::to_string(l) + " has " +
                                std::to_string(t.levels[l].size()) +
                                " bytes, not what its size needs");
    }
}

} // namespace

std::string_view to_string(MissingTextures m) {
    return m == MissingTextures::Neutral ? "neutral" : "checker";
}

std::optional<MissingTextures> parse_missing_textures(std::string_view name) {
    if (name == "checker") return MissingTextures::Checker;
    if (name == "neutral") return MissingTextures::Neutral;
    return std::nullopt;
}

tex::TextureTarget texture_target(const gpu::DeviceInfo& device, const TextureSettings& settings) {
    return {device.bc_textures, device.is_cpu() && settings.decode_bc7_on_cpu, device.name};
}

tex::PipelineOptions texture_pipeline_options(const TextureSettings& settings) {
    tex::PipelineOptions o;
    o.cache_dir = settings.cache_dir;
    o.cache_cap_bytes = settings.cache_cap_bytes;
    o.bc7_level = settings.quality;
    o.device_supports_bc = !settings.force_rgba8;
    o.progress = settings.progress;
    o.cancel = settings.cancel;
    return o;
}

SceneTextures::SceneTextures(gpu::ResourceManager& resources, gpu::BindlessTable& table,
                             const scene::Scene& scene,
                             std::shared_ptr<const tex::PreparedTextureSet> prepared,
                             MissingTextures missing)
    : resources_(resources), table_(table), prepared_(std::move(prepared)), missing_(missing) {
    if (!prepared_) prepared_ = std::make_shared<const tex::PreparedTextureSet>();
    warnings_ = prepared_->warnings;
    try {
        upload(scene);
    } catch (...) {
        release();
        throw;
    }
}

void SceneTextures::upload(const scene::Scene& scene) {
    // Samplers: one per distinct description (glTF default included).
    std::vector<scene::SamplerDesc> descs;
    std::vector<std::uint32_t> sampler_of_texture(scene.textures.size());
    for (std::size_t t = 0; t < scene.textures.size(); ++t) {
        const scene::SamplerDesc d = scene.sampler_of(scene.textures[t]);
        auto it = std::find(descs.begin(), descs.end(), d);
        if (it == descs.end()) {
            descs.push_back(d);
            samplers_.push_back(
                resources_.images().create_sampler(sampler_info(d, resources_.context().info())));
            it = descs.end() - 1;
        }
        sampler_of_texture[t] = static_cast<std::uint32_t>(it - descs.begin());
    }
    auto sampler_for = [&](std::int32_t texture) {
        return resources_.images().get(samplers_[sampler_of_texture[std::size_t(texture)]]);
    };

    const std::vector<tex::PreparedTexture>& records = prepared_->textures;
    gpu_.resize(records.size());
    slots_.assign(records.size(), scene::kTextureSentinel);
    gpu::UploadBatch batch(resources_);
    for (std::size_t i = 0; i < records.size(); ++i) {
        const tex::PreparedTexture& t = records[i];
        if (t.failed || t.textures.empty()) continue; // the default texture stands in
        check_prepared(t, scene, resources_.context().info());
        gpu::ImageDesc d;
        d.format = static_cast<VkFormat>(t.format);
        d.width = t.width;
        d.height = t.height;
        d.mip_levels = static_cast<std::uint32_t>(t.levels.size());
        d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        d.name = "image " + std::to_string(t.image) + " (" + std::string(tex::role_name(t.role)) +
                 ", " + std::string(tex::vk_format_name(t.format)) + ")";
        GpuTexture& g = gpu_[i];
        g.image = resources_.images().create(d);
        g.mip_levels = d.mip_levels;
        g.bytes = resources_.images().get(g.image).allocation_size;
        bytes_ += g.bytes;
        batch.upload_image_levels(g.image, t.levels);
        const VkImageView view = resources_.images().get(g.image).view.get();
        const std::int32_t first = t.textures.front();
        g.slot = slots_[i] = table_.add(view, sampler_for(first));
        // A texture sharing this image with a different sampler gets its own slot.
        for (std::int32_t texture : t.textures)
            if (sampler_of_texture[std::size_t(texture)] != sampler_of_texture[std::size_t(first)])
                extra_slots_[{texture, t.role}] = table_.add(view, sampler_for(texture));
    }
    batch.submit_and_wait();
}

void SceneTextures::release() {
    for (std::uint32_t s : slots_)
        if (s != scene::kTextureSentinel) table_.remove(s);
    for (const auto& [key, s] : extra_slots_) table_.remove(s);
    for (GpuTexture& g : gpu_) resources_.images().destroy(g.image);
    for (gpu::SamplerHandle& h : samplers_) resources_.images().destroy(h);
    slots_.clear();
    extra_slots_.clear();
    gpu_.clear();
    samplers_.clear();
}

SceneTextures::~SceneTextures() {
    release();
}

std::size_t SceneTextures::image_count() const {
    return static_cast<std::size_t>(std::count_if(
        gpu_.begin(), gpu_.end(), [](const GpuTexture& g) { return g.image.valid(); }));
}

std::uint32_t SceneTextures::slot(std::int32_t texture, scene::TextureRole role) const {
    if (auto it = extra_slots_.find({texture, role}); it != extra_slots_.end()) return it->second;
    const std::int32_t i = prepared_->find(texture, role);
    return i < 0 || std::size_t(i) >= slots_.size() ? scene::kTextureSentinel
                                                    : slots_[std::size_t(i)];
}

std::uint32_t SceneTextures::field_slot(const scene::TextureSlot& s, scene::TextureRole role,
                                        std::uint32_t fallback) const {
    const std::int32_t i = s.present() ? prepared_->find(s.texture, role) : -1;
    const bool failed = i >= 0 && prepared_->textures[std::size_t(i)].failed;
    std::uint32_t value = i >= 0 && std::size_t(i) < slots_.size() && !failed
                              ? slots_[std::size_t(i)]
                              : scene::kTextureSentinel; // as tex::resolve_material
    if (s.present())
        if (auto it = extra_slots_.find({s.texture, role}); it != extra_slots_.end())
            value = it->second;
    if (value != scene::kTextureSentinel) return value;
    // A present slot whose texture failed draws the checker (colour slots) when asked.
    return role == scene::kRoleColor && missing_ == MissingTextures::Checker && failed
               ? gpu::kCheckerTexture
               : fallback;
}

scene::GPUMaterialData SceneTextures::material(const scene::MaterialInstance& m) const {
    scene::GPUMaterialData g = tex::resolve_material(m, *prepared_, slots_);
    auto field = [&](std::uint32_t& value, const scene::TextureSlot& s, scene::TextureRole role,
                     std::uint32_t fallback) { value = field_slot(s, role, fallback); };
    // Emissive without a texture is the factor alone (glTF): white when it emits.
    const bool emits = glm::any(glm::greaterThan(m.emissive_factor, glm::vec3(0.0f)));
    field(g.base_color_tex, m.base_color, scene::kRoleColor, gpu::kWhiteTexture);
    field(g.emissive_tex, m.emissive, scene::kRoleColor,
          emits ? gpu::kWhiteTexture : gpu::kBlackTexture);
    field(g.metallic_roughness_tex, m.metallic_roughness, scene::kRoleLinear, gpu::kWhiteTexture);
    field(g.occlusion_tex, m.occlusion, scene::kRoleLinear, gpu::kWhiteTexture);
    field(g.normal_tex, m.normal, scene::kRoleNormal, gpu::kFlatNormalTexture);
    return g;
}

} // namespace sherpa::render
