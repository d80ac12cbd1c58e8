#include "ktx2_dfd.h"

namespace sherpa::tex {

namespace {
// Values from the Khronos Data Format Specification (khr_df.h enumerations).
constexpr std::uint32_t kModelRgbsda = 1, kModelBc5 = 132, kModelBc7 = 134;
constexpr std::uint32_t kPrimariesBt709 = 1;
constexpr std::uint32_t kTransferLinear = 1, kTransferSrgb = 2;
constexpr std::uint32_t kChannelRed = 0, kChannelGreen = 1, kChannelBlue = 2, kChannelAlpha = 15;
constexpr std::uint32_t kQualifierLinear = 0x10; // sample is linear even in an sRGB format

struct Sample {
    std::uint32_t bit_offset, bit_length, channel, lower, upper;
};

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

std::vector<std::uint8_t> basic_block(std::uint32_t model, std::uint32_t transfer,
                                      std::uint32_t block_w, std::uint32_t block_h,
                                      std::uint32_t bytes_plane0,
                                      const std::vector<Sample>& samples) {
    const std::uint32_t block_size = 24 + 16 * static_cast<std::uint32_t>(samples.size());
    std::vector<std::uint8_t> out;
    put32(out, 4 + block_size);          // dfdTotalSize
    put32(out, 0);                       // vendorId 0 (Khronos), descriptorType 0 (basic)
    put32(out, 2u | (block_size << 16)); // versionNumber 2 (KDF 1.3), descriptorBlockSize
    put32(out, model | (kPrimariesBt709 << 8) | (transfer << 16)); // flags 0: straight alpha
    put32(out, (block_w - 1) | ((block_h - 1) << 8)); // texelBlockDimension, depth/time 1
    put32(out, bytes_plane0);                         // bytesPlane0..3
    put32(out, 0);                                    // bytesPlane4..7
    for (const Sample& s : samples) {
        put32(out, s.bit_offset | ((s.bit_length - 1) << 16) | (s.channel << 24));
        put32(out, 0); // samplePosition: all at the block origin
        put32(out, s.lower);
        put32(out, s.upper);
    }
    return out;
}
} // namespace

std::vector<std::uint8_t> data_format_descriptor(VkFormat format) {
    switch (format) {
    case VkFormat::Bc7UnormBlock:
    case VkFormat::Bc7SrgbBlock:
        return basic_block(kModelBc7,
                           format == VkFormat::Bc7SrgbBlock ? kTransferSrgb : kTransferLinear, 4, 4,
                           16, {{0, 128, 0, 0, 0xFFFFFFFFu}});
    case VkFormat::Bc5UnormBlock:
        return basic_block(
            kModelBc5, kTransferLinear, 4, 4, 16,
            {{0, 64, kChannelRed, 0, 0xFFFFFFFFu}, {64, 64, kChannelGreen, 0, 0xFFFFFFFFu}});
    case VkFormat::R8G8B8A8Unorm:
    case VkFormat::R8G8B8A8Srgb: {
        const bool srgb = format == VkFormat::R8G8B8A8Srgb;
        return basic_block(kModelRgbsda, srgb ? kTransferSrgb : kTransferLinear, 1, 1, 4,
                           {{0, 8, kChannelRed, 0, 255},
                            {8, 8, kChannelGreen, 0, 255},
                            {16, 8, kChannelBlue, 0, 255},
                            {24, 8, kChannelAlpha | (srgb ? kQualifierLinear : 0), 0, 255}});
    }
    case VkFormat::Undefined:
        break;
    }
    return {};
}

} // namespace sherpa::tex
