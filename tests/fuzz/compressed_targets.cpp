// Compressed-geometry targets: GLB files made by gltfpack (EXT_/KHR_meshopt_compression,
// with the ATTRIBUTES/TRIANGLES/INDICES modes and the OCTAHEDRAL, QUATERNION and
// EXPONENTIAL filters) and gltf-transform (KHR_draco_mesh_compression), committed as
// seeds by tools/gltf_compress/make_fuzz_seeds.sh. Most cases mutate the compressed
// streams in place (the decoders' input) or the extension objects that say how to
// read them (counts, strides, offsets, modes, filters, attribute ids); the rest mutate
// the whole document or the GLB's bytes. The oracle is the importer targets'.
#include "compressed_targets.h"

#include <algorithm>

#include <sherpa/core/file_io.h>

namespace sherpa::fuzz {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::size_t as_size(const json& v) {
    return v.is_number_unsigned() ? v.get<std::size_t>() : 0;
}

} // namespace

bool CompressedTarget::init(const TargetConfig& config, std::string& error) {
    config_ = config;
    const fs::path dir = config.data_dir / "compressed_seeds";
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& f : fs::directory_iterator(dir, ec))
        if (f.path().extension() == ".glb") files.push_back(f.path());
    std::sort(files.begin(), files.end()); // the same seed numbering on every machine
    for (const fs::path& file : files) {
        Seed seed;
        seed.source = file;
        if (!core::read_file(file, seed.text, error)) return false;
        std::string text;
        std::vector<std::uint8_t> bin;
        if (!split_glb(seed.text, text, bin)) {
            error = file.string() + ": not a GLB";
            return false;
        }
        seed.doc = json::parse(text, nullptr, false);
        const json used =
            seed.doc.is_object() ? seed.doc.value("extensionsUsed", json::array()) : json::array();
        if (std::none_of(extensions_.begin(), extensions_.end(), [&](const std::string& e) {
                return std::find(used.begin(), used.end(), e) != used.end();
            }))
            continue;
        std::vector<Payload> streams = payloads(seed.doc);
        std::erase_if(streams, [&](const Payload& p) {
            return p.length == 0 || p.offset > bin.size() || p.length > bin.size() - p.offset;
        });
        if (streams.empty()) {
            error = file.string() + ": no compressed stream inside its BIN chunk";
            return false;
        }
        seed.bins = {std::move(bin)};
        seed.case_dir = config.work_dir / ("seed" + std::to_string(seeds_.size()));
        fs::create_directories(seed.case_dir);
        seeds_.push_back(std::move(seed));
        payloads_.push_back(std::move(streams));
    }
    if (seeds_.empty()) error = "no " + name() + " seeds in " + dir.string();
    return !seeds_.empty();
}

fs::path CompressedTarget::make_case(Rng& rng) {
    const std::size_t s = rng.below(seeds_.size());
    const Seed& seed = seeds_[s];
    const std::vector<Payload>& streams = payloads_[s];
    written_.clear();
    json doc = seed.doc;
    std::vector<std::uint8_t> bin = seed.bins[0];
    const std::size_t mode = rng.below(16);
    if (mode < 8) {
        // Inside one stream, its length kept: what the decoder reads. Now and then the
        // stream is also declared shorter (a truncated stream).
        const Payload& p = streams[rng.below(streams.size())];
        const Payload& other = streams[rng.below(streams.size())];
        std::vector<std::uint8_t> stream(bin.begin() + std::ptrdiff_t(p.offset),
                                         bin.begin() + std::ptrdiff_t(p.offset + p.length));
        mutate_bytes(rng, stream,
                     std::span<const std::uint8_t>(bin).subspan(other.offset, other.length),
                     p.length);
        const std::size_t kept = stream.size();
        stream.resize(p.length, 0);
        std::copy(stream.begin(), stream.end(), bin.begin() + std::ptrdiff_t(p.offset));
        if (kept < p.length && rng.chance(4) && doc.contains(p.extension)) {
            json& ext = doc[p.extension];
            if (ext.contains("byteLength")) ext["byteLength"] = kept; // meshopt
        }
    } else if (mode < 12) {
        // The extension object: counts, strides, offsets, modes, filters, ids.
        const Payload& p = streams[rng.below(streams.size())];
        if (doc.contains(p.extension)) mutate_json(rng, doc[p.extension], 2);
    } else if (mode < 14) {
        mutate_json(rng, doc);
    } else {
        std::vector<std::uint8_t> bytes = seed.text;
        mutate_bytes(rng, bytes, seeds_[rng.below(seeds_.size())].text, config_.max_size);
        return write_case(seed, "__case.glb", bytes);
    }
    return write_case(seed, "__case.glb", make_glb(dump_json(doc), bin));
}

std::vector<CompressedTarget::Payload> MeshoptTarget::payloads(const json& doc) const {
    std::vector<Payload> out;
    const json views = doc.value("bufferViews", json::array());
    for (std::size_t v = 0; v < views.size(); ++v)
        for (const char* codec : {"EXT_meshopt_compression", "KHR_meshopt_compression"}) {
            if (!views[v].contains("extensions") || !views[v]["extensions"].contains(codec))
                continue;
            const json& ext = views[v]["extensions"][codec];
            if (as_size(ext.value("buffer", json())) != 0) continue; // the GLB's BIN only
            out.push_back(
                {json::json_pointer("/bufferViews/" + std::to_string(v) + "/extensions/" + codec),
                 as_size(ext.value("byteOffset", json(0u))),
                 as_size(ext.value("byteLength", json()))});
        }
    return out;
}

std::vector<CompressedTarget::Payload> DracoTarget::payloads(const json& doc) const {
    std::vector<Payload> out;
    const json meshes = doc.value("meshes", json::array());
    const json views = doc.value("bufferViews", json::array());
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const json prims = meshes[m].value("primitives", json::array());
        for (std::size_t p = 0; p < prims.size(); ++p) {
            if (!prims[p].contains("extensions") ||
                !prims[p]["extensions"].contains("KHR_draco_mesh_compression"))
                continue;
            const json& ext = prims[p]["extensions"]["KHR_draco_mesh_compression"];
            const std::size_t v = as_size(ext.value("bufferView", json()));
            if (v >= views.size() || as_size(views[v].value("buffer", json())) != 0) continue;
            out.push_back(
                {json::json_pointer("/meshes/" + std::to_string(m) + "/primitives/" +
                                    std::to_string(p) + "/extensions/KHR_draco_mesh_compression"),
                 as_size(views[v].value("byteOffset", json(0u))),
                 as_size(views[v].value("byteLength", json()))});
        }
    }
    return out;
}

} // namespace sherpa::fuzz
