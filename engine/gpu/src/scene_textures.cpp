#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/gpu_structs.h>
#include <sherpa/gpu/scene_textures.h>
#include <sherpa/gpu/upload.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <bit>
#include <cmath>

namespace sherpa::gpu {

bool decode_rgba8(const ImageRecord& image, std::vector<std::uint8_t>& rgba, std::uint32_t& width,
                  std::uint32_t& height, std::string& error) {
    if (!image.pixels.empty()) {
        if (image.pixels.size() != std::size_t(image.width) * image.height * 4) {
            error = "generated pixels do not match " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + " RGBA8";
            return false;
        }
        rgba = image.pixels;
        width = image.width;
        height = image.height;
        return true;
    }
    if (image.encoded.empty()) {
        error = "no image data";
        return false;
    }
    // OIIO picks the reader by file extension; the proxy supplies the bytes.
    const bool jpeg =
        image.mime_type == "image/jpeg" ||
        (image.encoded.size() > 2 && image.encoded[0] == 0xFF && image.encoded[1] == 0xD8);
    OIIO::Filesystem::IOMemReader reader(const_cast<std::uint8_t*>(image.encoded.data()),
                                         image.encoded.size());
    auto in = OIIO::ImageInput::open(jpeg ? "image.jpg" : "image.png", nullptr, &reader);
    if (!in) {
        error = "cannot decode: " + OIIO::geterror();
        return false;
    }
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    if (spec.width <= 0 || spec.height <= 0 || channels < 1) {
        error = "image has no pixels";
        return false;
    }
    width = static_cast<std::uint32_t>(spec.width);
    height = static_cast<std::uint32_t>(spec.height);
    std::vector<std::uint8_t> raw(std::size_t(width) * height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, raw.data())) {
        error = "cannot decode: " + in->geterror();
        return false;
    }
    rgba.resize(std::size_t(width) * height * 4);
    const std::size_t n = std::size_t(width) * height;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t* s = &raw[i * channels];
        std::uint8_t* d = &rgba[i * 4];
        if (channels >= 3) {
            d[0] = s[0], d[1] = s[1], d[2] = s[2];
            d[3] = channels >= 4 ? s[3] : 255;
        } else { // grey or grey + alpha
            d[0] = d[1] = d[2] = s[0];
            d[3] = channels == 2 ? s[1] : 255;
        }
    }
    return true;
}

namespace {

VkSamplerCreateInfo sampler_info(const SamplerDesc& d, const DeviceInfo& device) {
    auto filter = [](Filter f) {
        return f == Filter::Nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
    };
    auto address = [](AddressMode m) {
        switch (m) {
        case AddressMode::MirroredRepeat:
            return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
        case AddressMode::ClampToEdge:
            return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        case AddressMode::Repeat:
            break;
        }
        return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    };
    auto si = vk_init<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
    si.magFilter = filter(d.mag_filter);
    si.minFilter = filter(d.min_filter);
    // Trilinear filtering doubles the texel fetches of every sample; on a CPU
    // rasterizer (lavapipe) that is the largest cost of a frame, so CPU devices
    // filter within the nearest mip level. GPUs get the sampler as glTF asks.
    si.mipmapMode = d.mipmap_mode == MipmapMode::Nearest || device.is_cpu()
                        ? VK_SAMPLER_MIPMAP_MODE_NEAREST
                        : VK_SAMPLER_MIPMAP_MODE_LINEAR;
    si.addressModeU = address(d.wrap_u);
    si.addressModeV = address(d.wrap_v);
    si.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    si.maxLod = d.max_lod;
    // Anisotropy costs many texel fetches per sample on a CPU rasterizer; GPUs get 8x.
    if (device.anisotropy && !device.is_cpu() && d.max_lod > 0.0f &&
        d.min_filter == Filter::Linear) {
        si.anisotropyEnable = VK_TRUE;
        si.maxAnisotropy = std::min(8.0f, device.max_anisotropy);
    }
    return si;
}

} // namespace

