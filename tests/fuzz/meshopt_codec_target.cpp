// The meshopt decoders (engine/scene/src/meshopt_codec.h) called directly, without the
// importer's checks in front: every mode, bitstream version, stride and filter is
// reachable from one mutated byte string. A case is a 7-byte header (mode, stride or
// index size, filter, count as 32 bits) and the stream. The seeds are the streams of
// tests/data/compressed_seeds' gltfpack files (EXT_ and KHR_meshopt_compression: vertex
// versions 0 and 1). The oracle: no crash or sanitizer report; a stream that decodes
// decodes to the same bytes twice (no read of memory the decoder did not write).
#include "meshopt_codec_target.h"

#include <algorithm>
#include <cstring>

#include <nlohmann/json.hpp>
#include <sherpa/core/file_io.h>

#include "gltf_targets.h"
#include "meshopt_codec.h"

namespace sherpa::fuzz {

namespace fs = std::filesystem;
namespace mo = scene::meshopt;
using nlohmann::json;

namespace {

constexpr std::size_t kHeader = 7;

struct Case {
    mo::Mode mode = mo::Mode::Attributes;
    std::size_t stride = 4, count = 0;
    mo::Filter filter = mo::Filter::None;
    std::span<const std::uint8_t> stream;
};

Case parse(std::span<const std::uint8_t> bytes) {
    Case c;
    if (bytes.size() < kHeader) return c;
    c.mode = mo::Mode(bytes[0] % 3);
    c.stride = c.mode == mo::Mode::Attributes ? (bytes[1] % 64 + 1) * 4u : (bytes[1] & 1) ? 4u : 2u;
    c.filter = mo::Filter(bytes[2] % 5);
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 3, 4);
    c.count = c.mode == mo::Mode::Triangles ? count / 3 * 3 : count;
    c.stream = bytes.subspan(kHeader);
    return c;
}

mo::Result decode(const Case& c, std::vector<std::uint8_t>& out) {
    out.assign(c.count * c.stride, 0xA5);
    return mo::decode(c.mode, out, c.count, c.stride, c.stream);
}

} // namespace

bool MeshoptCodecTarget::init(const TargetConfig& config, std::string& error) {
    config_ = config;
    const fs::path dir = config.data_dir / "compressed_seeds";
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& f : fs::directory_iterator(dir, ec))
        if (f.path().filename().string().find("meshopt") != std::string::npos)
            files.push_back(f.path());
    std::sort(files.begin(), files.end()); // the same seed numbering on every machine
    for (const fs::path& file : files) {
        std::vector<std::uint8_t> glb, bin;
        std::string text;
        if (!::sherpa::core::read_file(file, glb, error)) return false;
        if (!split_glb(glb, text, bin)) continue;
        const json doc = json::parse(text, nullptr, false);
        if (!doc.is_object()) continue;
        for (const json& view : doc.value("bufferViews", json::array()))
            for (const char* codec : {"EXT_meshopt_compression", "KHR_meshopt_compression"}) {
                if (!view.contains("extensions") || !view["extensions"].contains(codec)) continue;
                const json& e = view["extensions"][codec];
                const std::size_t offset = e.value("byteOffset", 0u),
                                  length = e.value("byteLength", 0u);
                if (length == 0 || offset > bin.size() || length > bin.size() - offset) continue;
                const std::string mode = e.value("mode", ""), filter = e.value("filter", "NONE");
                const std::size_t stride = e.value("byteStride", 4u);
                const auto count = std::uint32_t(e.value("count", 0u));
                std::vector<std::uint8_t> seed = {
                    std::uint8_t(mode == "ATTRIBUTES"  ? 0
                                 : mode == "TRIANGLES" ? 1
                                                       : 2),
                    std::uint8_t(mode == "ATTRIBUTES" ? stride / 4 - 1 : stride == 4),
                    std::uint8_t(filter == "OCTAHEDRAL"    ? 1
                                 : filter == "QUATERNION"  ? 2
                                 : filter == "EXPONENTIAL" ? 3
                                                           : 0)};
                for (int b = 0; b < 4; ++b) seed.push_back(std::uint8_t(count >> (8 * b)));
                seed.insert(seed.end(), bin.begin() + std::ptrdiff_t(offset),
                            bin.begin() + std::ptrdiff_t(offset + length));
                seeds_.push_back(std::move(seed));
            }
    }
    if (seeds_.empty()) {
        error = "no meshopt streams in " + dir.string();
        return false;
    }
    fs::create_directories(config.work_dir);
    return true;
}

std::optional<std::string> MeshoptCodecTarget::run() {
    const Case c = parse(bytes_);
    // The importer's guard: nothing is allocated for a stream too short for its count.
    const unsigned version = c.stream.empty() ? 0 : c.stream[0] & 15;
    if (c.stream.size() < mo::minimum_stream_size(c.mode, version, c.count, c.stride))
        return std::nullopt;
    if (c.count * c.stride > (64u << 20)) return std::nullopt; // a version 1 stream of
    // "all zero" blocks decodes 1024 times its size: the fuzzer's memory is the limit here
    std::vector<std::uint8_t> first, second;
    const mo::Result a = decode(c, first);
    const mo::Result b = decode(c, second);
    if (a.status != b.status || a.offset != b.offset)
        return "the same stream decoded twice gave different results";
    if (!a) return std::nullopt;
    if (first != second) return "the same stream decoded twice gave different bytes";
    if (c.mode == mo::Mode::Attributes) mo::apply_filter(c.filter, first, c.count, c.stride);
    return std::nullopt;
}

} // namespace sherpa::fuzz
