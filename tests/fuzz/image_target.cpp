// Image target: mutated PNG, JPEG and WebP files (tests/data/image_seeds, made by
// tools/images/make_fuzz_seeds.sh: RGBA, RGB, grey, 16-bit, progressive, lossy and
// lossless) through the engine's image path, tex::decode_encoded_image (and its
// header probe), as textures of a glTF reach it. Now and then the name hint names
// another format, as a file's wrong extension or mimeType would.
#include "image_target.h"

#include <algorithm>

#include <sherpa/core/file_io.h>
#include <sherpa/texture/image.h>

namespace sherpa::fuzz {

namespace fs = std::filesystem;

bool ImageTarget::init(const TargetConfig& config, std::string& error) {
    config_ = config;
    const fs::path dir = config.data_dir / "image_seeds";
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& f : fs::directory_iterator(dir, ec))
        if (f.path().extension() == ".png" || f.path().extension() == ".jpg" ||
            f.path().extension() == ".webp")
            files.push_back(f.path());
    std::sort(files.begin(), files.end()); // the same seed numbering on every machine
    // Not decoded here: the supervisor forks workers, and a decoder that started
    // threads in the parent would leave the children a pool without threads.
    for (const fs::path& file : files) {
        Seed seed{file.extension().string(), {}};
        if (!core::read_file(file, seed.bytes, error)) return false;
        seeds_.push_back(std::move(seed));
    }
    if (seeds_.empty()) {
        error = "no PNG/JPEG/WebP seeds in " + dir.string();
        return false;
    }
    fs::create_directories(config.work_dir);
    return true;
}

fs::path ImageTarget::make_case(Rng& rng) {
    const Seed& seed = seeds_[rng.below(seeds_.size())];
    bytes_ = seed.bytes;
    mutate_bytes(rng, bytes_, seeds_[rng.below(seeds_.size())].bytes, config_.max_size);
    const std::string& hint =
        rng.chance(16) ? seeds_[rng.below(seeds_.size())].extension : seed.extension;
    std::error_code ec;
    if (!case_path_.empty()) fs::remove(case_path_, ec);
    case_path_ = config_.work_dir / ("__case" + hint);
    write_case_file(case_path_, bytes_);
    return config_.work_dir;
}

std::optional<std::string> ImageTarget::run() {
    const std::string hint = case_path_.filename().string();
    std::string error;
    std::uint32_t w = 0, h = 0;
    const bool probed = tex::probe_encoded_image(bytes_, hint, error, &w, &h);
    if (!probed && error.empty()) return "probe_encoded_image refused the file without saying why";
    if (probed && config_.max_image_texels && std::uint64_t(w) * h > config_.max_image_texels)
        return std::nullopt; // --max-image-texels: header only
    tex::RgbaImage image;
    error.clear();
    if (!tex::decode_encoded_image(bytes_, hint, image, error)) {
        if (error.empty()) return "decode_encoded_image refused the file without saying why";
        return std::nullopt;
    }
    // Accepted: an image with exactly its pixels, of the size its header declares.
    if (image.empty()) return "decode_encoded_image accepted an image without pixels";
    if (image.pixels.size() != std::size_t(image.width) * image.height * 4)
        return "decode_encoded_image returned " + std::to_string(image.pixels.size()) +
               " bytes for " + std::to_string(image.width) + "x" + std::to_string(image.height);
    if (!probed || w != image.width || h != image.height)
        return "decode_encoded_image returned " + std::to_string(image.width) + "x" +
               std::to_string(image.height) + " where the header probe said " +
               (probed ? std::to_string(w) + "x" + std::to_string(h) : "no image");
    return std::nullopt;
}

} // namespace sherpa::fuzz
