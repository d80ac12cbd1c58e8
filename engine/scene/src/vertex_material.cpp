#include <sherpa/scene/material.h>
#include <sherpa/scene/scene.h>
#include <sherpa/scene/texture_records.h>
#include <sherpa/scene/vertex.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sherpa::scene {

std::string_view gltf_name(VertexAttribute a) {
    switch (a) {
    case VertexAttribute::Position:
        return "POSITION";
    case VertexAttribute::Normal:
        return "NORMAL";
    case VertexAttribute::Tangent:
        return "TANGENT";
    case VertexAttribute::TexCoord0:
        return "TEXCOORD_0";
    case VertexAttribute::TexCoord1:
        return "TEXCOORD_1";
    case VertexAttribute::Color0:
        return "COLOR_0";
    }
    return "?";
}

std::string_view to_string(Provenance p) {
    switch (p) {
    case Provenance::Authored:
        return "authored";
    case Provenance::Generated:
        return "generated";
    case Provenance::Defaulted:
        return "defaulted";
    }
    return "?";
}

std::uint32_t stream_stride(VertexAttribute a) {
    switch (a) {
    case VertexAttribute::Position:
    case VertexAttribute::Normal:
        return 12;
    case VertexAttribute::TexCoord0:
    case VertexAttribute::TexCoord1:
        return 8;
    case VertexAttribute::Tangent:
    case VertexAttribute::Color0:
        return 16;
    }
    return 0;
}

std::string_view to_string(AlphaMode m) {
    switch (m) {
    case AlphaMode::Opaque:
        return "OPAQUE";
    case AlphaMode::Mask:
        return "MASK";
    case AlphaMode::Blend:
        return "BLEND";
    }
    return "?";
}

std::string_view to_string(Topology t) {
    switch (t) {
    case Topology::Triangles:
        return "triangles";
    case Topology::Lines:
        return "lines";
    case Topology::Points:
        return "points";
    }
    return "?";
}

std::string_view to_string(PrimitiveMode m) {
    switch (m) {
    case PrimitiveMode::Points:
        return "POINTS";
    case PrimitiveMode::Lines:
        return "LINES";
    case PrimitiveMode::LineLoop:
        return "LINE_LOOP";
    case PrimitiveMode::LineStrip:
        return "LINE_STRIP";
    case PrimitiveMode::Triangles:
        return "TRIANGLES";
    case PrimitiveMode::TriangleStrip:
        return "TRIANGLE_STRIP";
    case PrimitiveMode::TriangleFan:
        return "TRIANGLE_FAN";
    }
    return "?";
}

glm::mat3 TextureTransform::matrix() const {
    // KHR_texture_transform: uv' = T * R * S * uv, rotation counter-clockwise.
    const float c = std::cos(rotation), s = std::sin(rotation);
    const glm::mat3 t(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    const glm::mat3 r(c, -s, 0, s, c, 0, 0, 0, 1);
    const glm::mat3 sc(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    return t * r * sc;
}

static std::uint32_t texture_field(const TextureSlot& slot) {
    return slot.present() ? static_cast<std::uint32_t>(slot.texture) : kTextureSentinel;
}

GPUMaterialData to_gpu_material(const MaterialInstance& m) {
    GPUMaterialData g{};
    g.base_color_factor = m.base_color_factor;
    g.emissive_factor = glm::vec4(m.emissive_factor, m.emissive_strength);
    g.metallic_factor = m.metallic_factor;
    g.roughness_factor = m.roughness_factor;
    g.normal_scale = m.normal_scale;
    g.occlusion_strength = m.occlusion_strength;
    g.base_color_tex = texture_field(m.base_color);
    g.emissive_tex = texture_field(m.emissive);
    g.metallic_roughness_tex = texture_field(m.metallic_roughness);
    g.normal_tex = texture_field(m.normal);
    g.occlusion_tex = texture_field(m.occlusion);
    g.alpha_cutoff = m.alpha_cutoff;
    g.alpha_mode = static_cast<std::uint32_t>(m.alpha_mode);
    g.double_sided = m.double_sided ? 1u : 0u;
    return g;
}

SamplerDesc sampler_from_gltf(int mag_filter, int min_filter, int wrap_s, int wrap_t) {
    SamplerDesc d;
    // tinygltf reports an absent filter as -1, the JSON default would be 0: both mean unspecified.
    mag_filter = std::max(mag_filter, 0);
    min_filter = std::max(min_filter, 0);
    switch (mag_filter) {
    case 0:
    case 9729:
        d.mag_filter = Filter::Linear;
        break;
    case 9728:
        d.mag_filter = Filter::Nearest;
        break;
    default:
        throw std::invalid_argument("magFilter " + std::to_string(mag_filter) + " is not valid");
    }
    switch (min_filter) {
    case 0: // unspecified: trilinear, as most viewers do
    case 9987:
        d.min_filter = Filter::Linear;
        d.mipmap_mode = MipmapMode::Linear;
        break;
    case 9728:
        d.min_filter = Filter::Nearest;
        d.max_lod = 0.0f;
        break;
    case 9729:
        d.min_filter = Filter::Linear;
        d.max_lod = 0.0f;
        break;
    case 9984:
        d.min_filter = Filter::Nearest;
        d.mipmap_mode = MipmapMode::Nearest;
        break;
    case 9985:
        d.min_filter = Filter::Linear;
        d.mipmap_mode = MipmapMode::Nearest;
        break;
    case 9986:
        d.min_filter = Filter::Nearest;
        d.mipmap_mode = MipmapMode::Linear;
        break;
    default:
        throw std::invalid_argument("minFilter " + std::to_string(min_filter) + " is not valid");
    }
    auto wrap = [](int w, const char* what) {
        switch (w) {
        case 0:
        case 10497:
            return AddressMode::Repeat;
        case 33648:
            return AddressMode::MirroredRepeat;
        case 33071:
            return AddressMode::ClampToEdge;
        default:
            throw std::invalid_argument(std::string(what) + " " + std::to_string(w) +
                                        " is not valid");
        }
    };
    d.wrap_u = wrap(wrap_s, "wrapS");
    d.wrap_v = wrap(wrap_t, "wrapT");
    return d;
}

} // namespace sherpa::scene
