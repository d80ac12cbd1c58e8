#pragma once
// Whole-file reads and crash-safe writes (temp file, fsync, rename).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sherpa::core {

// Reads a whole regular file. Returns false and fills `error` (naming the file) on
// failure, also for a directory, FIFO or device, which are refused before any read:
// a FIFO would block the open and a device could be read forever.
bool read_file(const std::filesystem::path& path, std::vector<std::uint8_t>& out,
               std::string& error);

// Writes `bytes` to `path` atomically: a unique temp file in the same directory is
// written, fsync'ed and renamed over `path`, so readers see the old or the new file,
// never a torn one. Concurrent writers of the same path are safe (last rename wins).
// The temp file is named "NAME.tmp.PID.XXXXXX" (PID: the writer's), so a cleaner can
// tell the files of dead writers from those being written (temp_file_writer_pid).
bool write_file_atomic(const std::filesystem::path& path, std::span<const std::uint8_t> bytes,
                       std::string& error);

// The writer's PID in the name of a write_file_atomic temp file ("NAME.tmp.PID.XXXXXX"),
// or 0 when the name is not one or holds no PID.
long temp_file_writer_pid(std::string_view filename);

} // namespace sherpa::core
