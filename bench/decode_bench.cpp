// BC7 decode throughput: reference per-block decoder vs decode_image's fast path.
#include "decode_bench.h"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include <sherpa/texture/block_codecs.h>
#include <sherpa/texture/image.h>

namespace sherpa::bench {

namespace {

double wall_ms() {
    return std::chrono::duration<double, std::milli>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

struct Encoded {
    std::string name;
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint8_t> blocks;
};

// decode_image as it was before the fast path.
std::vector<std::uint8_t> reference_decode(const Encoded& e) {
    return tex::decode_image_per_block(tex::BlockFormat::Bc7, e.blocks, e.width, e.height);
}

} // namespace

int run_decode_bench(const std::filesystem::path& assets, int threads) {
    const auto dir = assets / "gltf/DamagedHelmet/glTF";
    std::vector<Encoded> set;
    double mpix = 0;
    int modes[9] = {};
    for (const char* name : {"Default_albedo.jpg", "Default_emissive.jpg",
                             "Default_metalRoughness.jpg", "Default_normal.jpg"}) {
        tex::RgbaImage img;
        std::string error;
        if (!tex::read_image_file(dir / name, img, error)) {
            std::fprintf(stderr, "decode bench: %s\n", error.c_str());
            return 2;
        }
        Encoded e{name, img.width, img.height,
                  tex::encode_image(tex::BlockFormat::Bc7, img.pixels, img.width, img.height,
                                    {tex::kBc7DefaultLevel, tex::best_simd_level()}, 0)};
        for (std::size_t b = 0; b < e.blocks.size(); b += tex::kBlockBytes)
            ++modes[e.blocks[b] ? __builtin_ctz(e.blocks[b]) : 8];
        mpix += double(img.width) * img.height / 1e6;
        set.push_back(std::move(e));
    }
    std::fprintf(stderr, "decode bench: %zu BC7 textures, %.2f MPix; block modes 0-7:", set.size(),
                 mpix);
    for (int m = 0; m < 8; ++m) std::fprintf(stderr, " %d", modes[m]);
    std::fprintf(stderr, "\n");

    constexpr int kReps = 3;
    // What every row must reproduce, decoded once.
    std::vector<std::vector<std::uint8_t>> expected;
    for (const Encoded& e : set) expected.push_back(reference_decode(e));
    bool identical = true;
    auto row = [&](const char* label, bool wall, auto&& decode) {
        std::vector<std::vector<std::uint8_t>> out(set.size());
        const double start = wall ? wall_ms() : cpu_ms();
        for (int r = 0; r < kReps; ++r)
            for (std::size_t i = 0; i < set.size(); ++i) out[i] = decode(set[i]);
        const double ms = (wall ? wall_ms() : cpu_ms()) - start;
        for (std::size_t i = 0; i < set.size(); ++i) identical = identical && out[i] == expected[i];
        std::printf("| %s | %.1f | %.1f |\n", label, ms / kReps, mpix * kReps / (ms / 1e3));
    };
    std::printf("| BC7 decode, DamagedHelmet 4 x 2048^2 | ms per set | MPix/s |\n|---|---|---|\n");
    row("reference decode_bc7_block + copy, 1 thread (CPU time)", false, reference_decode);
    row("decode_image, 1 thread (CPU time)", false, [](const Encoded& e) {
        return tex::decode_image(tex::BlockFormat::Bc7, e.blocks, e.width, e.height, 1);
    });
    if (threads != 1)
        row(threads > 1 ? "decode_image, --threads (wall time)"
                        : "decode_image, OpenMP default threads (wall time)",
            true, [threads](const Encoded& e) {
                return tex::decode_image(tex::BlockFormat::Bc7, e.blocks, e.width, e.height,
                                         threads);
            });
    if (!identical) std::fprintf(stderr, "decode bench: decoders disagree\n");
    return identical ? 0 : 1;
}

} // namespace sherpa::bench
