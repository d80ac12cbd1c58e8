// libjpeg-turbo reports errors through longjmp: as in png_codec.cpp, the calls run in
// frames that hold no C++ object with a destructor.
#include "image_codecs.h"

#include <csetjmp>
#include <cstdio>

#include <jpeglib.h>

namespace sherpa::tex {
namespace {

struct JpegError {
    jpeg_error_mgr mgr;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX] = {};
};

void on_error(j_common_ptr info) {
    auto* err = reinterpret_cast<JpegError*>(info->err);
    info->err->format_message(info, err->message);
    std::longjmp(err->jump, 1);
}

// libjpeg's default prints warnings ("Corrupt JPEG data: ...") to stderr.
void on_message(j_common_ptr) {}

enum class Step { Done, Failed, Unsupported, Refused };

// Header only when `out` is null; else the whole image into `out` (after the size check).
Step run_decode(std::span<const std::uint8_t> bytes, std::string_view name, JpegError& err,
                std::uint32_t& width, std::uint32_t& height, RgbaImage* out, std::string& refused) {
    jpeg_decompress_struct info{};
    info.err = jpeg_std_error(&err.mgr);
    err.mgr.error_exit = on_error;
    err.mgr.output_message = on_message;
    if (setjmp(err.jump)) {
        jpeg_destroy_decompress(&info);
        return Step::Failed;
    }
    jpeg_create_decompress(&info);
    jpeg_mem_src(&info, bytes.data(), static_cast<unsigned long>(bytes.size()));
    jpeg_read_header(&info, TRUE);
    width = info.image_width;
    height = info.image_height;
    // CMYK and YCCK need an inversion convention libjpeg does not settle: OpenImageIO's.
    if (info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK) {
        jpeg_destroy_decompress(&info);
        return Step::Unsupported;
    }
    if (!out) {
        jpeg_destroy_decompress(&info);
        return Step::Done;
    }
    if (!decoded_size_ok(width, height, name, refused)) {
        jpeg_destroy_decompress(&info);
        return Step::Refused;
    }
    // libjpeg-turbo's defaults (islow DCT, fancy upsampling), as OpenImageIO reads;
    // grey is replicated to RGB and alpha filled with 255 by the colour converter.
    info.out_color_space = JCS_EXT_RGBA;
    jpeg_start_decompress(&info);
    out->width = info.output_width;
    out->height = info.output_height;
    out->pixels.resize(std::size_t(out->width) * out->height * 4);
    while (info.output_scanline < info.output_height) {
        JSAMPROW row = out->pixels.data() + std::size_t(info.output_scanline) * out->width * 4;
        jpeg_read_scanlines(&info, &row, 1);
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    return Step::Done;
}

CodecResult finish(Step step, std::string_view name, const JpegError& err,
                   const std::string& refused, std::string& error) {
    switch (step) {
    case Step::Done:
        return CodecResult::Ok;
    case Step::Unsupported:
        return CodecResult::Unsupported;
    case Step::Refused:
        error = refused;
        return CodecResult::Failed;
    case Step::Failed:
        break;
    }
    error = std::string(name) + ": cannot decode: JPEG: " + err.message;
    return CodecResult::Failed;
}

} // namespace

bool is_jpeg(std::span<const std::uint8_t> bytes) {
    return bytes.size() >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF;
}

CodecResult decode_jpeg(std::span<const std::uint8_t> bytes, std::string_view name, RgbaImage& out,
                        std::string& error) {
    JpegError err;
    std::string refused;
    std::uint32_t width = 0, height = 0;
    RgbaImage image;
    const CodecResult r = finish(run_decode(bytes, name, err, width, height, &image, refused), name,
                                 err, refused, error);
    if (r == CodecResult::Ok) out = std::move(image);
    return r;
}

CodecResult probe_jpeg(std::span<const std::uint8_t> bytes, std::string_view name,
                       std::uint32_t& width, std::uint32_t& height, std::string& error) {
    JpegError err;
    std::string refused;
    return finish(run_decode(bytes, name, err, width, height, nullptr, refused), name, err, refused,
                  error);
}

} // namespace sherpa::tex
