// sherpa-texture-sweep: encodes the corpus at every quality level and reports
// speed (ms per megapixel, single thread unless --threads) against quality
// (PSNR; mean normal-angle error for BC5). Writes CSV for docs/textures/.
// --decode instead times BC7 decoding of the DamagedHelmet maps (see decode_bench.h).
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include <sherpa/texture/block_codecs.h>
#include <sherpa/texture/quality.h>

#include "decode_bench.h"
#include "texture_corpus.h"

using namespace sherpa;
using bench::cpu_ms;

namespace {

struct Options {
    std::filesystem::path assets = SHERPA_DEFAULT_ASSETS_DIR;
    std::size_t textures = 13;
    int threads = 1;
    tex::SimdLevel simd = tex::best_simd_level();
    std::string csv;
    std::string only;   // "bc7", "bc5" or "" for both
    int max_level = 99; // highest level swept
    bool decode = false;
};

struct Row {
    std::string kind; // bc7-rgb, bc7-rgba, bc5
    int level = 0;
    std::size_t textures = 0;
    double mpix = 0, ms = 0, psnr_sum = 0, angle_sum = 0, angle_rgb_sum = 0;
    tex::SquaredError pooled; // all texels of all textures together
};

Row measure(const std::vector<bench::CorpusTexture>& set, tex::BlockFormat format, int level,
            const std::string& kind, const Options& opt) {
    Row row;
    row.kind = kind, row.level = level, row.textures = set.size();
    const unsigned channels = kind == "bc7-rgba" ? tex::kChannelsRgba
                              : kind == "bc5"    ? tex::kChannelsRg
                                                 : tex::kChannelsRgb;
    for (const auto& t : set) {
        // CPU time of the process, not wall time: the machine is shared, and the
        // figure wanted is the cost per core. With --threads > 1 it sums all threads.
        const double start = cpu_ms();
        const auto blocks = tex::encode_image(format, t.image.pixels, t.image.width, t.image.height,
                                              {level, opt.simd}, opt.threads);
        const double ms = cpu_ms() - start;
        const auto decoded = tex::decode_image(format, blocks, t.image.width, t.image.height);
        const tex::SquaredError err = tex::squared_error(t.image.pixels, decoded, channels);
        const double psnr = err.psnr();
        row.pooled += err;
        row.mpix += double(t.image.width) * t.image.height / 1e6;
        row.ms += ms;
        row.psnr_sum += psnr;
        if (format == tex::BlockFormat::Bc5) {
            row.angle_sum += tex::normal_angle_error(t.image.pixels, decoded).mean();
            row.angle_rgb_sum += tex::normal_angle_error_vs_rgb(t.image.pixels, decoded).mean();
        }
        std::fprintf(stderr, "  %s L%d %-28s %7.1f ms/MPix %6.2f dB\n", kind.c_str(), level,
                     t.name.c_str(), ms / (double(t.image.width) * t.image.height / 1e6), psnr);
    }
    return row;
}

} // namespace

int main(int argc, char** argv) {
    Options opt;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
            return argv[++i];
        };
        if (a == "--assets")
            opt.assets = next();
        else if (a == "--textures")
            opt.textures = std::stoul(next());
        else if (a == "--threads")
            opt.threads = std::stoi(next());
        else if (a == "--csv")
            opt.csv = next();
        else if (a == "--only")
            opt.only = next();
        else if (a == "--decode")
            opt.decode = true;
        else if (a == "--max-level")
            opt.max_level = std::stoi(next());
        else if (a == "--simd") {
            const std::string s = next();
            opt.simd = s == "scalar" ? tex::SimdLevel::Scalar
                       : s == "avx2" ? tex::SimdLevel::Avx2
                                     : tex::SimdLevel::Avx512;
        } else {
            std::cerr
                << "usage: sherpa-texture-sweep [--assets DIR] [--textures N] [--threads N]"
                   " [--simd scalar|avx2|avx512] [--only bc7|bc5] [--max-level N] [--csv FILE]"
                   " [--decode]\n";
            return a == "--help" ? 0 : 2;
        }
    }
    if (opt.decode) return bench::run_decode_bench(opt.assets, opt.threads);
    const bench::Corpus corpus = bench::load_corpus(opt.assets, opt.textures);
    std::fprintf(stderr, "corpus: %zu colour, %zu alpha, %zu normal maps; simd %s, %d thread(s)\n",
                 corpus.color.size(), corpus.alpha.size(), corpus.normal.size(),
                 std::string(tex::to_string(std::min(opt.simd, tex::best_simd_level()))).c_str(),
                 opt.threads);
    std::vector<Row> rows;
    if (opt.only != "bc5")
        for (int level = tex::kBc7MinLevel; level <= std::min(tex::kBc7MaxLevel, opt.max_level);
             ++level) {
            rows.push_back(measure(corpus.color, tex::BlockFormat::Bc7, level, "bc7-rgb", opt));
            rows.push_back(measure(corpus.alpha, tex::BlockFormat::Bc7, level, "bc7-rgba", opt));
        }
    if (opt.only != "bc7")
        for (int level = tex::kBc5MinLevel; level <= tex::kBc5MaxLevel; ++level)
            rows.push_back(measure(corpus.normal, tex::BlockFormat::Bc5, level, "bc5", opt));

    std::ostringstream csv;
    csv << "kind,level,textures,mpix,ms_per_mpix,psnr_db,pooled_psnr_db,mean_angle_deg,mean_angle_"
           "vs_rgb_deg\n";
    std::printf(
        "| kind | level | textures | ms/MPix | mean PSNR dB | pooled PSNR dB | mean angle deg "
        "| mean angle vs source RGB deg |\n|---|---|---|---|---|---|---|---|\n");
    for (const Row& r : rows) {
        const double n = double(r.textures ? r.textures : 1);
        const double ms_per_mpix = r.mpix > 0 ? r.ms / r.mpix : 0.0;
        const bool bc5 = r.kind == "bc5";
        char line[256];
        std::snprintf(line, sizeof line, "%s,%d,%zu,%.3f,%.2f,%.3f,%.3f,%.3f,%.3f\n",
                      r.kind.c_str(), r.level, r.textures, r.mpix, ms_per_mpix, r.psnr_sum / n,
                      r.pooled.psnr(), r.angle_sum / n, r.angle_rgb_sum / n);
        csv << line;
        char angles[64] = "- | -";
        if (bc5)
            std::snprintf(angles, sizeof angles, "%.3f | %.3f", r.angle_sum / n,
                          r.angle_rgb_sum / n);
        std::printf("| %s | %d | %zu | %.1f | %.2f | %.2f | %s |\n", r.kind.c_str(), r.level,
                    r.textures, ms_per_mpix, r.psnr_sum / n, r.pooled.psnr(), angles);
    }
    if (!opt.csv.empty()) {
        std::ofstream(opt.csv) << csv.str();
        std::fprintf(stderr, "wrote %s\n", opt.csv.c_str());
    }
    return 0;
}
