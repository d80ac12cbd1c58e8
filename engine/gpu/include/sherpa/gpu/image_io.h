#pragma once
// PNG reading and writing of RGBA8 images (golden images, CLI output).
#include <cstdint>
#include <string>
#include <vector>

namespace sherpa::gpu {

bool write_png(const std::string& path, std::uint32_t width, std::uint32_t height,
               const std::vector<std::uint8_t>& rgba, std::string& error);
bool read_png_rgba8(const std::string& path, std::uint32_t& width, std::uint32_t& height,
                    std::vector<std::uint8_t>& rgba, std::string& error);

} // namespace sherpa::gpu
