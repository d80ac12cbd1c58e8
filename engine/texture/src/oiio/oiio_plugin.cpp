// libsherpa_oiio.so: OpenImageIO behind the plugin table of oiio_plugin_api.h, for
// every format the engine does not decode itself (WebP, TGA, BMP, HDR, EXR, DDS ...).
// Nothing else links OpenImageIO, so a process loads it only when such an image is
// decoded or written.
#include "oiio_plugin_api.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <vector>

namespace sherpa::tex::oiio {
namespace {

// glTF stores base colour unassociated ("straight") with alpha beside it; OpenImageIO
// associates (premultiplies) alpha on read unless told otherwise, which darkens every
// texel whose alpha is below 1 and, once blended, applies alpha twice.
OIIO::ImageSpec unassociated_alpha_config() {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    return config;
}

// Expands `channels`-channel 8-bit rows to RGBA8 in place of `out`.
void expand_to_rgba(const std::vector<std::uint8_t>& src, int channels, RgbaImage& out) {
    const std::size_t texels = std::size_t{out.width} * out.height;
    out.pixels.resize(texels * 4);
    for (std::size_t i = 0; i < texels; ++i) {
        const std::uint8_t* s = src.data() + i * channels;
        std::uint8_t* d = out.pixels.data() + i * 4;
        if (channels >= 3)
            d[0] = s[0], d[1] = s[1], d[2] = s[2];
        else
            d[0] = d[1] = d[2] = s[0];
        d[3] = channels == 4 ? s[3] : channels == 2 ? s[1] : 255;
    }
}

bool read_from(OIIO::ImageInput* in, std::string_view name, SizeCheck check, RgbaImage& out,
               std::string& error) {
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
        error = std::string(name) + ": image has no pixels";
        return false;
    }
    if (!check(std::uint32_t(spec.width), std::uint32_t(spec.height), name, error)) return false;
    const int channels = std::min(spec.nchannels, 4);
    std::vector<std::uint8_t> raw(std::size_t(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, raw.data())) {
        error = std::string(name) + ": " + in->geterror();
        return false;
    }
    out.width = static_cast<std::uint32_t>(spec.width);
    out.height = static_cast<std::uint32_t>(spec.height);
    expand_to_rgba(raw, channels, out);
    return true;
}

// Opens `bytes` through an IOProxy (the name only picks the plugin), then runs `read`.
template <typename Read>
bool with_encoded_image(std::span<const std::uint8_t> bytes, std::string_view name_hint,
                        std::string& error, Read read) {
    // The proxy must be attached before open(), which then reads from it.
    OIIO::Filesystem::IOMemReader reader(const_cast<std::uint8_t*>(bytes.data()), bytes.size());
    auto in = OIIO::ImageInput::create(std::string(name_hint), false, nullptr, &reader);
    OIIO::ImageSpec spec;
    if (!in || !in->supports("ioproxy") || !in->set_ioproxy(&reader) ||
        !in->open(std::string(name_hint), spec, unassociated_alpha_config())) {
        error =
            std::string(name_hint) + ": cannot decode: " + (in ? in->geterror() : OIIO::geterror());
        return false;
    }
    const bool ok = read(in.get());
    in->close();
    return ok;
}

bool decode(std::span<const std::uint8_t> bytes, std::string_view name_hint, SizeCheck check,
            RgbaImage& out, std::string& error) {
    return with_encoded_image(bytes, name_hint, error, [&](OIIO::ImageInput* in) {
        return read_from(in, name_hint, check, out, error);
    });
}

bool probe(std::span<const std::uint8_t> bytes, std::string_view name_hint, std::string& error,
           std::uint32_t& width, std::uint32_t& height) {
    return with_encoded_image(bytes, name_hint, error, [&](OIIO::ImageInput* in) {
        const OIIO::ImageSpec& spec = in->spec();
        width = std::uint32_t(std::max(spec.width, 0));
        height = std::uint32_t(std::max(spec.height, 0));
        if (spec.width > 0 && spec.height > 0 && spec.nchannels > 0) return true;
        error = std::string(name_hint) + ": image has no pixels";
        return false;
    });
}

bool read_file(const std::filesystem::path& path, SizeCheck check, RgbaImage& out,
               std::string& error) {
    const OIIO::ImageSpec config = unassociated_alpha_config();
    auto in = OIIO::ImageInput::open(path.string(), &config);
    if (!in) {
        error = path.string() + ": cannot open: " + OIIO::geterror();
        return false;
    }
    const bool ok = read_from(in.get(), path.string(), check, out, error);
    in->close();
    return ok;
}

bool read_float_file(const std::filesystem::path& path, std::uint32_t max_side, FloatRgbImage& out,
                     std::string& error) {
    const OIIO::ImageSpec config = unassociated_alpha_config();
    auto in = OIIO::ImageInput::open(path.string(), &config);
    if (!in) {
        error = path.string() + ": cannot open: " + OIIO::geterror();
        return false;
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
        error = path.string() + ": the image has no texels (" + std::to_string(spec.width) + "x" +
                std::to_string(spec.height) + ")";
        return false;
    }
    if (std::uint32_t(spec.width) > max_side || std::uint32_t(spec.height) > max_side) {
        error = path.string() + ": the image is " + std::to_string(spec.width) + "x" +
                std::to_string(spec.height) + ", over the limit of " + std::to_string(max_side) +
                " texels a side";
        return false;
    }
    const int channels = std::min(spec.nchannels, 3);
    const std::size_t texels = std::size_t(spec.width) * std::size_t(spec.height);
    std::vector<float> raw(texels * std::size_t(channels));
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, raw.data())) {
        error = path.string() + ": cannot decode: " + in->geterror();
        return false;
    }
    in->close();
    out.width = std::uint32_t(spec.width);
    out.height = std::uint32_t(spec.height);
    if (channels == 3) {
        out.rgb = std::move(raw);
        return true;
    }
    out.rgb.resize(texels * 3);
    for (std::size_t i = 0; i < texels; ++i)
        out.rgb[i * 3] = out.rgb[i * 3 + 1] = out.rgb[i * 3 + 2] = raw[i * std::size_t(channels)];
    return true;
}

bool write_file(const std::filesystem::path& path, const RgbaImage& image, std::string& error) {
    auto outfile = OIIO::ImageOutput::create(path.string());
    if (!outfile) {
        error = path.string() + ": no writer: " + OIIO::geterror();
        return false;
    }
    OIIO::ImageSpec spec(static_cast<int>(image.width), static_cast<int>(image.height), 4,
                         OIIO::TypeDesc::UINT8);
    // The pixels are unassociated: without this the writer would divide by alpha.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!outfile->open(path.string(), spec) ||
        !outfile->write_image(OIIO::TypeDesc::UINT8, image.pixels.data())) {
        error = path.string() + ": " + outfile->geterror();
        return false;
    }
    outfile->close();
    return true;
}

const PluginApi kApi{kPluginAbi, decode, probe, read_file, read_float_file, write_file};

} // namespace
} // namespace sherpa::tex::oiio

extern "C" __attribute__((visibility("default"))) const sherpa::tex::oiio::PluginApi*
sherpa_oiio_plugin_api() {
    return &sherpa::tex::oiio::kApi;
}
