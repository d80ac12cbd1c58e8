// libpng reports errors through longjmp. The calls run in frames of their own that
// hold no C++ object with a destructor (longjmp skips destructors, and GCC warns that
// locals of a frame that calls setjmp may be clobbered); each returns nullptr or what
// went wrong, and the callers build the messages.
#include "image_codecs.h"

#include <sherpa/texture/texel_budget.h>

#include <png.h>

#include <algorithm>
#include <cstring>

namespace sherpa::tex {
namespace {

struct PngContext {
    std::span<const std::uint8_t> bytes;
    std::size_t offset = 0;
    std::vector<std::uint8_t>* sink = nullptr;
    char message[256] = {};
};

void on_error(png_structp png, png_const_charp message) {
    auto* ctx = static_cast<PngContext*>(png_get_error_ptr(png));
    std::snprintf(ctx->message, sizeof ctx->message, "%s", message);
    png_longjmp(png, 1);
}

// libpng's default prints warnings (e.g. "known incorrect sRGB profile") to stderr.
void on_warning(png_structp, png_const_charp) {}

void read_bytes(png_structp png, png_bytep data, png_size_t length) {
    auto* ctx = static_cast<PngContext*>(png_get_io_ptr(png));
    if (length > ctx->bytes.size() - ctx->offset) png_error(png, "file is truncated");
    std::memcpy(data, ctx->bytes.data() + ctx->offset, length);
    ctx->offset += length;
}

void write_bytes(png_structp png, png_bytep data, png_size_t length) {
    auto* ctx = static_cast<PngContext*>(png_get_io_ptr(png));
    ctx->sink->insert(ctx->sink->end(), data, data + length);
}

void flush_nothing(png_structp) {}

// libpng's allocation limits, set here rather than left to how libpng was built (a
// build may turn them off; Debian's 1.6.39 has 1,000,000 per side, 8,000,000 bytes
// per chunk and 1000 stored ancillary chunks). Sides: the texel budget's. A chunk's
// data is buffered whole before it is handled (and a compressed one inflates up to
// the same limit): 8 MiB, more than a texture's metadata needs.
constexpr png_alloc_size_t kMaxChunkBytes = png_alloc_size_t{8} << 20;
constexpr png_uint_32 kMaxStoredChunks = 64;
// The ancillary chunks the RGBA8 conversion does not read (colour space, text,
// histogram, palette suggestions, times, offsets, Exif), skipped without being
// buffered: 5 bytes each, the name and a NUL, as png_set_keep_unknown_chunks reads
// them. tRNS and PLTE are read.
constexpr char kSkippedChunks[] = "bKGD\0cHRM\0eXIf\0gAMA\0hIST\0iCCP\0iTXt\0oFFs\0pCAL\0"
                                  "pHYs\0sBIT\0sCAL\0sPLT\0sRGB\0sTER\0tEXt\0tIME\0zTXt";

void set_limits(png_structp png) {
    png_set_user_limits(png, png_uint_32(kMaxImageSide), png_uint_32(kMaxImageSide));
    png_set_chunk_malloc_max(png, kMaxChunkBytes);
    png_set_chunk_cache_max(png, kMaxStoredChunks);
    png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_NEVER,
                                reinterpret_cast<png_const_bytep>(kSkippedChunks),
                                int(sizeof kSkippedChunks / 5));
}

// Header only when `out` is null; else the whole image into `out` (after the size check).
const char* run_decode(PngContext& ctx, std::string_view name, std::uint32_t& width,
                       std::uint32_t& height, RgbaImage* out, std::vector<png_bytep>& rows,
                       std::string& refused) {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &ctx, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        return "libpng could not start";
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        return ctx.message;
    }
    png_set_read_fn(png, &ctx, read_bytes);
    set_limits(png);
    png_read_info(png, info);
    width = png_get_image_width(png, info);
    height = png_get_image_height(png, info);
    if (!out) {
        png_destroy_read_struct(&png, &info, nullptr);
        return nullptr;
    }
    if (!decoded_size_ok(width, height, name, refused)) {
        png_destroy_read_struct(&png, &info, nullptr);
        return "";
    }
    // What OpenImageIO's PNG reader gives, converted to 8-bit RGBA: palette, grey and
    // tRNS expanded; 16-bit samples rounded to 8 bits (OpenImageIO's conversion, not
    // libpng's truncating strip); no gamma, no alpha association.
    png_set_expand(png);
    png_set_scale_16(png);
    png_set_gray_to_rgb(png);
    png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_rowbytes(png, info) != std::size_t(width) * 4) {
        png_destroy_read_struct(&png, &info, nullptr);
        return "libpng did not expand it to RGBA8";
    }
    out->width = width;
    out->height = height;
    out->pixels.resize(std::size_t(width) * height * 4);
    rows.resize(height);
    for (std::uint32_t y = 0; y < height; ++y)
        rows[y] = out->pixels.data() + std::size_t(y) * width * 4;
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    return nullptr;
}

const char* run_encode(PngContext& ctx, std::uint32_t width, std::uint32_t height,
                       std::vector<png_bytep>& rows) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &ctx, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return "libpng could not start";
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return ctx.message;
    }
    png_set_write_fn(png, &ctx, write_bytes, flush_nothing);
    png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return nullptr;
}

} // namespace

bool is_png(std::span<const std::uint8_t> bytes) {
    return bytes.size() >= 8 && png_sig_cmp(bytes.data(), 0, 8) == 0;
}

CodecResult decode_png(std::span<const std::uint8_t> bytes, std::string_view name, RgbaImage& out,
                       std::string& error) {
    PngContext ctx{bytes};
    std::vector<png_bytep> rows;
    std::string refused;
    std::uint32_t width = 0, height = 0;
    RgbaImage image;
    if (const char* problem = run_decode(ctx, name, width, height, &image, rows, refused)) {
        error = !refused.empty() ? refused : std::string(name) + ": cannot decode: PNG: " + problem;
        return CodecResult::Failed;
    }
    out = std::move(image);
    return CodecResult::Ok;
}

CodecResult probe_png(std::span<const std::uint8_t> bytes, std::string_view name,
                      std::uint32_t& width, std::uint32_t& height, std::string& error) {
    PngContext ctx{bytes};
    std::vector<png_bytep> rows;
    std::string refused;
    if (const char* problem = run_decode(ctx, name, width, height, nullptr, rows, refused)) {
        error = std::string(name) + ": cannot decode: PNG: " + problem;
        return CodecResult::Failed;
    }
    if (width == 0 || height == 0) {
        error = std::string(name) + ": image has no pixels";
        return CodecResult::Failed;
    }
    return CodecResult::Ok;
}

bool encode_png(std::uint32_t width, std::uint32_t height, std::span<const std::uint8_t> rgba,
                std::vector<std::uint8_t>& encoded, std::string& error) {
    if (width == 0 || height == 0 || rgba.size() != std::size_t(width) * height * 4) {
        error = "cannot encode PNG: pixel buffer does not match " + std::to_string(width) + "x" +
                std::to_string(height);
        return false;
    }
    encoded.clear();
    PngContext ctx{{}, 0, &encoded};
    std::vector<png_bytep> rows(height);
    for (std::uint32_t y = 0; y < height; ++y)
        rows[y] = const_cast<png_bytep>(rgba.data() + std::size_t(y) * width * 4);
    if (const char* problem = run_encode(ctx, width, height, rows)) {
        error = std::string("cannot encode PNG: ") + problem;
        return false;
    }
    return true;
}

} // namespace sherpa::tex
