// sherpa-bench-validate --passes: the validator's passes timed one by one on a file, in
// one process (the fastest of N runs each, data warm in the caches), beside the
// importer's own JSON parse and property checks. Buffers are read as the importer
// would find them: external files next to the glTF or base64 data URIs.
#include "validate_passes.h"

#include "gltf_lenient.h" // engine/scene/src: the validator's internal passes
#include "gltf_validate.h"
#include "validate_internal.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

namespace fs = std::filesystem;

namespace sherpa::bench {
namespace {

std::vector<std::uint8_t> read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::uint8_t> base64(std::string_view text) {
    std::vector<std::uint8_t> out;
    std::uint32_t bits = 0;
    int have = 0;
    for (char c : text) {
        int v = c >= 'A' && c <= 'Z'   ? c - 'A'
                : c >= 'a' && c <= 'z' ? c - 'a' + 26
                : c >= '0' && c <= '9' ? c - '0' + 52
                : c == '+'             ? 62
                : c == '/'             ? 63
                                       : -1;
        if (v < 0) break;
        bits = bits << 6 | static_cast<std::uint32_t>(v);
        if ((have += 6) >= 8) out.push_back(static_cast<std::uint8_t>(bits >> (have -= 8)));
    }
    return out;
}

bool keep_encoded(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                  const unsigned char*, int, void*) {
    return true;
}

double fastest_ms(int repeat, const std::function<void()>& f) {
    double best = 1e300;
    for (int r = 0; r < repeat; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        f();
        best = std::min(
            best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                      .count());
    }
    return best;
}

} // namespace

bool print_passes(const fs::path& file, int repeat) {
    using namespace sherpa::scene::detail;
    const std::vector<std::uint8_t> bytes = read_bytes(file);
    nlohmann::json root;
    DocumentOrder order;
    if (!parse_gltf_document(bytes, root, nullptr, &order).empty()) return false;
    normalize_integers(root);
    std::vector<std::vector<std::uint8_t>> owned;
    for (const nlohmann::json& b : root.value("buffers", nlohmann::json::array())) {
        const std::string uri = b.value("uri", "");
        const auto comma = uri.find(',');
        owned.push_back(uri.starts_with("data:") && comma != std::string::npos
                            ? base64(std::string_view(uri).substr(comma + 1))
                            : read_bytes(file.parent_path() / uri));
    }
    const std::vector<std::span<const std::uint8_t>> buffers(owned.begin(), owned.end());
    const std::string base = file.parent_path().string();
    auto run = [&](scene::ValidationReport& report, auto&& passes) {
        Validation v{report, root, &order, false, false, {}, {}, {}, {}, {}, {}, {}, {}};
        v.base_dir = base;
        passes(v);
    };
    // Cumulative: each pass needs the ones before it (links, layouts, uses).
    using Pass = void (*)(Validation&);
    const std::pair<const char*, Pass> passes[] = {
        {"schema", validate_schema},       {"extensions", validate_extensions},
        {"buffers", validate_buffers},     {"meshes", validate_meshes},
        {"nodes", validate_nodes},         {"animations", validate_animations},
        {"materials", validate_materials}, {"unused", validate_unused},
    };
    std::printf("%s, fastest of %d in one process (ms):\n", file.filename().string().c_str(),
                repeat);
    std::printf("  importer: JSON parse %.4f, property checks %.4f\n",
                fastest_ms(repeat,
                           [&] {
                               nlohmann::json r;
                               DocumentOrder o;
                               parse_gltf_document(bytes, r, nullptr, &o);
                           }),
                fastest_ms(repeat, [&] { check_gltf_properties(root); }));
    double before = 0;
    std::printf("  validator:");
    for (std::size_t n = 1; n <= std::size(passes); ++n) {
        const double upto = fastest_ms(repeat, [&] {
            scene::ValidationReport report;
            run(report, [&](Validation& v) {
                for (std::size_t i = 0; i < n; ++i) passes[i].second(v);
            });
        });
        std::printf(" %s %.4f", passes[n - 1].first, std::max(upto - before, 0.0));
        before = upto;
    }
    scene::ValidationReport report;
    Validation done{report, root, &order, false, false, {}, {}, {}, {}, {}, {}, {}, {}};
    done.base_dir = base;
    validate_document(done);
    const double data = fastest_ms(repeat, [&] {
        Validation v = done;
        validate_data(v, buffers);
    });
    std::printf(", JSON passes %.4f, data %.4f\n", before, data);
    // tinygltf builds its model from the text, parsing the JSON a second time (it takes
    // no parsed document): its load alone, and a parse of the same text with the same
    // JSON library (nlohmann::json, the document freed), what avoiding it would save.
    if (bytes.size() >= 4 && std::equal(bytes.begin(), bytes.begin() + 4, "glTF")) return true;
    const double tinygltf_ms = fastest_ms(std::min(repeat, 7), [&] {
        tinygltf::TinyGLTF loader;
        loader.SetImageLoader(keep_encoded, nullptr);
        tinygltf::Model model;
        std::string err, warn;
        loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                   static_cast<unsigned>(bytes.size()), base);
    });
    const double json_ms = fastest_ms(std::min(repeat, 7), [&] {
        const auto doc = nlohmann::json::parse(bytes.begin(), bytes.end());
    });
    std::printf("  tinygltf: load %.4f, of which its JSON parse about %.4f\n", tinygltf_ms,
                json_ms);
    return true;
}

} // namespace sherpa::bench
