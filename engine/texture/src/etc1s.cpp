// ETC1S / BasisLZ payloads.
#include "ktx2_basis.h"

namespace sherpa::tex {

bool decode_etc1s_levels(const Ktx2BasisFile&, std::vector<RgbaImage>&, std::string& error) {
    error = "ETC1S/BasisLZ payloads are not supported yet";
    return false;
}

} // namespace sherpa::tex
