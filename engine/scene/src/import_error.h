#pragma once
// Internal: the importer reports failures by throwing ImportError with a message
// that names the JSON path of the offending element; import_gltf() catches it,
// prefixes the file name and discards the partially built scene.
#include <stdexcept>
#include <string>

namespace sherpa::detail {

struct ImportError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

[[noreturn]] inline void fail(const std::string& message) {
    throw ImportError(message);
}

} // namespace sherpa::detail
