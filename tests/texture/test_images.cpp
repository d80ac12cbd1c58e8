#include "test_images.h"

#include <sherpa/core/file_io.h>

#include <unistd.h>

#include <algorithm>
#include <stdexcept>

namespace sherpa::test {

tex::RgbaImage load_crop(const std::filesystem::path& file, std::uint32_t x, std::uint32_t y,
                         std::uint32_t w, std::uint32_t h) {
    tex::RgbaImage full;
    std::string error;
    if (!tex::read_image_file(file, full, error)) throw std::runtime_error(error);
    if (x + w > full.width || y + h > full.height)
        throw std::runtime_error("crop outside " + file.string());
    tex::RgbaImage crop{w, h, std::vector<std::uint8_t>(std::size_t{w} * h * 4)};
    for (std::uint32_t row = 0; row < h; ++row)
        std::copy_n(full.pixels.data() + ((std::size_t{y} + row) * full.width + x) * 4, w * 4,
                    crop.pixels.data() + std::size_t{row} * w * 4);
    return crop;
}

tex::RgbaImage synthetic_image(std::uint32_t w, std::uint32_t h, bool with_alpha,
                               std::uint32_t seed) {
    tex::RgbaImage img{w, h, std::vector<std::uint8_t>(std::size_t{w} * h * 4)};
    std::uint32_t state = seed * 2654435761u + 1;
    auto noise = [&] {
        state = state * 1664525u + 1013904223u;
        return static_cast<int>(state >> 24);
    };
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            std::uint8_t* p = img.pixels.data() + (std::size_t{y} * w + x) * 4;
            const int region = static_cast<int>(((x / 8) + (y / 8) * 3 + seed) % 5);
            int r = 0, g = 0, b = 0;
            switch (region) {
            case 0:
                r = x * 255 / w, g = y * 255 / h, b = 128;
                break; // smooth gradient
            case 1:
                r = (x + y) % 8 < 4 ? 230 : 20, g = 40, b = (x * 7) % 256;
                break; // hard edges
            case 2:
                r = noise(), g = noise(), b = noise();
                break; // noise
            case 3:
                r = 200 + noise() % 8, g = 100 + noise() % 8, b = 50;
                break; // near constant
            default:
                r = g = b = (x % 4) * 80;
                break; // grey stripes
            }
            p[0] = static_cast<std::uint8_t>(r), p[1] = static_cast<std::uint8_t>(g),
            p[2] = static_cast<std::uint8_t>(b);
            p[3] = with_alpha ? static_cast<std::uint8_t>(
                                    region == 2 ? noise() : (x * 255 / (w > 1 ? w - 1 : 1)))
                              : 255;
        }
    return img;
}

tex::RgbaImage constant_image(std::uint32_t w, std::uint32_t h, std::uint8_t r, std::uint8_t g,
                              std::uint8_t b, std::uint8_t a) {
    tex::RgbaImage img{w, h, {}};
    for (std::size_t i = 0; i < std::size_t{w} * h; ++i)
        img.pixels.insert(img.pixels.end(), {r, g, b, a});
    return img;
}

std::vector<std::uint8_t> png_bytes(const tex::RgbaImage& img, const std::string& name) {
    const auto dir = fresh_temp_dir("png-" + name);
    std::string error;
    if (!tex::write_image_file(dir / "img.png", img, error)) throw std::runtime_error(error);
    std::vector<std::uint8_t> bytes;
    if (!core::read_file(dir / "img.png", bytes, error)) throw std::runtime_error(error);
    std::filesystem::remove_all(dir);
    return bytes;
}

std::filesystem::path fresh_temp_dir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("sherpa-test-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace sherpa::test
