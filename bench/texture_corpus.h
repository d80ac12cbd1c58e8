#pragma once
// The benchmark corpus: Sponza textures plus the DamagedHelmet maps, split into
// colour/data textures (BC7) and normal maps (BC5).
#include <filesystem>
#include <string>
#include <vector>

#include <sherpa/texture/image.h>

namespace sherpa::bench {

struct CorpusTexture {
    std::string name;
    tex::RgbaImage image;
};

struct Corpus {
    std::vector<CorpusTexture> color;  // opaque colour/data maps (BC7, RGB PSNR)
    std::vector<CorpusTexture> alpha;  // maps with alpha (BC7, RGBA PSNR)
    std::vector<CorpusTexture> normal; // normal maps (BC5)
};

// Loads up to `per_set` textures of each kind (all alpha maps: there are few) from assets_dir.
// Sponza maps are classified as normal maps by content (blue-dominant, red and green centred);
// DamagedHelmet's Default_normal.jpg is a normal map, its other maps are colour.
// Order is deterministic (sorted names, DamagedHelmet last).
Corpus load_corpus(const std::filesystem::path& assets_dir, std::size_t per_set);

} // namespace sherpa::bench
