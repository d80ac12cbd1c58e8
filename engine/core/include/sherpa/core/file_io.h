#pragma once
// Whole-file reads and crash-safe writes (temp file, fsync, rename).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace sherpa {

// Reads a whole file. Returns false and fills `error` (naming the file) on failure.
bool read_file(const std::filesystem::path& path, std::vector<std::uint8_t>& out,
               std::string& error);

// Writes `bytes` to `path` atomically: a unique temp file in the same directory is
// written, fsync'ed and renamed over `path`, so readers see the old or the new file,
// never a torn one. Concurrent writers of the same path are safe (last rename wins).
bool write_file_atomic(const std::filesystem::path& path, std::span<const std::uint8_t> bytes,
                       std::string& error);

} // namespace sherpa
