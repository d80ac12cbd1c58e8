// Importer targets: mutated .gltf (with mutated .bin buffers) and .glb files through
// import_gltf, and the same with tangents regenerated for every triangle mesh.
#include "gltf_targets.h"

#include <algorithm>
#include <cstring>

#include <sherpa/core/file_io.h>
#include <sherpa/scene/scene_loader.h>

#include "gltf_validate.h" // engine/scene/src: the importer's own depth scan

namespace sherpa::fuzz {

namespace fs = std::filesystem;

namespace {

std::vector<std::uint8_t> read_all(const fs::path& path) {
    std::vector<std::uint8_t> bytes;
    std::string error;
    if (!core::read_file(path, bytes, error)) bytes.clear();
    return bytes;
}

std::vector<std::uint8_t> as_bytes(const std::string& s) {
    return {s.begin(), s.end()};
}

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(std::uint8_t(v >> (8 * i)));
}

} // namespace

std::vector<std::uint8_t> make_glb(const std::string& json, std::span<const std::uint8_t> bin) {
    std::string j = json;
    while (j.size() % 4) j += ' ';
    std::vector<std::uint8_t> b(bin.begin(), bin.end());
    while (b.size() % 4) b.push_back(0);
    std::vector<std::uint8_t> out;
    put_u32(out, 0x46546C67); // "glTF"
    put_u32(out, 2);
    put_u32(out, std::uint32_t(12 + 8 + j.size() + (bin.empty() ? 0 : 8 + b.size())));
    put_u32(out, std::uint32_t(j.size()));
    put_u32(out, 0x4E4F534A); // "JSON"
    out.insert(out.end(), j.begin(), j.end());
    if (!bin.empty()) {
        put_u32(out, std::uint32_t(b.size()));
        put_u32(out, 0x004E4942); // "BIN\0"
        out.insert(out.end(), b.begin(), b.end());
    }
    return out;
}

bool split_glb(std::span<const std::uint8_t> glb, std::string& json,
               std::vector<std::uint8_t>& bin) {
    auto u32 = [&](std::size_t at) {
        std::uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= std::uint32_t(glb[at + i]) << (8 * i);
        return v;
    };
    if (glb.size() < 20 || u32(0) != 0x46546C67 || u32(16) != 0x4E4F534A) return false;
    const std::size_t json_size = u32(12);
    if (json_size > glb.size() - 20) return false;
    json.assign(reinterpret_cast<const char*>(glb.data()) + 20, json_size);
    bin.clear();
    const std::size_t at = 20 + json_size;
    if (glb.size() - at >= 8 && u32(at + 4) == 0x004E4942) {
        const std::size_t size = std::min<std::size_t>(u32(at), glb.size() - at - 8);
        bin.assign(glb.begin() + std::ptrdiff_t(at + 8),
                   glb.begin() + std::ptrdiff_t(at + 8 + size));
    }
    return true;
}

bool GltfTarget::init(const TargetConfig& config, std::string& error) {
    config_ = config;
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& model : fs::directory_iterator(config.assets_dir / "gltf", ec))
        for (const auto& f : fs::directory_iterator(model.path() / "glTF", ec))
            if (f.path().extension() == ".gltf") files.push_back(f.path());
    for (const auto& f : fs::directory_iterator(config.data_dir, ec))
        if (f.path().extension() == ".gltf" || f.path().extension() == ".glb")
            files.push_back(f.path());
    std::sort(files.begin(), files.end()); // the same seed numbering on every machine
    for (const fs::path& file : files) {
        Seed seed;
        seed.source = file;
        seed.text = read_all(file);
        if (seed.text.empty() || seed.text.size() > config.max_size) continue;
        // Seeds nesting deeper than the importer parses are mutated as bytes only:
        // copying their parsed document recurses once per level and overflowed the
        // stack under AddressSanitizer (tests/data/deep_nesting.gltf).
        if (scene::detail::json_depth_exceeded_at(seed.text, scene::detail::kMaxJsonDepth) ==
            SIZE_MAX)
            seed.doc = nlohmann::json::parse(seed.text.begin(), seed.text.end(), nullptr, false);
        if (seed.doc.is_object() && seed.doc["buffers"].is_array())
            for (const auto& buffer : seed.doc["buffers"]) {
                const std::string uri = buffer.value("uri", std::string());
                std::vector<std::uint8_t> bin;
                if (!uri.empty() && uri.rfind("data:", 0) != 0)
                    bin = read_all(file.parent_path() / uri);
                seed.bins.push_back(bin.size() <= config.max_size ? bin
                                                                  : std::vector<std::uint8_t>());
            }
        // Every file beside the seed, linked into the case directory, so the case's
        // relative URIs (images, untouched buffers) resolve as the seed's do.
        seed.case_dir = config.work_dir / ("seed" + std::to_string(seeds_.size()));
        fs::create_directories(seed.case_dir);
        for (const auto& sibling : fs::directory_iterator(file.parent_path(), ec)) {
            const fs::path link = seed.case_dir / sibling.path().filename();
            if (!fs::exists(fs::symlink_status(link))) fs::create_symlink(sibling.path(), link, ec);
        }
        std::size_t total = seed.text.size();
        for (const auto& bin : seed.bins) total += bin.size();
        if (total > config.max_seed_size) continue;
        if (!add_seed(std::move(seed))) continue;
    }
    if (seeds_.empty()) error = "no glTF seeds under " + config.assets_dir.string();
    return !seeds_.empty();
}

