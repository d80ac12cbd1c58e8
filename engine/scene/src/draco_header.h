#pragma once
// Internal: the counts a Draco mesh stream declares before its data, read from the
// bytes without the decoder. Draco 1.5.5 checks a sequential stream's counts against
// its bytes (faces <= bytes / 3, points <= 3 x faces), but an Edgebreaker stream's
// only against each other (vertices <= 3 x faces, faces <= 4/3 x symbols): it sizes
// its corner table by the faces before it reads the symbols, so 138 bytes can ask for
// gigabytes. gltf_draco.cpp bounds these counts by the glTF accessors and documented
// limits before the stream reaches the decoder.
//
// The layout follows Draco's decoders (bitstream versions 1.0-2.2): the header
// ("DRACO", major, minor, geometry type, method, uint16 flags), the geometry metadata
// when flag 0x8000 is set (version 1.3 on), then the connectivity header of the
// sequential or Edgebreaker method. Counts are little-endian uint32 before 2.2
// (sequential) or 2.0 (Edgebreaker), LEB128 varints from then on.
#include <cstdint>
#include <span>
#include <string>

namespace sherpa::scene::detail {

enum class DracoMethod : std::uint8_t { Sequential = 0, Edgebreaker = 1 };

struct DracoCounts {
    std::uint8_t version_major = 0, version_minor = 0;
    DracoMethod method = DracoMethod::Sequential;
    std::uint32_t faces = 0;
    // Sequential: the stream's point count (what the decoded mesh has).
    std::uint32_t points = 0;
    // Edgebreaker: the connectivity's vertices (the decoded points are at least
    // these), and its attribute connectivities (a corner table each, one per
    // attribute other than position at most).
    std::uint32_t encoded_vertices = 0;
    std::uint8_t attribute_data = 0;
};

// The counts of a Draco triangle-mesh stream. False, with `error` saying what, for a
// stream that is not a Draco mesh of a version Draco 1.5.5 decodes, or whose header
// is cut short or malformed (the decoder would refuse it too).
bool read_draco_counts(std::span<const std::uint8_t> stream, DracoCounts& counts,
                       std::string& error);

} // namespace sherpa::scene::detail
