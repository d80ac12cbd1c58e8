// The in-process PNG (libpng) and JPEG (libjpeg-turbo) decoders give exactly the
// texels OpenImageIO gives with unassociated alpha (OpenImageIO, through its plugin, is
// the reference here): every PNG and JPEG of the shared assets, and PNG/JPEG variants
// the assets lack (16-bit, grey, grey+alpha, palette with tRNS, 1-bit, interlaced,
// grey JPEG) written here with libpng/libjpeg.
#include <gtest/gtest.h>

#include <csetjmp>
#include <cstdio>
#include <vector>

#include <jpeglib.h>
#include <png.h>

#include <sherpa/core/file_io.h>
#include <sherpa/texture/image.h>

#include "image_codecs.h"
#include "oiio/oiio_plugin_api.h"
#include "test_images.h"

using namespace sherpa;

namespace {

bool no_limit(std::uint32_t, std::uint32_t, std::string_view, std::string&) {
    return true;
}

// OpenImageIO's texels, through the plugin.
tex::RgbaImage oiio_decode(const std::vector<std::uint8_t>& bytes, const std::string& hint) {
    std::string error;
    const tex::oiio::PluginApi* api = tex::oiio::plugin(error);
    EXPECT_NE(api, nullptr) << error;
    tex::RgbaImage img;
    if (api) {
        EXPECT_TRUE(api->decode(bytes, hint, no_limit, img, error)) << hint << ": " << error;
    }
    return img;
}

void expect_same_as_oiio(const std::vector<std::uint8_t>& bytes, const std::string& hint) {
    tex::RgbaImage ours;
    std::string error;
    ASSERT_TRUE(tex::decode_encoded_image(bytes, hint, ours, error)) << hint << ": " << error;
    const tex::RgbaImage ref = oiio_decode(bytes, hint);
    ASSERT_EQ(ours.width, ref.width) << hint;
    ASSERT_EQ(ours.height, ref.height) << hint;
    std::size_t differing = 0, first = 0;
    for (std::size_t i = 0; i < ours.pixels.size(); ++i)
        if (ours.pixels[i] != ref.pixels[i] && differing++ == 0) first = i;
    EXPECT_EQ(differing, 0u) << hint << ": first at byte " << first << ": ours "
                             << int(ours.pixels[first]) << ", OpenImageIO "
                             << int(ref.pixels[first]);
    std::uint32_t w = 0, h = 0;
    EXPECT_TRUE(tex::probe_encoded_image(bytes, hint, error, &w, &h)) << error;
    EXPECT_EQ(w, ref.width);
    EXPECT_EQ(h, ref.height);
}

// A PNG written by libpng: `channels` samples of `depth` bits per texel (palette:
// channels 1 with a palette and tRNS), values from a fixed pattern.
struct PngVariant {
    int color_type, depth, interlace;
};

void png_to_vector(png_structp png, png_bytep data, png_size_t n) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + n);
}

std::vector<std::uint8_t> write_png_variant(PngVariant v, std::uint32_t w, std::uint32_t h) {
    std::vector<std::uint8_t> out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_set_write_fn(png, &out, png_to_vector, nullptr);
    png_set_IHDR(png, info, w, h, v.depth, v.color_type, v.interlace, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (v.color_type == PNG_COLOR_TYPE_PALETTE) {
        std::vector<png_color> palette(std::size_t(1) << v.depth);
        std::vector<png_byte> alpha(palette.size());
        for (std::size_t i = 0; i < palette.size(); ++i) {
            palette[i] = {png_byte(i * 37), png_byte(255 - i * 11), png_byte(i * 5 + 3)};
            alpha[i] = png_byte(i * 29 + 7);
        }
        png_set_PLTE(png, info, palette.data(), int(palette.size()));
        png_set_tRNS(png, info, alpha.data(), int(alpha.size()), nullptr);
    }
    png_write_info(png, info);
    const int channels = png_get_channels(png, info);
    const std::size_t row_bytes = png_get_rowbytes(png, info);
    std::vector<std::uint8_t> rows(row_bytes * h);
    std::uint32_t state = 12345;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        state = state * 1664525u + 1013904223u;
        rows[i] = std::uint8_t(state >> 24);
    }
    (void)channels;
    std::vector<png_bytep> pointers(h);
    for (std::uint32_t y = 0; y < h; ++y) pointers[y] = rows.data() + y * row_bytes;
    png_write_image(png, pointers.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return out;
}

std::vector<std::uint8_t> write_grey_jpeg(std::uint32_t w, std::uint32_t h) {
    jpeg_compress_struct info{};
    jpeg_error_mgr err{};
    info.err = jpeg_std_error(&err);
    jpeg_create_compress(&info);
    unsigned char* mem = nullptr;
    unsigned long size = 0;
    jpeg_mem_dest(&info, &mem, &size);
    info.image_width = w;
    info.image_height = h;
    info.input_components = 1;
    info.in_color_space = JCS_GRAYSCALE;
    jpeg_set_defaults(&info);
    jpeg_start_compress(&info, TRUE);
    std::vector<std::uint8_t> row(w);
    while (info.next_scanline < h) {
        for (std::uint32_t x = 0; x < w; ++x)
            row[x] = std::uint8_t((x * 7 + info.next_scanline * 3) ^ x);
        JSAMPROW p = row.data();
        jpeg_write_scanlines(&info, &p, 1);
    }
    jpeg_finish_compress(&info);
    jpeg_destroy_compress(&info);
    std::vector<std::uint8_t> out(mem, mem + size);
    std::free(mem);
    return out;
}

} // namespace