SceneTextures::SceneTextures(ResourceManager& resources, BindlessTable& table, const Scene& scene)
    : resources_(resources), table_(table) {
    // Samplers: one per distinct description (glTF default included).
    std::vector<SamplerDesc> descs;
    std::vector<std::uint32_t> sampler_of_texture(scene.textures.size());
    for (std::size_t t = 0; t < scene.textures.size(); ++t) {
        const SamplerDesc d = scene.sampler_of(scene.textures[t]);
        auto it = std::find(descs.begin(), descs.end(), d);
        if (it == descs.end()) {
            descs.push_back(d);
            samplers_.push_back(
                resources_.create_sampler(sampler_info(d, resources_.context().info())));
            it = descs.end() - 1;
        }
        sampler_of_texture[t] = static_cast<std::uint32_t>(it - descs.begin());
    }

    // Which (texture, colour space) pairs materials need.
    struct Job {
        std::int32_t texture;
        bool srgb;
        std::vector<std::uint8_t> rgba;
        std::uint32_t width = 0, height = 0;
        std::string error;
    };
    std::vector<Job> jobs;
    auto want = [&](const TextureSlot& s, bool srgb) {
        if (!s.present() || s.texture >= static_cast<std::int32_t>(scene.textures.size())) return;
        for (const Job& j : jobs)
            if (j.texture == s.texture && j.srgb == srgb) return;
        jobs.push_back({s.texture, srgb, {}, 0, 0, {}});
    };
    for (const MaterialInstance& m : scene.materials) {
        want(m.base_color, true);
        want(m.emissive, true);
        want(m.metallic_roughness, false);
        want(m.occlusion, false);
        want(m.normal, false);
    }

    // Decoding dominates load time; images are independent.
#pragma omp parallel for schedule(dynamic)
    for (std::size_t i = 0; i < jobs.size(); ++i) {
        Job& j = jobs[i];
        const std::int32_t image = scene.textures[j.texture].image;
        if (image < 0 || image >= static_cast<std::int32_t>(scene.images.size())) {
            j.error = "texture " + std::to_string(j.texture) + " has no image";
            continue;
        }
        if (!decode_rgba8(scene.images[image], j.rgba, j.width, j.height, j.error))
            j.error = "image " + std::to_string(image) + " ('" + scene.images[image].name +
                      "'): " + j.error;
    }

    UploadBatch batch(resources_);
    for (Job& j : jobs) {
        if (!j.error.empty()) {
            warnings_.push_back(j.error + "; the default texture stands in");
            continue;
        }
        ImageDesc d;
        d.format = j.srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
        d.width = j.width;
        d.height = j.height;
        d.mip_levels = static_cast<std::uint32_t>(std::bit_width(std::max(j.width, j.height)));
        d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                  VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        d.name = "texture " + std::to_string(j.texture) + (j.srgb ? " (sRGB)" : "");
        ImageHandle h = resources_.create_image(d);
        images_.push_back(h);
        bytes_ += resources_.get(h).allocation_size;
        batch.upload_image(h, j.rgba.data(), j.rgba.size());
        const std::uint32_t s = table_.add(
            resources_.get(h).view.get(), resources_.get(samplers_[sampler_of_texture[j.texture]]));
        slots_.push_back(s);
        slot_of_[{j.texture, j.srgb}] = s;
        std::vector<std::uint8_t>().swap(j.rgba); // staged copy made; free the decode early
    }
    batch.submit_and_wait();
}

SceneTextures::~SceneTextures() {
    for (std::uint32_t s : slots_) table_.remove(s);
    for (ImageHandle& h : images_) resources_.destroy(h);
    for (SamplerHandle& h : samplers_) resources_.destroy(h);
}

std::uint32_t SceneTextures::slot(std::int32_t texture, bool srgb, std::uint32_t fallback) const {
    auto it = slot_of_.find({texture, srgb});
    return it == slot_of_.end() ? fallback : it->second;
}

} // namespace sherpa::gpu
