// sherpa-bench-codecs: compressed geometry decode throughput next to the reference
// decoders, on one core, in the same run, on the same bytes:
//  - EXT_meshopt_compression: Sherpa's decode_meshopt_views (the importer's whole
//    wrapper: stream checks, output buffers, filters) against meshoptimizer's own
//    decode calls on each view's stream (meshopt_decodeVertexBuffer/IndexBuffer/
//    IndexSequence + the filter), output allocated the same way.
//  - KHR_draco_mesh_compression: decode_draco_primitives (Draco decode + mapping,
//    count/min-max checks, new buffers) against draco::Decoder::DecodeMeshFromBuffer
//    on each primitive's stream, and Debian's draco_decoder tool on the same stream
//    (its own "ms to decode", whole milliseconds; it also writes a PLY).
//  - The meshopt decoders alone: Sherpa's (meshopt_codec.h) against Debian's
//    libmeshoptimizer on the same version 0 streams into preallocated outputs, vertex
//    (ATTRIBUTES) and index (TRIANGLES, INDICES) streams apart, filters left out.
//  - Load time (load_scene, tangents off) of each compressed file next to its
//    uncompressed source.
// Times are the minimum over --runs repetitions (default 30) of one full pass, ours
// and the reference's runs alternating;
// MB/s counts decoded bytes (MB = 1e6 bytes). Usage: sherpa-bench-codecs CORPUS_DIR ASSETS_DIR
#include "gltf_draco.h"
#include "gltf_meshopt.h"
#include "gltf_prepare.h"
#include "meshopt_codec.h"

#include <sherpa/scene/scene_loader.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <span>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <draco/compression/decode.h>
#include <meshoptimizer.h>
#include <tiny_gltf.h>

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Minimum over `runs` of one call's wall time (one thread), in ms.
double best_ms(int runs, const std::function<void()>& fn) {
    double best = std::numeric_limits<double>::infinity();
    for (int r = 0; r < runs; ++r) {
        const auto t0 = Clock::now();
        fn();
        best = std::min(best, ms_since(t0));
    }
    return best;
}

// The same for two calls measured in alternation (ours, then the reference, `runs`
// times): on a shared machine a load change then hits both alike, where timing one
// call's runs after the other's would give it to one side only.
std::pair<double, double> best_ms_alternating(int runs, const std::function<void()>& a,
                                              const std::function<void()>& b) {
    double best_a = std::numeric_limits<double>::infinity(), best_b = best_a;
    for (int r = 0; r < runs; ++r) {
        auto t0 = Clock::now();
        a();
        best_a = std::min(best_a, ms_since(t0));
        t0 = Clock::now();
        b();
        best_b = std::min(best_b, ms_since(t0));
    }
    return {best_a, best_b};
}

std::vector<std::uint8_t> read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

bool no_images(tinygltf::Image*, const int, std::string*, std::string*, int, int,
               const unsigned char*, int, void*) {
    return true; // images are not part of geometry decoding
}

tinygltf::Model load_model(const fs::path& path) {
    std::vector<std::uint8_t> bytes = read_bytes(path);
    if (auto prepared = sherpa::scene::detail::prepared_for_tinygltf(bytes); !prepared.empty())
        bytes = std::move(prepared);
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(no_images, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    if (!loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                     static_cast<unsigned>(bytes.size()),
                                     path.parent_path().string()))
        throw std::runtime_error(path.string() + ": " + err);
    return model;
}

constexpr double kToolMissing = -2; // Row::tool_ms: draco_decoder absent or failing

struct Row {
    std::string file;
    std::uint64_t encoded = 0, decoded = 0;
    double ours_ms = 0, reference_ms = 0, tool_ms = -1;
};

int number(const tinygltf::Value& o, const char* key, int fallback) {
    return o.Has(key) && o.Get(key).IsNumber() ? static_cast<int>(o.Get(key).GetNumberAsInt())
                                               : fallback;
}
std::string text(const tinygltf::Value& o, const char* key, const char* fallback) {
    return o.Has(key) && o.Get(key).IsString() ? o.Get(key).Get<std::string>() : fallback;
}

