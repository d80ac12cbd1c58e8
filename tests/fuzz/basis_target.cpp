// Basis Universal target: mutated KTX2 files with ETC1S/BasisLZ and UASTC payloads
// (raw and Zstandard) through transcode_ktx2_basis, our own transcoder. The seeds are
// tiny files made by the reference encoder (tools/basisu/make_fuzz_seeds.sh), so
// that most mutations land in the structures the transcoder walks: level index,
// supercompression global data, BasisLZ codebooks and Huffman tables, slice data.
#include "basis_target.h"

#include <algorithm>

#include <sherpa/core/file_io.h>
#include <sherpa/texture/ktx2.h>

namespace sherpa::fuzz {

namespace fs = std::filesystem;

bool BasisTarget::init(const TargetConfig& config, std::string& error) {
    config_ = config;
    const fs::path dir = config.data_dir / "basis_seeds";
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& f : fs::directory_iterator(dir, ec))
        if (f.path().extension() == ".ktx2") files.push_back(f.path());
    std::sort(files.begin(), files.end()); // the same seed numbering on every machine
    for (const fs::path& file : files) {
        std::vector<std::uint8_t> bytes;
        if (!core::read_file(file, bytes, error)) return false;
        // A seed the transcoder refuses would make every case a refusal: say so.
        tex::BasisTexture texture;
        if (!tex::transcode_ktx2_basis(bytes, texture, error)) {
            error = file.string() + ": seed does not transcode: " + error;
            return false;
        }
        seeds_.push_back(std::move(bytes));
    }
    if (seeds_.empty()) {
        error = "no Basis KTX2 seeds in " + dir.string();
        return false;
    }
    fs::create_directories(config.work_dir);
    return true;
}

std::optional<std::string> BasisTarget::run() {
    tex::BasisTexture texture;
    std::string error;
    if (!tex::transcode_ktx2_basis(bytes_, texture, error)) {
        if (error.empty()) return "transcode_ktx2_basis refused the file without saying why";
        return std::nullopt;
    }
    // Accepted: a full-size level 0 and a chain of halving levels, each with exactly
    // the pixels its extent needs.
    if (texture.levels.empty() || texture.levels[0].empty())
        return "transcode_ktx2_basis accepted a texture without an image";
    const tex::RgbaImage& base = texture.levels[0];
    for (std::uint32_t l = 0; l < texture.levels.size(); ++l) {
        const tex::RgbaImage& level = texture.levels[l];
        if (level.width != tex::mip_extent(base.width, l) ||
            level.height != tex::mip_extent(base.height, l))
            return "transcode_ktx2_basis returned level " + std::to_string(l) + " of " +
                   std::to_string(level.width) + "x" + std::to_string(level.height);
        if (level.pixels.size() != std::size_t(level.width) * level.height * 4)
            return "transcode_ktx2_basis returned level " + std::to_string(l) +
                   " with the wrong number of pixel bytes";
    }
    return std::nullopt;
}

} // namespace sherpa::fuzz
