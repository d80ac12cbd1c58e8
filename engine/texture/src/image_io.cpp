// Decoding of encoded sources into RGBA8, and the PNG reading and writing of rendered
// frames: the engine's one image I/O module. PNG and JPEG are decoded in process
// (png_codec.cpp, jpeg_decode.cpp); every other format, and the rare JPEG variants
// those leave aside, through OpenImageIO, loaded as a plugin on first use
// (oiio/oiio_plugin_api.h says why).
#include "image_codecs.h"
#include "oiio/oiio_plugin_api.h"

#include <sherpa/core/file_io.h>
#include <sherpa/texture/image.h>
#include <sherpa/texture/texel_budget.h>

#include <algorithm>
#include <cctype>
#include <new>

namespace sherpa::tex {

bool RgbaImage::has_alpha() const {
    for (std::size_t i = 3; i < pixels.size(); i += 4)
        if (pixels[i] != 255) return true;
    return false;
}

// Every decoder calls this with the header's size before it allocates pixels: no
// pixels, or more than the texel budget (texel_budget.h), are refused by name.
bool decoded_size_ok(std::uint32_t width, std::uint32_t height, std::string_view name,
                     std::string& error) {
    if (width == 0 || height == 0) {
        error = std::string(name) + ": image has no pixels";
        return false;
    }
    return check_texel_budget(width, height, name, error);
}

namespace {

bool size_check(std::uint32_t width, std::uint32_t height, std::string_view name,
                std::string& error) {
    return decoded_size_ok(width, height, name, error);
}

const oiio::PluginApi* image_plugin(std::string_view name, std::string& error) {
    std::string why;
    const oiio::PluginApi* api = oiio::plugin(why);
    if (!api) error = std::string(name) + ": cannot decode: " + why;
    return api;
}

// Decodes in process when a decoder here reads the bytes; `handled` false leaves the
// image to OpenImageIO.
bool decode_in_process(std::span<const std::uint8_t> bytes, std::string_view name, RgbaImage& out,
                       std::string& error, bool& handled) {
    CodecResult r = CodecResult::Unsupported;
    if (is_png(bytes))
        r = decode_png(bytes, name, out, error);
    else if (is_jpeg(bytes))
        r = decode_jpeg(bytes, name, out, error);
    handled = r != CodecResult::Unsupported;
    return r == CodecResult::Ok;
}

// PNG, JPEG and WebP sizes read from their headers before any decoder sees them: some
// decoders allocate the declared size as soon as they are opened.
bool declared_size_ok(std::span<const std::uint8_t> bytes, std::string_view name,
                      std::string& error) {
    const auto declared = declared_image_size(bytes);
    return !declared || check_texel_budget(declared->width, declared->height, name, error);
}

} // namespace

bool decode_encoded_image(std::span<const std::uint8_t> bytes, std::string_view name_hint,
                          RgbaImage& out, std::string& error) {
    if (!declared_size_ok(bytes, name_hint, error)) return false;
    try {
        bool handled = false;
        const bool ok = decode_in_process(bytes, name_hint, out, error, handled);
        if (handled) return ok;
        const oiio::PluginApi* api = image_plugin(name_hint, error);
        return api && api->decode(bytes, name_hint, size_check, out, error);
    } catch (const std::bad_alloc&) { // within the texel budget, but not in this memory
        error = std::string(name_hint) + ": out of memory while decoding (" +
                std::to_string(bytes.size()) + " encoded bytes)";
    }
    return false;
}

bool probe_encoded_image(std::span<const std::uint8_t> bytes, std::string_view name_hint,
                         std::string& error, std::uint32_t* width, std::uint32_t* height) {
    if (!declared_size_ok(bytes, name_hint, error)) return false;
    std::uint32_t w = 0, h = 0;
    CodecResult r = CodecResult::Unsupported;
    if (is_png(bytes))
        r = probe_png(bytes, name_hint, w, h, error);
    else if (is_jpeg(bytes))
        r = probe_jpeg(bytes, name_hint, w, h, error);
    bool ok = r == CodecResult::Ok;
    if (r == CodecResult::Unsupported) {
        const oiio::PluginApi* api = image_plugin(name_hint, error);
        ok = api && api->probe(bytes, name_hint, error, w, h);
    }
    if (width) *width = w;
    if (height) *height = h;
    return ok && decoded_size_ok(w, h, name_hint, error);
}

bool read_image_file(const std::filesystem::path& path, RgbaImage& out, std::string& error) {
    std::vector<std::uint8_t> bytes;
    if (!core::read_file(path, bytes, error)) return false;
    bool handled = false;
    const bool ok = decode_in_process(bytes, path.string(), out, error, handled);
    if (handled) return ok;
    // OpenImageIO reads by path (some formats read more than one file), and names
    // what it cannot open.
    const oiio::PluginApi* api = image_plugin(path.string(), error);
    return api && api->read_file(path, size_check, out, error);
}

bool read_float_image_file(const std::filesystem::path& path, std::uint32_t max_side,
                           FloatRgbImage& out, std::string& error) {
    const oiio::PluginApi* api = image_plugin(path.string(), error);
    try {
        return api && api->read_float_file(path, max_side, out, error);
    } catch (const std::bad_alloc&) {
        error = path.string() + ": out of memory while decoding";
    }
    return false;
}

bool write_image_file(const std::filesystem::path& path, const RgbaImage& image,
                      std::string& error) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".png") {
        std::vector<std::uint8_t> encoded;
        if (!encode_png(image.width, image.height, image.pixels, encoded, error)) {
            error = path.string() + ": " + error;
            return false;
        }
        return core::write_file_atomic(path.string(), encoded, error);
    }
    std::string why;
    const oiio::PluginApi* api = oiio::plugin(why);
    if (!api) error = path.string() + ": no writer: " + why;
    return api && api->write_file(path, image, error);
}

bool write_png(const std::string& path, std::uint32_t width, std::uint32_t height,
               const std::vector<std::uint8_t>& rgba, std::string& error) {
    // Encoded in memory, then written atomically so readers never see a torn file.
    std::vector<std::uint8_t> encoded;
    if (!encode_png(width, height, rgba, encoded, error)) {
        error = path + ": " + error;
        return false;
    }
    return core::write_file_atomic(
        path, std::span<const std::uint8_t>(encoded.data(), encoded.size()), error);
}

bool read_png_rgba8(const std::string& path, std::uint32_t& width, std::uint32_t& height,
                    std::vector<std::uint8_t>& rgba, std::string& error) {
    std::vector<std::uint8_t> encoded;
    if (!core::read_file(path, encoded, error)) return false;
    RgbaImage image;
    if (!decode_encoded_image(encoded, "image.png", image, error)) {
        error = path + ": " + error;
        return false;
    }
    width = image.width;
    height = image.height;
    rgba = std::move(image.pixels);
    return true;
}

} // namespace sherpa::tex