Row bench_meshopt(const fs::path& file, int runs) {
    const tinygltf::Model original = load_model(file);
    Row row{file.filename().string()};
    struct View {
        const std::uint8_t* data;
        std::size_t length, count, stride, bytes;
        std::string mode, filter;
    };
    std::vector<View> views;
    for (const auto& v : original.bufferViews) {
        const auto it = v.extensions.find("EXT_meshopt_compression");
        if (it == v.extensions.end()) continue;
        const tinygltf::Value& e = it->second;
        const auto& buffer = original.buffers.at(std::size_t(number(e, "buffer", 0))).data;
        View view{buffer.data() + number(e, "byteOffset", 0),
                  std::size_t(number(e, "byteLength", 0)),
                  std::size_t(number(e, "count", 0)),
                  std::size_t(number(e, "byteStride", 0)),
                  v.byteLength,
                  text(e, "mode", "ATTRIBUTES"),
                  text(e, "filter", "NONE")};
        row.encoded += view.length;
        row.decoded += view.count * view.stride;
        views.push_back(view);
    }
    std::vector<tinygltf::Model> copies(std::size_t(runs), original);
    std::size_t next = 0;
    // Every decoded view stays alive, as the wrapper's do (each run decodes into a
    // fresh model copy): freeing them would let the next run reuse touched pages.
    std::vector<std::vector<std::uint8_t>> kept;
    kept.reserve(views.size() * std::size_t(runs));
    const auto ours = [&] { sherpa::scene::detail::decode_meshopt_views(copies[next++], {}); };
    std::tie(row.ours_ms, row.reference_ms) = best_ms_alternating(runs, ours, [&] {
        for (const View& v : views) {
            std::vector<std::uint8_t>& out = kept.emplace_back(v.bytes, 0);
            int rc = 0;
            if (v.mode == "ATTRIBUTES")
                rc = meshopt_decodeVertexBuffer(out.data(), v.count, v.stride, v.data, v.length);
            else if (v.mode == "TRIANGLES")
                rc = meshopt_decodeIndexBuffer(out.data(), v.count, v.stride, v.data, v.length);
            else
                rc = meshopt_decodeIndexSequence(out.data(), v.count, v.stride, v.data, v.length);
            if (rc != 0) throw std::runtime_error("meshopt reference decode failed");
            if (v.filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out.data(), v.count, v.stride);
            if (v.filter == "QUATERNION") meshopt_decodeFilterQuat(out.data(), v.count, v.stride);
            if (v.filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data(), v.count, v.stride);
        }
    });
    return row;
}

