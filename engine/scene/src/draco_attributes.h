#pragma once
// Internal: one decoded Draco attribute written in the component type its glTF
// accessor declares (JOINTS stay integers, normalized colours and UVs stay
// normalized integers, dequantized positions stay floats), so the importer reads a
// Draco primitive exactly as it reads the same primitive stored uncompressed.
#include <cstddef>
#include <string>
#include <vector>

namespace draco {
class PointAttribute;
}

namespace sherpa::scene::detail {

// Appends each of `points` points' value of `att` (through Draco's point-to-value
// map) to `data` as `comps` components of `component_type`, each row padded to a
// multiple of 4 bytes (glTF's vertex attribute alignment). Returns the row stride.
// Conversions: integer to integer keeps the value (one outside the accessor's type
// fails); float to a normalized integer rounds v * max; float to a plain integer
// must be integral; integer to float divides by the Draco type's maximum when Draco
// marks the attribute normalized. Throws ImportError naming `where` on a value the
// accessor's type cannot hold, or a point Draco maps past its values.
std::size_t append_draco_attribute(const draco::PointAttribute& att, std::size_t points, int comps,
                                   int component_type, bool normalized,
                                   std::vector<unsigned char>& data, const std::string& where);

} // namespace sherpa::scene::detail
