#pragma once
// The boundary to OpenImageIO. OpenImageIO's closure is about 250 shared libraries
// (GDAL, OpenCV, ffmpeg, poppler, libheif ...): linked into the engine, every process
// that uses the texture layer paid ~0.2 s to load and relocate them, even one that
// decodes no image. PNG and JPEG are decoded in process (png_codec.cpp,
// jpeg_decode.cpp); every other format goes through this plugin, a shared module
// (libsherpa_oiio.so) that oiio_loader.cpp dlopen()s on first use.
//
// The module is built by the same project with the same compiler and standard
// library, so the table passes C++ types; `abi` guards against a stale module.
#include <sherpa/texture/image.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace sherpa::tex::oiio {

inline constexpr std::uint32_t kPluginAbi = 2;

// Called with the header's size before the pixels are allocated: false (with `error`
// set) refuses the image. The engine's limit lives on the engine's side.
using SizeCheck = bool (*)(std::uint32_t width, std::uint32_t height, std::string_view name,
                           std::string& error);

struct PluginApi {
    std::uint32_t abi = kPluginAbi;
    // As decode_encoded_image(): unassociated alpha, RGBA8.
    bool (*decode)(std::span<const std::uint8_t> bytes, std::string_view name_hint, SizeCheck check,
                   RgbaImage& out, std::string& error) = nullptr;
    // As probe_encoded_image(); width/height are always written.
    bool (*probe)(std::span<const std::uint8_t> bytes, std::string_view name_hint,
                  std::string& error, std::uint32_t& width, std::uint32_t& height) = nullptr;
    bool (*read_file)(const std::filesystem::path& path, SizeCheck check, RgbaImage& out,
                      std::string& error) = nullptr;
    // As read_float_image_file(): float RGB; over `max_side` a side is refused before
    // the pixels are allocated.
    bool (*read_float_file)(const std::filesystem::path& path, std::uint32_t max_side,
                            FloatRgbImage& out, std::string& error) = nullptr;
    // Format from the extension; pixels stored unassociated.
    bool (*write_file)(const std::filesystem::path& path, const RgbaImage& image,
                       std::string& error) = nullptr;
};

// The module's one exported symbol.
inline constexpr const char* kEntryPoint = "sherpa_oiio_plugin_api";
using EntryPoint = const PluginApi* (*)();

// The plugin's table, loaded on the first call (thread-safe); nullptr with `error`
// set (the paths tried and dlerror()) when the module cannot be loaded.
const PluginApi* plugin(std::string& error);

// True once the module is loaded in this process (tests and reports).
bool plugin_loaded();

} // namespace sherpa::tex::oiio