// draco_decoder's own decode time: "... (N ms to decode)".
// The decoders alone on the file's streams of one kind (vertex: ATTRIBUTES; index:
// TRIANGLES and INDICES), ours and the library's runs alternating, outputs allocated
// once; the decoded bytes of the streams are `row.decoded`.
Row bench_meshopt_decoders(const fs::path& file, int runs, bool vertex) {
    const tinygltf::Model model = load_model(file);
    Row row{file.filename().string() + (vertex ? " vertex" : " index")};
    struct Stream {
        std::span<const std::uint8_t> data;
        std::size_t count, stride;
        sherpa::scene::meshopt::Mode mode;
        std::vector<std::uint8_t> out;
    };
    std::vector<Stream> streams;
    for (const auto& v : model.bufferViews) {
        const auto it = v.extensions.find("EXT_meshopt_compression");
        if (it == v.extensions.end()) continue;
        const tinygltf::Value& e = it->second;
        const std::string mode = text(e, "mode", "ATTRIBUTES");
        if ((mode == "ATTRIBUTES") != vertex) continue;
        const auto& buffer = model.buffers.at(std::size_t(number(e, "buffer", 0))).data;
        Stream st{
            {buffer.data() + number(e, "byteOffset", 0), std::size_t(number(e, "byteLength", 0))},
            std::size_t(number(e, "count", 0)),
            std::size_t(number(e, "byteStride", 0)),
            mode == "ATTRIBUTES"  ? sherpa::scene::meshopt::Mode::Attributes
            : mode == "TRIANGLES" ? sherpa::scene::meshopt::Mode::Triangles
                                  : sherpa::scene::meshopt::Mode::Indices,
            {}};
        st.out.resize(st.count * st.stride);
        row.encoded += st.data.size();
        row.decoded += st.out.size();
        streams.push_back(std::move(st));
    }
    namespace mo = sherpa::scene::meshopt;
    std::tie(row.ours_ms, row.reference_ms) = best_ms_alternating(
        runs,
        [&] {
            for (Stream& st : streams) {
                const std::span<std::uint8_t> out(st.out);
                const mo::Result r = mo::decode(st.mode, out, st.count, st.stride, st.data);
                if (!r) throw std::runtime_error("our meshopt decode failed");
            }
        },
        [&] {
            for (Stream& st : streams) {
                std::uint8_t* out = st.out.data();
                const int rc = st.mode == mo::Mode::Attributes
                                   ? meshopt_decodeVertexBuffer(out, st.count, st.stride,
                                                                st.data.data(), st.data.size())
                               : st.mode == mo::Mode::Triangles
                                   ? meshopt_decodeIndexBuffer(out, st.count, st.stride,
                                                               st.data.data(), st.data.size())
                                   : meshopt_decodeIndexSequence(out, st.count, st.stride,
                                                                 st.data.data(), st.data.size());
                if (rc != 0) throw std::runtime_error("meshopt reference decode failed");
            }
        });
    return row;
}

double draco_tool_ms(const fs::path& drc) {
    const fs::path out = drc.string() + ".ply";
    const std::string cmd =
        "draco_decoder -i '" + drc.string() + "' -o '" + out.string() + "' 2>&1";
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return -1;
    std::string text;
    char buf[512];
    while (fgets(buf, sizeof buf, p)) text += buf;
    pclose(p);
    const auto at = text.find(" ms to decode");
    if (at == std::string::npos) return -1;
    const auto open = text.rfind('(', at);
    return std::stod(text.substr(open + 1, at - open - 1));
}

Row bench_draco(const fs::path& file, int runs, const fs::path& scratch) {
    const tinygltf::Model original = load_model(file);
    Row row{file.filename().string()};
    std::vector<std::pair<const char*, std::size_t>> streams;
    for (const auto& mesh : original.meshes)
        for (const auto& prim : mesh.primitives) {
            const auto it = prim.extensions.find("KHR_draco_mesh_compression");
            if (it == prim.extensions.end()) continue;
            const auto& view =
                original.bufferViews.at(std::size_t(number(it->second, "bufferView", 0)));
            const auto& buffer = original.buffers.at(std::size_t(view.buffer)).data;
            streams.emplace_back(reinterpret_cast<const char*>(buffer.data() + view.byteOffset),
                                 view.byteLength);
            row.encoded += view.byteLength;
        }
    std::vector<tinygltf::Model> copies(std::size_t(runs) + 1, original);
    // Decoded bytes: what the wrapper wrote for the primitives.
    for (const auto& d : sherpa::scene::detail::decode_draco_primitives(copies.back()))
        row.decoded += d.stats.decoded_bytes;
    std::size_t next = 0;
    const auto ours = [&] { sherpa::scene::detail::decode_draco_primitives(copies[next++]); };
    std::tie(row.ours_ms, row.reference_ms) = best_ms_alternating(runs, ours, [&] {
        for (const auto& [data, size] : streams) {
            draco::DecoderBuffer stream;
            stream.Init(data, size);
            draco::Decoder decoder;
            if (!decoder.DecodeMeshFromBuffer(&stream).ok())
                throw std::runtime_error("Draco reference decode failed");
        }
    });
    row.tool_ms = 0;
    for (std::size_t s = 0; s < streams.size(); ++s) {
        const fs::path drc = scratch / (row.file + "." + std::to_string(s) + ".drc");
        std::ofstream(drc, std::ios::binary)
            .write(streams[s].first, std::streamsize(streams[s].second));
        double best = std::numeric_limits<double>::infinity();
        for (int r = 0; r < 5; ++r) best = std::min(best, draco_tool_ms(drc));
        if (best < 0) { // not installed (.ci/setup installs only libdraco-dev) or failed
            row.tool_ms = kToolMissing;
            break;
        }
        row.tool_ms += best;
    }
    return row;
}

