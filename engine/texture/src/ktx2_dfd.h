#pragma once
// Data Format Descriptor (Khronos Data Format Specification 1.3, basic block)
// for the formats Sherpa writes to KTX2.
#include <cstdint>
#include <vector>

#include <sherpa/texture/ktx2.h>

namespace sherpa::tex {

// The complete DFD (dfdTotalSize word included) for `format`; empty if unsupported.
std::vector<std::uint8_t> data_format_descriptor(VkFormat format);

} // namespace sherpa::tex