bool GltfTarget::add_seed(Seed seed) {
    if (seed.source.extension() != ".gltf") return false;
    seeds_.push_back(std::move(seed));
    return true;
}

fs::path GltfTarget::make_case(Rng& rng) {
    const Seed& seed = seeds_[rng.below(seeds_.size())];
    for (const fs::path& f : written_) fs::remove(f);
    written_.clear();
    std::vector<std::uint8_t> text;
    if (seed.doc.is_object() && !rng.chance(4)) {
        nlohmann::json doc = seed.doc;
        for (std::size_t j = 0; j < seed.bins.size(); ++j) {
            if (seed.bins[j].empty() || !rng.chance(3)) continue;
            std::vector<std::uint8_t> bin = seed.bins[j];
            mutate_bytes(rng, bin, {}, config_.max_size);
            const std::string name = "__case_" + std::to_string(j) + ".bin";
            write_case_file(seed.case_dir / name, bin);
            written_.push_back(seed.case_dir / name);
            doc["buffers"][j]["uri"] = name;
        }
        if (written_.empty() || !rng.chance(2)) mutate_json(rng, doc);
        text = as_bytes(dump_json(doc));
        if (rng.chance(8)) mutate_bytes(rng, text, seed.text, config_.max_size, 2);
    } else {
        text = seed.text;
        mutate_bytes(rng, text, seeds_[rng.below(seeds_.size())].text, config_.max_size);
    }
    return write_case(seed, "__case.gltf", text);
}

fs::path GltfTarget::write_case(const Seed& seed, const std::string& name,
                                std::span<const std::uint8_t> bytes) {
    case_path_ = seed.case_dir / name;
    write_case_file(case_path_, bytes);
    written_.push_back(case_path_);
    return seed.case_dir;
}

std::optional<std::string> GltfTarget::run() {
    return load(scene::LoadOptions{});
}

std::optional<std::string> GltfTarget::load(const scene::LoadOptions& options) {
    const scene::LoadResult result = scene::import_gltf(case_path_.string(), options);
    if (!result) return std::nullopt; // a refusal with a message is a correct outcome
    // A loaded scene must be safe to draw: every index names a vertex.
    for (std::size_t m = 0; m < result.scene->meshes.size(); ++m) {
        const scene::Mesh& mesh = result.scene->meshes[m];
        for (const std::uint32_t index : mesh.indices)
            if (index >= mesh.vertices.size())
                return "mesh " + std::to_string(m) + ": index " + std::to_string(index) +
                       " >= vertex count " + std::to_string(mesh.vertices.size());
        // Indices are lists of the mesh's topology (strips, loops and fans arrive
        // converted): 3 per triangle, 2 per line, 1 per point.
        const std::uint32_t per = scene::indices_per_element(mesh.topology());
        if (mesh.indices.size() % per)
            return "mesh " + std::to_string(m) + ": " + std::to_string(mesh.indices.size()) +
                   " indices are not a multiple of " + std::to_string(per) + " (" +
                   std::string(to_string(mesh.topology())) + ")";
    }
    return std::nullopt;
}

bool GlbTarget::add_seed(Seed seed) {
    // .glb files as they are, and every .gltf with at most one buffer converted to one.
    if (seed.source.extension() == ".glb") {
        seed.doc = nullptr;
        seeds_.push_back(std::move(seed));
        return true;
    }
    if (!seed.doc.is_object() || seed.bins.size() > 1) return false;
    std::vector<std::uint8_t> bin;
    if (seed.bins.size() == 1) {
        if (seed.bins[0].empty()) return false;
        bin = seed.bins[0];
        seed.doc["buffers"][0].erase("uri");
        seed.doc["buffers"][0]["byteLength"] = bin.size();
    }
    seed.text = make_glb(seed.doc.dump(), bin);
    seed.bins = {bin};
    seeds_.push_back(std::move(seed));
    return true;
}

fs::path GlbTarget::make_case(Rng& rng) {
    const Seed& seed = seeds_[rng.below(seeds_.size())];
    written_.clear();
    std::vector<std::uint8_t> bytes;
    if (seed.doc.is_object() && rng.chance(2)) { // rebuilt with consistent chunk lengths
        nlohmann::json doc = seed.doc;
        std::vector<std::uint8_t> bin =
            seed.bins.empty() ? std::vector<std::uint8_t>() : seed.bins[0];
        if (!bin.empty() && rng.chance(3))
            mutate_bytes(rng, bin, {}, config_.max_size);
        else
            mutate_json(rng, doc);
        bytes = make_glb(dump_json(doc), bin);
    } else {
        bytes = seed.text;
        mutate_bytes(rng, bytes, seeds_[rng.below(seeds_.size())].text, config_.max_size);
    }
    return write_case(seed, "__case.glb", bytes);
}

fs::path TangentsTarget::make_case(Rng& rng) {
    method_ = scene::kAllTangentMethods[rng.below(scene::kAllTangentMethods.size())];
    return GltfTarget::make_case(rng);
}

std::optional<std::string> TangentsTarget::run() {
    scene::LoadOptions options;
    options.tangents.regenerate = true; // every triangle mesh, not only normal-mapped ones
    options.tangents.method = method_;
    return load(options);
}

} // namespace sherpa::fuzz
