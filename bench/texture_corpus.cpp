#include "texture_corpus.h"

#include <algorithm>
#include <iostream>

namespace sherpa::bench {

namespace {
bool looks_like_normal_map(const tex::RgbaImage& img) {
    double sum[3] = {0, 0, 0};
    const std::size_t texels = std::size_t{img.width} * img.height;
    for (std::size_t i = 0; i < texels; ++i)
        for (int c = 0; c < 3; ++c) sum[c] += img.pixels[i * 4 + c];
    const double r = sum[0] / texels, g = sum[1] / texels, b = sum[2] / texels;
    return b > 180.0 && std::abs(r - 128.0) < 30.0 && std::abs(g - 128.0) < 30.0;
}
} // namespace

Corpus load_corpus(const std::filesystem::path& assets_dir, std::size_t per_set) {
    Corpus corpus;
    std::vector<std::filesystem::path> sponza;
    for (const auto& e : std::filesystem::directory_iterator(assets_dir / "textures/sponza")) {
        const auto ext = e.path().extension();
        if (ext == ".jpg" || ext == ".png") sponza.push_back(e.path());
    }
    std::sort(sponza.begin(), sponza.end());
    const std::filesystem::path helmet = assets_dir / "gltf/DamagedHelmet/glTF";
    // DamagedHelmet first so that small sets still include its 2048^2 maps.
    std::vector<std::filesystem::path> files = {
        helmet / "Default_albedo.jpg", helmet / "Default_emissive.jpg",
        helmet / "Default_metalRoughness.jpg", helmet / "Default_normal.jpg"};
    files.insert(files.end(), sponza.begin(), sponza.end());
    for (const auto& path : files) {
        CorpusTexture t{path.filename().string(), {}};
        std::string error;
        if (!tex::read_image_file(path, t.image, error)) {
            std::cerr << "corpus: skipping " << error << "\n";
            continue;
        }
        if (t.image.width < 64) continue; // placeholder textures (white.png) say nothing
        const bool normal =
            path.filename() == "Default_normal.jpg" ||
            (path.parent_path().filename() == "sponza" && looks_like_normal_map(t.image));
        auto& set = normal ? corpus.normal : t.image.has_alpha() ? corpus.alpha : corpus.color;
        if (set.size() < per_set || &set == &corpus.alpha) set.push_back(std::move(t));
    }
    return corpus;
}

} // namespace sherpa::bench
