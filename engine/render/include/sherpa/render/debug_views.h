#pragma once
// The debug views and overlays, once: the enums, and one table row per entry with
// its stable name (sherpa-cli --view/--overlay, editor settings), the vertex streams
// it reads whatever the materials use, and an English label the editor translates.
// Everything else derives from these tables: the CLI's parser and usage text, the
// editor's View menu, and the shaders' VIEW_* / OVERLAY_* constants, which
// tools/glsl_constants writes into a generated GLSL header at build time.
//
// Header-only and free of Vulkan, so that host tool can include it.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include <sherpa/scene/vertex.h>

// Marks a label for translation without Qt (the engine has none): lupdate is told
// to read it as QT_TRANSLATE_NOOP (editor/CMakeLists.txt, -tr-function-alias), and
// the editor passes the label through QCoreApplication::translate(kViewLabelContext).
#define SHERPA_TRANSLATE_NOOP(context, text) text

namespace sherpa::render {

// Values are the VIEW_* constants of the generated shader header (the forward
// shader's specialization constant), so they are part of the pipeline cache key.
enum class DebugView : std::uint32_t {
    Lit = 0,
    Normal = 1,    // interpolated vertex normal (world)
    Tangent = 2,   // world tangent xyz
    Bitangent = 3, // cross(N, T) * w
    TangentW = 4,  // handedness: green +1, red -1, yellow 0
    Uv0 = 5,
    Uv1 = 6,
    Uv0Checker = 7,
    Uv1Checker = 8,
    BaseColor = 9,
    Metallic = 10,
    Roughness = 11,
    Occlusion = 12,
    Emissive = 13,
    GeometricVsShading = 14, // angle between face normal and normal-mapped shading normal
    Provenance = 15,         // tangent provenance: green authored, yellow generated, red defaulted
    ShadingNormal = 16,      // normal after normal mapping (world)
    Specular = 17,           // F0: specular-glossiness' specular, else mix(0.04, base, metallic)
    JointInfluence = 18,     // weight of FrameRequest::selected_joint, as a heat map
    // Visibility of the sun (1 lit, 0 shadowed, greys between): the cascaded shadow maps
    // in the rasterizer, shadow rays in the ray tracer (docs/raytracing/README.md).
    Shadow = 19,
    AmbientOcclusion = 20, // rays only: unoccluded fraction of a cosine-weighted hemisphere
    // Rays only: where the cascaded shadow maps disagree with shadow rays, in the
    // kShadowError* colours below.
    ShadowError = 21,
    // KHR_materials_ior: grey (ior - 1) / 2, ior 0 (F0 = 1) in kSpecGlossFlagColor.
    Ior = 22,
    // KHR_materials_specular: the specular weight (factor x texture alpha) and the F0
    // colour (factor x texture rgb, linear radiance like base colour).
    SpecularWeight = 23,
    SpecularColor = 24,
    // The transmission family: KHR_materials_transmission's factor (grey), the volume's
    // thickness (grey, local units, clipped at 1), its attenuation colour (white: none),
    // KHR_materials_diffuse_transmission's factor (grey).
    Transmission = 25,
    Thickness = 26,
    Attenuation = 27,
    DiffuseTransmission = 28,
    // KHR_materials_clearcoat: the coat's weight and roughness (greys; 0 without the
    // extension) and its normal (encoded as the normal view; the geometry's normal
    // where the coat has no normal map of its own).
    Clearcoat = 29,
    ClearcoatRoughness = 30,
    ClearcoatNormal = 31,
    // KHR_materials_sheen: the sheen colour (linear radiance like base colour; black
    // without the extension) and roughness (grey).
    SheenColor = 32,
    SheenRoughness = 33,
    // KHR_materials_anisotropy: the strength (grey; 0 without the extension) and the
    // direction in the world, along the normal-mapped tangent frame (encoded as the
    // normal view; black without the extension).
    AnisotropyStrength = 34,
    AnisotropyDirection = 35,
    // KHR_materials_iridescence: the factor (grey) and the film's thickness in
    // micrometres (grey, clipped at 1); 0 without the extension.
    IridescenceFactor = 36,
    IridescenceThickness = 37,
};

// The metallic view's colour on specular-glossiness materials (no metallic value
// there): not a grey, so no metallic value reads as it. GLSL: SPEC_GLOSS_FLAG
// (generated with the VIEW_* constants). Linear data, stored as the 8-bit value.
inline constexpr std::array<float, 3> kSpecGlossFlagColor{0.0f, 0.5f, 1.0f};

// The shadow-error view's classes (linear data, stored as 8-bit values; exact in 8
// bits, so a pixel's class is read back from its bytes: gpu::classify_shadow_error).
// GLSL: SHADOW_AGREE_LIT etc. (generated with the VIEW_* constants).
inline constexpr std::array<float, 3> kShadowAgreeLitColor{0.8f, 0.8f, 0.8f};
inline constexpr std::array<float, 3> kShadowAgreeShadowedColor{0.2f, 0.2f, 0.2f};
// The maps shadow a point the rays find lit / light a point the rays find shadowed.
inline constexpr std::array<float, 3> kShadowFalseShadowColor{1.0f, 0.0f, 0.0f};
inline constexpr std::array<float, 3> kShadowFalseLightColor{0.0f, 0.0f, 1.0f};

// The bytes a data view stores for a class colour (values, not sRGB-encoded): what
// the shadow-error counts and the CLI's legends compare and draw.
inline std::array<std::uint8_t, 3> stored_bytes(const std::array<float, 3>& c) {
    std::array<std::uint8_t, 3> b{};
    for (int i = 0; i < 3; ++i) b[i] = static_cast<std::uint8_t>(c[i] * 255.0f + 0.5f);
    return b;
}

// The provenance view's colours (linear data, stored as 8-bit values), indexed by the
// two provenance bits the shaders read (render/gpu_scene.cpp provenance_bits()):
// authored green, generated yellow, defaulted red. GLSL: PROVENANCE_COLORS.
inline constexpr std::array<std::array<float, 3>, 3> kProvenanceColors{
    {{0.15f, 0.75f, 0.2f}, {0.95f, 0.8f, 0.1f}, {0.9f, 0.15f, 0.1f}}};
inline constexpr std::array<const char*, 3> kProvenanceNames{"authored", "generated", "defaulted"};

enum Overlay : std::uint32_t {
    kOverlayWireframe = 1u << 0,
    kOverlayNormals = 1u << 1,
    kOverlayTangents = 1u << 2,
    kOverlayBitangents = 1u << 3,
    kOverlayBounds = 1u << 4,
    // Instance boxes coloured by the camera cull: green visible, red culled, yellow
    // kept by the conservative test although the exact test rejects it. With a
    // frozen culling camera its frustum is drawn too.
    kOverlayCullBoxes = 1u << 5,
    // Joints and bones of every skin as lines (world positions from the frame's pose, else
    // the scene as loaded), the selected joint (FrameRequest::selected_joint) highlighted.
    kOverlaySkeleton = 1u << 6,
};

// Bit (1 << VertexAttribute) per vertex stream.
constexpr std::uint32_t stream_bit(scene::VertexAttribute a) {
    return 1u << static_cast<std::uint32_t>(a);
}
inline constexpr std::uint32_t kNormalStream = stream_bit(scene::VertexAttribute::Normal);
inline constexpr std::uint32_t kTangentStream = stream_bit(scene::VertexAttribute::Tangent);
inline constexpr std::uint32_t kUv0Stream = stream_bit(scene::VertexAttribute::TexCoord0);
inline constexpr std::uint32_t kUv1Stream = stream_bit(scene::VertexAttribute::TexCoord1);

// The context the editor translates labels in (the editor's former ViewCatalog,
// whose translations the .ts files hold).
inline constexpr const char* kViewLabelContext = "ViewCatalog";

struct DebugViewInfo {
    DebugView id;
    std::string_view name; // stable: command line, settings; VIEW_<NAME> in GLSL
    // Streams the view reads even where no material does (the scene is then uploaded
    // with StreamPolicy::AllPresent); 0: only what the materials read.
    std::uint32_t streams;
    const char* label; // English; translated in kViewLabelContext
};

struct OverlayEntry {
    Overlay bit;
    std::string_view name; // stable: command line; OVERLAY_<NAME> in GLSL
    std::uint32_t streams; // as DebugViewInfo::streams
    // English, translated in kViewLabelContext; null: not in the editor's Overlays
    // menu (cull-boxes is switched by its Culling menu).
    const char* label;
};

inline constexpr std::array<DebugViewInfo, 38> kDebugViews{{
    {DebugView::Lit, "lit", 0, SHERPA_TRANSLATE_NOOP("ViewCatalog", "Lit")},
    {DebugView::Normal, "normal", kNormalStream, SHERPA_TRANSLATE_NOOP("ViewCatalog", "Normals")},
    {DebugView::Tangent, "tangent", kTangentStream,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Tangents")},
    {DebugView::Bitangent, "bitangent", kNormalStream | kTangentStream,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Bitangents")},
    {DebugView::TangentW, "tangent-w", kTangentStream,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Handedness (tangent w)")},
    {DebugView::Uv0, "uv0", kUv0Stream, SHERPA_TRANSLATE_NOOP("ViewCatalog", "UV 0")},
    {DebugView::Uv1, "uv1", kUv1Stream, SHERPA_TRANSLATE_NOOP("ViewCatalog", "UV 1")},
    {DebugView::Uv0Checker, "uv0-checker", kUv0Stream,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "UV 0 checker")},
    {DebugView::Uv1Checker, "uv1-checker", kUv1Stream,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "UV 1 checker")},
    {DebugView::BaseColor, "base-color", 0, SHERPA_TRANSLATE_NOOP("ViewCatalog", "Base colour")},
    {DebugView::Metallic, "metallic", 0, SHERPA_TRANSLATE_NOOP("ViewCatalog", "Metallic")},
    {DebugView::Roughness, "roughness", 0, SHERPA_TRANSLATE_NOOP("ViewCatalog", "Roughness")},
    {DebugView::Occlusion, "occlusion", 0, SHERPA_TRANSLATE_NOOP("ViewCatalog", "Occlusion")},
    {DebugView::Emissive, "emissive", 0, SHERPA_TRANSLATE_NOOP("ViewCatalog", "Emissive")},
    {DebugView::GeometricVsShading, "geometric-vs-shading", kNormalStream | kTangentStream,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Geometric vs shading normal")},
    {DebugView::Provenance, "provenance", 0,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Tangent provenance")},
    {DebugView::ShadingNormal, "shading-normal", kNormalStream | kTangentStream,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Shading normal")},
    {DebugView::Specular, "specular", 0, SHERPA_TRANSLATE_NOOP("ViewCatalog", "Specular (F0)")},
    {DebugView::JointInfluence, "joint-influence", 0,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Joint influence")},
    {DebugView::Shadow, "shadow", kNormalStream,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Sun shadow")},
    {DebugView::AmbientOcclusion, "ao", 0,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Ambient occlusion (rays)")},
    {DebugView::ShadowError, "shadow-error", kNormalStream,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Shadow error (maps vs rays)")},
    {DebugView::Ior, "ior", 0, SHERPA_TRANSLATE_NOOP("ViewCatalog", "Index of refraction")},
    {DebugView::SpecularWeight, "specular-weight", 0,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Specular weight")},
    {DebugView::SpecularColor, "specular-color", 0,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Specular colour")},
    {DebugView::Transmission, "transmission", 0,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Transmission")},
    {DebugView::Thickness, "thickness", 0,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Volume thickness")},
    {DebugView::Attenuation, "attenuation", 0,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Volume attenuation")},
    {DebugView::DiffuseTransmission, "diffuse-transmission", 0,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Diffuse transmission")},
    {DebugView::Clearcoat, "clearcoat", 0, SHERPA_TRANSLATE_NOOP("ViewCatalog", "Clearcoat")},
    {DebugView::ClearcoatRoughness, "clearcoat-roughness", 0,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Clearcoat roughness")},
    {DebugView::ClearcoatNormal, "clearcoat-normal", kNormalStream | kTangentStream,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Clearcoat normal")},
    {DebugView::SheenColor, "sheen-color", 0, SHERPA_TRANSLATE_NOOP("ViewCatalog", "Sheen colour")},
    {DebugView::SheenRoughness, "sheen-roughness", 0,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Sheen roughness")},
    {DebugView::AnisotropyStrength, "anisotropy-strength", 0,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Anisotropy strength")},
    {DebugView::AnisotropyDirection, "anisotropy-direction", kNormalStream | kTangentStream,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Anisotropy direction")},
    {DebugView::IridescenceFactor, "iridescence", 0,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Iridescence")},
    {DebugView::IridescenceThickness, "iridescence-thickness", 0,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Iridescence thickness")},
}};

inline constexpr std::array<OverlayEntry, 7> kOverlays{{
    {kOverlayWireframe, "wireframe", 0, SHERPA_TRANSLATE_NOOP("ViewCatalog", "Wireframe")},
    {kOverlayNormals, "normals", kNormalStream,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Normal glyphs")},
    {kOverlayTangents, "tangents", kTangentStream,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Tangent glyphs")},
    {kOverlayBitangents, "bitangents", kNormalStream | kTangentStream,
     SHERPA_TRANSLATE_NOOP("ViewCatalog", "Bitangent glyphs")},
    {kOverlayBounds, "aabb", 0, SHERPA_TRANSLATE_NOOP("ViewCatalog", "Bounding boxes")},
    {kOverlayCullBoxes, "cull-boxes", 0, nullptr},
    {kOverlaySkeleton, "skeleton", 0, SHERPA_TRANSLATE_NOOP("ViewCatalog", "Skeleton")},
}};

// The table is indexed by id (checked below).
constexpr bool views_indexed_by_id() {
    for (std::size_t i = 0; i < kDebugViews.size(); ++i)
        if (static_cast<std::size_t>(kDebugViews[i].id) != i) return false;
    return true;
}
static_assert(views_indexed_by_id(), "kDebugViews must list the views in id order");

// Whether the rasterizer draws `v`: every view but those only rays can compute (the
// ray tracer's list is frame_request.h's ray_traced_view).
constexpr bool raster_view(DebugView v) {
    return v != DebugView::AmbientOcclusion && v != DebugView::ShadowError;
}

constexpr std::optional<DebugView> find_debug_view(std::string_view name) {
    for (const DebugViewInfo& v : kDebugViews)
        if (v.name == name) return v.id;
    return std::nullopt;
}
constexpr std::optional<Overlay> find_overlay(std::string_view name) {
    for (const OverlayEntry& o : kOverlays)
        if (o.name == name) return o.bit;
    return std::nullopt;
}

} // namespace sherpa::render
