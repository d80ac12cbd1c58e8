#include "basisu_corpus.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace sherpa::test {

std::filesystem::path BasisCorpusFile::reference_rgb(unsigned level) const {
    const std::string format = payload == "uastc" ? "ASTC_RGBA_" : "ETC1_RGB_";
    return ktx2.parent_path() / name /
           (name + "_unpacked_rgb_" + format + std::to_string(level) + "_0_0000.png");
}

std::filesystem::path BasisCorpusFile::reference_alpha(unsigned level) const {
    const std::string l = std::to_string(level);
    if (payload == "uastc")
        return ktx2.parent_path() / name / (name + "_unpacked_a_ASTC_RGBA_" + l + "_0_0000.png");
    const std::string swapped = name + "_alpha_as_rgb";
    return ktx2.parent_path() / swapped / (swapped + "_unpacked_rgb_ETC1_RGB_" + l + "_0_0000.png");
}

std::filesystem::path basis_corpus_dir() {
    // SHERPA_BASISU_CORPUS: another corpus of the same layout (ad-hoc sweeps).
    if (const char* dir = std::getenv("SHERPA_BASISU_CORPUS")) return dir;
    return std::filesystem::path(SHERPA_BASISU_CACHE) / "corpus";
}

std::vector<BasisCorpusFile> basis_corpus(std::string& error) {
    const auto dir = basis_corpus_dir();
    std::ifstream manifest(dir / "manifest.txt");
    if (!manifest) {
        error = (dir / "manifest.txt").string() +
                " missing: run the basisu_corpus CTest fixture (tools/basisu/make_corpus.sh)";
        return {};
    }
    std::vector<BasisCorpusFile> files;
    for (std::string line; std::getline(manifest, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream row(line);
        BasisCorpusFile f;
        row >> f.name >> f.payload;
        f.ktx2 = dir / (f.name + ".ktx2");
        files.push_back(f);
    }
    return files;
}

} // namespace sherpa::test
