// OpenImageIO-backed decoding of encoded sources into RGBA8, and the PNG reading and
// writing of rendered frames: the engine's one image I/O module.
#include <sherpa/core/file_io.h>
#include <sherpa/texture/image.h>
#include <sherpa/texture/texel_budget.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <new>

namespace sherpa::tex {

bool RgbaImage::has_alpha() const {
    for (std::size_t i = 3; i < pixels.size(); i += 4)
        if (pixels[i] != 255) return true;
    return false;
}

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

bool read_from(OIIO::ImageInput* in, std::string_view name, RgbaImage& out, std::string& error) {
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
        error = std::string(name) + ": image has no pixels";
        return false;
    }
    // Any format OpenImageIO reads: its header's size, before the pixels are allocated.
    if (!check_texel_budget(std::uint64_t(spec.width), std::uint64_t(spec.height), name, error))
        return false;
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
} // namespace

namespace {
// Opens `bytes` through an IOProxy (the name only picks the plugin), then runs `read`.
template <typename Read>
bool with_encoded_image(std::span<const std::uint8_t> bytes, std::string_view name_hint,
                        std::string& error, Read read) {
    // PNG, JPEG and WebP sizes are read from their headers before any decoder sees
    // them: some decoders allocate the declared size as soon as they are opened.
    if (const auto declared = declared_image_size(bytes);
        declared && !check_texel_budget(declared->width, declared->height, name_hint, error))
        return false;
    try {
        // The proxy must be attached before open(), which then reads from it.
        OIIO::Filesystem::IOMemReader reader(const_cast<std::uint8_t*>(bytes.data()), bytes.size());
        auto in = OIIO::ImageInput::create(std::string(name_hint), false, nullptr, &reader);
        OIIO::ImageSpec spec;
        if (!in || !in->supports("ioproxy") || !in->set_ioproxy(&reader) ||
            !in->open(std::string(name_hint), spec, unassociated_alpha_config())) {
            error = std::string(name_hint) +
                    ": cannot decode: " + (in ? in->geterror() : OIIO::geterror());
            return false;
        }
        const bool ok = read(in.get());
        in->close();
        return ok;
    } catch (const std::bad_alloc&) { // within the texel budget, but not in this memory
        error = std::string(name_hint) + ": out of memory while decoding (" +
                std::to_string(bytes.size()) + " encoded bytes)";
    } catch (const std::exception& e) {
        error = std::string(name_hint) + ": cannot decode: " + e.what();
    }
    return false;
}
} // namespace

bool decode_encoded_image(std::span<const std::uint8_t> bytes, std::string_view name_hint,
                          RgbaImage& out, std::string& error) {
    return with_encoded_image(bytes, name_hint, error, [&](OIIO::ImageInput* in) {
        return read_from(in, name_hint, out, error);
    });
}

bool probe_encoded_image(std::span<const std::uint8_t> bytes, std::string_view name_hint,
                         std::string& error, std::uint32_t* width, std::uint32_t* height) {
    return with_encoded_image(bytes, name_hint, error, [&](OIIO::ImageInput* in) {
        const OIIO::ImageSpec& spec = in->spec();
        if (width) *width = std::uint32_t(std::max(spec.width, 0));
        if (height) *height = std::uint32_t(std::max(spec.height, 0));
        if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
            error = std::string(name_hint) + ": image has no pixels";
            return false;
        }
        return check_texel_budget(std::uint64_t(spec.width), std::uint64_t(spec.height), name_hint,
                                  error);
    });
}

bool read_image_file(const std::filesystem::path& path, RgbaImage& out, std::string& error) {
    const OIIO::ImageSpec config = unassociated_alpha_config();
    auto in = OIIO::ImageInput::open(path.string(), &config);
    if (!in) {
        error = path.string() + ": cannot open: " + OIIO::geterror();
        return false;
    }
    const bool ok = read_from(in.get(), path.string(), out, error);
    in->close();
    return ok;
}

bool write_image_file(const std::filesystem::path& path, const RgbaImage& image,
                      std::string& error) {
    auto outfile = OIIO::ImageOutput::create(path.string());
    if (!outfile) {
        error = path.string() + ": no writer: " + OIIO::geterror();
        return false;
    }
    OIIO::ImageSpec spec(static_cast<int>(image.width), static_cast<int>(image.height), 4,
                         OIIO::TypeDesc::UINT8);
    // The pixels are unassociated: without this the PNG writer would divide by alpha.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!outfile->open(path.string(), spec) ||
        !outfile->write_image(OIIO::TypeDesc::UINT8, image.pixels.data())) {
        error = path.string() + ": " + outfile->geterror();
        return false;
    }
    outfile->close();
    return true;
}

bool write_png(const std::string& path, std::uint32_t width, std::uint32_t height,
               const std::vector<std::uint8_t>& rgba, std::string& error) {
    if (rgba.size() != std::size_t(width) * height * 4) {
        error = path + ": pixel buffer does not match " + std::to_string(width) + "x" +
                std::to_string(height);
        return false;
    }
    // Encode in memory, then write atomically so readers never see a torn file.
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput writer(encoded);
    auto out = OIIO::ImageOutput::create("png");
    if (!out) {
        error = path + ": no PNG writer: " + OIIO::geterror();
        return false;
    }
    OIIO::ImageSpec spec(int(width), int(height), 4, OIIO::TypeDesc::UINT8);
    // Rendered pixels are stored as they are; without this the PNG writer treats them
    // as associated and divides colour by alpha.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    // The name only selects the format; the proxy receives the bytes.
    if (!out->set_ioproxy(&writer) || !out->open("out.png", spec) ||
        !out->write_image(OIIO::TypeDesc::UINT8, rgba.data()) || !out->close()) {
        error = path + ": cannot encode PNG: " + out->geterror();
        return false;
    }
    return write_file_atomic(path, std::span<const std::uint8_t>(encoded.data(), encoded.size()),
                             error);
}

bool read_png_rgba8(const std::string& path, std::uint32_t& width, std::uint32_t& height,
                    std::vector<std::uint8_t>& rgba, std::string& error) {
    std::vector<std::uint8_t> encoded;
    if (!read_file(path, encoded, error)) return false;
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
