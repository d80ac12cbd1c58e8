#pragma once
// Internal: how the importer touches the filesystem. Every path a glTF file names
// (its buffers' and images' URIs) and the SCENE path itself go through these, so a
// directory, FIFO or device is refused with a message instead of being read: a
// directory made tinygltf ask for 2^63 bytes (bad_alloc), a FIFO blocks forever.
#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace sherpa::scene::detail {

// Reads a whole regular file. On failure returns false and sets `error` to the
// problem in words, without the path ("is a directory, not a file", "cannot open:
// No such file or directory"). Never blocks on a FIFO.
bool read_regular_file(const std::string& path, std::vector<std::uint8_t>& out, std::string& error);

// tinygltf callbacks that read through read_regular_file and expand nothing.
tinygltf::FsCallbacks safe_fs_callbacks();

} // namespace sherpa::scene::detail
