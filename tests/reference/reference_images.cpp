// libpng and libjpeg report errors through longjmp; everything they allocate is
// owned by their structs, released on both paths.
#include "reference_images.h"

#include <cctype>
#include <csetjmp>
#include <cstdio>
#include <memory>
#include <vector>

#include <jpeglib.h>
#include <png.h>

namespace sherpa::test {
namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

struct JpegError {
    jpeg_error_mgr mgr;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX] = {};
};

void jpeg_error_exit(j_common_ptr info) {
    auto* err = reinterpret_cast<JpegError*>(info->err);
    info->err->format_message(info, err->message);
    std::longjmp(err->jump, 1);
}

// The libpng and libjpeg calls run in frames of their own that hold no C++ object
// with a destructor: longjmp skips destructors, and GCC (-Wclobbered, at -O1) warns
// that locals of a frame that calls setjmp may be clobbered. Each returns nullptr,
// or what went wrong; the callers build the messages.
const char* decode_png(std::FILE* file, ReferenceImage& out, std::vector<png_bytep>& rows) {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        return "libpng could not start";
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return "libpng failed to decode it";
    }
    png_init_io(png, file);
    png_read_info(png, info);
    // Expand whatever the file stores to 8-bit RGBA, without touching colour values:
    // no gamma handling and no alpha association (libpng never associates unless
    // asked with png_set_alpha_mode).
    png_set_expand(png); // palette -> RGB, grey < 8 bits -> 8 bits, tRNS -> alpha
    png_set_strip_16(png);
    png_set_gray_to_rgb(png);
    png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    out.width = png_get_image_width(png, info);
    out.height = png_get_image_height(png, info);
    if (png_get_rowbytes(png, info) != std::size_t(out.width) * 4) {
        png_destroy_read_struct(&png, &info, nullptr);
        return "libpng did not expand it to RGBA8";
    }
    out.rgba.assign(std::size_t(out.width) * out.height * 4, 0);
    rows.resize(out.height);
    for (std::uint32_t y = 0; y < out.height; ++y)
        rows[y] = out.rgba.data() + std::size_t(y) * out.width * 4;
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    return nullptr;
}

// `err.message` holds libjpeg's own words when this returns "libjpeg".
const char* decode_jpeg(std::FILE* file, ReferenceImage& out, std::vector<std::uint8_t>& row,
                        JpegError& err) {
    jpeg_decompress_struct info{};
    info.err = jpeg_std_error(&err.mgr);
    err.mgr.error_exit = jpeg_error_exit;
    if (setjmp(err.jump)) {
        jpeg_destroy_decompress(&info);
        return "libjpeg";
    }
    jpeg_create_decompress(&info);
    jpeg_stdio_src(&info, file);
    jpeg_read_header(&info, TRUE);
    info.out_color_space = JCS_RGB;
    jpeg_start_decompress(&info);
    out.width = info.output_width;
    out.height = info.output_height;
    out.rgba.assign(std::size_t(out.width) * out.height * 4, 255);
    row.resize(std::size_t(out.width) * 3);
    while (info.output_scanline < info.output_height) {
        const std::uint32_t y = info.output_scanline;
        JSAMPROW rows[1] = {row.data()};
        jpeg_read_scanlines(&info, rows, 1);
        for (std::uint32_t x = 0; x < out.width; ++x)
            for (int c = 0; c < 3; ++c)
                out.rgba[(std::size_t(y) * out.width + x) * 4 + c] = row[std::size_t(x) * 3 + c];
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    return nullptr;
}

} // namespace

bool read_png_reference(const std::filesystem::path& path, ReferenceImage& out,
                        std::string& error) {
    File file(std::fopen(path.c_str(), "rb"));
    if (!file) {
        error = path.string() + ": cannot open";
        return false;
    }
    std::vector<png_bytep> rows;
    if (const char* problem = decode_png(file.get(), out, rows)) {
        error = path.string() + ": " + problem;
        return false;
    }
    return true;
}

bool read_jpeg_reference(const std::filesystem::path& path, ReferenceImage& out,
                         std::string& error) {
    File file(std::fopen(path.c_str(), "rb"));
    if (!file) {
        error = path.string() + ": cannot open";
        return false;
    }
    std::vector<std::uint8_t> row;
    JpegError err;
    if (const char* problem = decode_jpeg(file.get(), out, row, err)) {
        error = path.string() + ": " + problem + ": " + err.message;
        return false;
    }
    return true;
}

bool read_reference_image(const std::filesystem::path& path, ReferenceImage& out,
                          std::string& error) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".png") return read_png_reference(path, out, error);
    if (ext == ".jpg" || ext == ".jpeg") return read_jpeg_reference(path, out, error);
    error = path.string() + ": no reference decoder for " + ext;
    return false;
}

} // namespace sherpa::test
