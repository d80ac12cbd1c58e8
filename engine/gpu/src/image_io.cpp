#include <sherpa/core/file_io.h>
#include <sherpa/gpu/image_io.h>
#include <sherpa/texture/image.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

namespace sherpa::gpu {

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
    tex::RgbaImage image;
    if (!tex::decode_encoded_image(encoded, "image.png", image, error)) {
        error = path + ": " + error;
        return false;
    }
    width = image.width;
    height = image.height;
    rgba = std::move(image.pixels);
    return true;
}

} // namespace sherpa::gpu