TEST(ImageCodecs, EveryAssetPngAndJpegDecodesAsOpenImageIODoes) {
    std::size_t png = 0, jpeg = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(test::assets_dir())) {
        std::string ext = entry.path().extension().string();
        for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
        const bool is_png = ext == ".png", is_jpeg = ext == ".jpg" || ext == ".jpeg";
        if (!is_png && !is_jpeg) continue;
        std::vector<std::uint8_t> bytes;
        std::string error;
        ASSERT_TRUE(core::read_file(entry.path(), bytes, error)) << error;
        expect_same_as_oiio(bytes, entry.path().string());
        (is_png ? png : jpeg)++;
    }
    // The assets hold RGB, RGBA, palette (8- and 1-bit) PNGs and baseline and
    // progressive JPEGs.
    EXPECT_GT(png, 20u);
    EXPECT_GT(jpeg, 20u);
}

TEST(ImageCodecs, PngVariantsDecodeAsOpenImageIODoes) {
    const PngVariant variants[] = {
        {PNG_COLOR_TYPE_RGB_ALPHA, 16, PNG_INTERLACE_NONE},
        {PNG_COLOR_TYPE_RGB, 16, PNG_INTERLACE_NONE},
        {PNG_COLOR_TYPE_GRAY, 8, PNG_INTERLACE_NONE},
        {PNG_COLOR_TYPE_GRAY, 16, PNG_INTERLACE_NONE},
        {PNG_COLOR_TYPE_GRAY, 1, PNG_INTERLACE_NONE},
        {PNG_COLOR_TYPE_GRAY, 4, PNG_INTERLACE_NONE},
        {PNG_COLOR_TYPE_GRAY_ALPHA, 8, PNG_INTERLACE_NONE},
        {PNG_COLOR_TYPE_GRAY_ALPHA, 16, PNG_INTERLACE_NONE},
        {PNG_COLOR_TYPE_PALETTE, 8, PNG_INTERLACE_NONE},
        {PNG_COLOR_TYPE_PALETTE, 2, PNG_INTERLACE_NONE},
        {PNG_COLOR_TYPE_RGB_ALPHA, 8, PNG_INTERLACE_ADAM7},
        {PNG_COLOR_TYPE_RGB, 8, PNG_INTERLACE_ADAM7},
    };
    for (const PngVariant& v : variants) {
        SCOPED_TRACE("color type " + std::to_string(v.color_type) + ", " + std::to_string(v.depth) +
                     " bits, interlace " + std::to_string(v.interlace));
        expect_same_as_oiio(write_png_variant(v, 37, 23), "variant.png");
    }
}

TEST(ImageCodecs, GreyJpegDecodesAsOpenImageIODoes) {
    expect_same_as_oiio(write_grey_jpeg(67, 45), "grey.jpg");
}

// Alpha stays as stored (OpenImageIO would premultiply without being told not to):
// a texel of alpha 0 keeps its colour.
TEST(ImageCodecs, PngAlphaIsUnassociated) {
    tex::RgbaImage img;
    img.width = 2;
    img.height = 1;
    img.pixels = {200, 100, 50, 0, 10, 20, 30, 128};
    std::vector<std::uint8_t> encoded;
    std::string error;
    ASSERT_TRUE(tex::encode_png(2, 1, img.pixels, encoded, error)) << error;
    tex::RgbaImage back;
    ASSERT_TRUE(tex::decode_encoded_image(encoded, "a.png", back, error)) << error;
    EXPECT_EQ(back.pixels, img.pixels);
    EXPECT_EQ(oiio_decode(encoded, "a.png").pixels, img.pixels);
}

TEST(ImageCodecs, DamagedFilesFailWithTheDecodersReason) {
    std::vector<std::uint8_t> png = write_png_variant({PNG_COLOR_TYPE_RGB, 8, 0}, 64, 64);
    png.resize(png.size() / 2);
    tex::RgbaImage img;
    std::string error;
    EXPECT_FALSE(tex::decode_encoded_image(png, "half.png", img, error));
    EXPECT_NE(error.find("half.png: cannot decode: PNG"), std::string::npos) << error;
    std::vector<std::uint8_t> jpeg = write_grey_jpeg(64, 64);
    jpeg.resize(40);
    error.clear();
    EXPECT_FALSE(tex::decode_encoded_image(jpeg, "cut.jpg", img, error));
    EXPECT_NE(error.find("cut.jpg: cannot decode: JPEG"), std::string::npos) << error;
}