double load_ms(const std::string& path, int runs) {
    sherpa::scene::LoadOptions options;
    options.generate_tangents = false;
    return best_ms(runs, [&] {
        if (!sherpa::scene::load_scene(path, options))
            throw std::runtime_error(path + ": does not load");
    });
}

void print(const Row& r) {
    const double mb = double(r.decoded) / 1e6;
    std::printf("%-28s %9llu %9llu %9.3f %9.3f %8.1f %8.1f %6.2fx", r.file.c_str(),
                static_cast<unsigned long long>(r.encoded),
                static_cast<unsigned long long>(r.decoded), r.ours_ms, r.reference_ms,
                mb / (r.ours_ms / 1e3), mb / (r.reference_ms / 1e3), r.ours_ms / r.reference_ms);
    if (r.tool_ms >= 0) std::printf("  draco_decoder %.0f ms", r.tool_ms);
    if (r.tool_ms == kToolMissing) std::printf("  draco_decoder did not run");
    std::printf("\n");
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: sherpa-bench-codecs CORPUS_DIR ASSETS_DIR [--runs N]\n");
        return 2;
    }
    const fs::path corpus = argv[1], assets = argv[2];
    int runs = 30;
    if (argc >= 5 && std::string(argv[3]) == "--runs") runs = std::max(1, std::atoi(argv[4]));
    const fs::path scratch = fs::temp_directory_path() / "sherpa_codec_bench";
    fs::create_directories(scratch);
    const char* models[] = {"Duck", "BoxTextured", "DamagedHelmet", "2CylinderEngine"};
    try {
        std::printf("%-28s %9s %9s %9s %9s %8s %8s %7s\n", "file", "encoded", "decoded", "ours ms",
                    "ref ms", "ours MB/s", "ref MB/s", "ratio");
        for (const char* m : models)
            print(bench_meshopt(corpus / (std::string(m) + ".meshopt.glb"), runs));
        for (const char* m : models)
            print(bench_draco(corpus / (std::string(m) + ".draco.glb"), runs, scratch));
        std::printf("\nmeshopt decoders alone (ours: meshopt_codec.h; ref: Debian's "
                    "libmeshoptimizer %d.%d), version 0 streams, best of %d\n",
                    MESHOPTIMIZER_VERSION / 1000, MESHOPTIMIZER_VERSION % 1000 / 10, runs);
        for (const bool vertex : {true, false})
            for (const char* m : models)
                print(bench_meshopt_decoders(corpus / (std::string(m) + ".meshopt.glb"), runs,
                                             vertex));
        std::printf("\nload_scene (tangents off), best of %d, ms\n%-18s %10s %10s %10s\n", runs,
                    "model", "original", "meshopt", "draco");
        for (const char* m : models) {
            const std::string original =
                (assets / "gltf" / m / "glTF" / (std::string(m) + ".gltf")).string();
            std::printf("%-18s %10.2f %10.2f %10.2f\n", m, load_ms(original, runs),
                        load_ms((corpus / (std::string(m) + ".meshopt.glb")).string(), runs),
                        load_ms((corpus / (std::string(m) + ".draco.glb")).string(), runs));
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    fs::remove_all(scratch);
    return 0;
}
