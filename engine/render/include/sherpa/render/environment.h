#pragma once
// Image-based lighting: the radiance an environment sends from every direction, as an
// equirectangular image (docs/environment.md), and the settings that show it.
//
// Convention (three.js's EquirectangularReflectionMapping, +Y up): a world direction
// d = (x, y, z) reads the image at u = atan2(z, x) / 2pi + 0.5 (columns, left to right)
// and v = asin(y) / pi + 0.5 (0 at the bottom row, 1 at the top row): the image's
// centre column looks along +X, its left and right edges along -X, its top row is +Y.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace sherpa::render {

// Linear RGB radiance, RGBA float texels, top row first.
struct EnvironmentImage {
    std::uint32_t width = 0, height = 0;
    std::vector<float> rgba; // width * height * 4
    std::string name;        // "room", a file name, ...
    bool valid() const {
        return width > 0 && height > 0 && rgba.size() == std::size_t{width} * height * 4;
    }
};

// The largest equirectangular image read (texels per side): 16384 x 8192 is 2 GiB of
// float texels; larger files are refused (documented limit).
inline constexpr std::uint32_t kMaxEnvironmentSide = 16384;

// The built-in studio ("room"): a grey room lit by a large soft key light, a fill
// and a rim strip, made from code so that nothing has to be installed. width x width/2.
EnvironmentImage room_environment(std::uint32_t width = 1024);
// The same radiance from every direction (the furnace test's environment).
EnvironmentImage uniform_environment(glm::vec3 radiance, std::uint32_t width = 64);

// An equirectangular .hdr or .exr (anything OpenImageIO reads, through the texture layer's plugin),
// alpha not premultiplied. On any problem the warnings name the file and what is wrong: unreadable
// or corrupt files and 0-size images fall back to the room (`fallback` true); NaN and infinite
// texels are read as 0 (black) and counted; radiance above the half-float range is clamped to it
// (the GPU keeps it in half floats).
struct EnvironmentLoad {
    EnvironmentImage image;
    std::vector<std::string> warnings;
    bool fallback = false; // the file could not be used: `image` is the room
};
EnvironmentLoad load_environment(const std::string& path);

// What --environment names: the room, nothing, or a file.
struct EnvironmentChoice {
    enum class Kind { None, Room, File } kind = Kind::Room;
    std::string path; // Kind::File
};
EnvironmentChoice parse_environment_choice(std::string_view text); // "room", "none", else a file
// The image of a choice (none: nullopt); warnings as load_environment's.
std::optional<EnvironmentImage> make_environment(const EnvironmentChoice& choice,
                                                 std::vector<std::string>& warnings);

// The equirectangular EXRs Blender's data package installs (CC0), sorted; empty when
// it is not installed.
std::vector<std::string> installed_studio_lights();
inline constexpr const char* kStudioLightsDir = "/usr/share/blender/datafiles/studiolights/world";

// What is drawn where no surface is.
enum class Background : std::uint32_t {
    Environment, // the environment itself
    Blurred,     // the environment prefiltered at roughness kBlurredBackgroundRoughness
    Color,       // FrameRequest::clear_color
};
inline constexpr float kBlurredBackgroundRoughness = 0.5f;
std::string_view to_string(Background b);
// "environment", "blurred" or "R,G,B" (linear, 0..1): the colour into `color`.
std::optional<Background> parse_background(std::string_view text, glm::vec3& color);

// Display transform of the lit view: exposure, then one of these curves, then sRGB.
enum class ToneMap : std::uint32_t {
    Neutral, // Khronos PBR Neutral
    Aces,    // three.js ACESFilmicToneMapping (Hill's RRT+ODT fit, exposure / 0.6)
    Agx,     // three.js AgXToneMapping (Blender AgX, sRGB primaries via Rec.2020)
    Linear,  // clamp only
};
std::string_view to_string(ToneMap t);
std::optional<ToneMap> parse_tone_map(std::string_view name);
std::vector<std::string_view> tone_map_names();

// KHR_materials_anisotropy's environment specular (docs/materials.md): the isotropic
// split-sum read along a bent normal (three.js's and the Khronos Sample Viewer's form),
// the anisotropic lobe's own albedo (its split-sum table) with that read, or that albedo
// with four reads spread along the anisotropy direction.
enum class AnisotropyLighting : std::uint32_t { Isotropic, Albedo, Lobe };
std::string_view to_string(AnisotropyLighting a);
std::optional<AnisotropyLighting> parse_anisotropy_lighting(std::string_view name);

// How the diffuse light of an environment is kept: the Lambert-prefiltered irradiance
// cube, or 9 spherical-harmonic coefficients (environment_sh.h) evaluated per pixel,
// which make no cube and no prefilter pass.
enum class IrradianceMode : std::uint32_t { Cube, Sh9 };
std::string_view to_string(IrradianceMode m);
std::optional<IrradianceMode> parse_irradiance_mode(std::string_view name); // "cube", "sh9"

// How an environment is made (Renderer::set_environment): the defaults are what every
// view draws; the Lab's lighting family varies them. SH9 is the default irradiance: as
// close to the path tracer as the cube (docs/lab/README.md), without the cube's pass
// and its texture fetch per pixel (docs/environment.md "Speed").
struct EnvironmentOptions {
    IrradianceMode irradiance = IrradianceMode::Sh9;
    // Face of the specular cube (a power of two, 16 to 512); 0: a quarter of the
    // source's width within those bounds.
    std::uint32_t specular_size = 0;
    // GGX importance samples per texel of every blurred specular level; 0: 16 at the
    // first blurred level and 32 after (EnvironmentMap::kSpecularSamples*).
    std::uint32_t specular_samples = 0;
};

// Sizes of the maps made from an environment (environment_map.cpp).
struct EnvironmentStats {
    bool present = false;
    std::string name;
    std::uint32_t source_width = 0, source_height = 0;
    std::uint32_t cube_size = 0, specular_levels = 0, irradiance_size = 0, sheen_size = 0,
                  sheen_levels = 0, lut_size = 0;
    IrradianceMode irradiance = IrradianceMode::Cube; // Sh9: irradiance_size is 0
    std::uint64_t bytes = 0;                          // kept on the GPU (cubes and lookup tables)
    double prefilter_ms = 0.0;                        // upload and every compute pass, wall clock
    double gpu_ms = 0.0;                              // the compute passes by GPU timestamps
    // GPU ms of: the radiance cube (and its levels), GGX specular, Lambert irradiance,
    // Charlie sheen, the lookup table.
    double pass_ms[5] = {};
    std::uint64_t nonfinite = 0; // texels read as 0
    // KHR_materials_anisotropy's table (in `bytes` too; 0 unless the scene has an
    // anisotropic material) and its pass's GPU ms.
    std::uint64_t anisotropy_lut_bytes = 0;
    double anisotropy_lut_gpu_ms = 0.0;
};

} // namespace sherpa::render
