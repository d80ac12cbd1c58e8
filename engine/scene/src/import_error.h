#pragma once
// Internal: the importer reports failures by throwing ImportError with a message
// that names the JSON path of the offending element; import_gltf() catches it,
// prefixes the file name and discards the partially built scene.
#include <cstdio>
#include <stdexcept>
#include <string>

namespace sherpa::scene::detail {

struct ImportError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

[[noreturn]] inline void fail(const std::string& message) {
    throw ImportError(message);
}

// A number as a user reads it in a message ("1e+30", "0.5"), not std::to_string's
// fixed six decimals.
inline std::string number_text(double v) {
    char text[32];
    std::snprintf(text, sizeof(text), "%g", v);
    return text;
}

} // namespace sherpa::scene::detail
