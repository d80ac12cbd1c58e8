// "validate": the glTF validator's passes in-process on mutated .gltf/.glb bytes, as
// the importer runs them (the JSON passes, then the data pass over the GLB's BIN chunk
// and the buffers' base64 data URIs). Seeds: tests/data's files (the hostile
// reproducers and the per-code validation cases) and the small sample models.
// A finding: a message without a code, a pointer that is not a JSON pointer, a
// severity out of range, or more messages than the report keeps.
#include "validate_target.h"

#include "gltf_validate.h"     // engine/scene/src
#include "validate_internal.h" // engine/scene/src

#include <algorithm>
#include <fstream>
#include <iterator>

namespace sherpa::fuzz {
namespace {

namespace fs = std::filesystem;

std::vector<std::uint8_t> read_file(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::uint8_t> base64(std::string_view s) {
    auto value = [](char c) -> int {
        if (c >= 'A' && c <= 'Z') return c - 'A';
        if (c >= 'a' && c <= 'z') return c - 'a' + 26;
        if (c >= '0' && c <= '9') return c - '0' + 52;
        return c == '+' ? 62 : c == '/' ? 63 : -1;
    };
    std::vector<std::uint8_t> out;
    std::uint32_t acc = 0;
    int bits = 0;
    for (char c : s) {
        const int v = value(c);
        if (v < 0) break;
        acc = (acc << 6) | static_cast<std::uint32_t>(v);
        if ((bits += 6) >= 8) out.push_back(static_cast<std::uint8_t>(acc >> (bits -= 8)));
    }
    return out;
}

std::uint32_t le32(std::span<const std::uint8_t> b, std::size_t at) {
    return std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 |
           std::uint32_t(b[at + 3]) << 24;
}

} // namespace

bool ValidateTarget::init(const TargetConfig& config, std::string& error) {
    config_ = config;
    std::error_code ec;
    fs::create_directories(config.work_dir, ec);
    std::vector<fs::path> files;
    for (const fs::path& dir : {config.data_dir, config.data_dir / "validation"})
        for (const auto& f : fs::directory_iterator(dir, ec)) files.push_back(f.path());
    for (const auto& model : fs::directory_iterator(config.assets_dir / "gltf", ec))
        for (const auto& f : fs::recursive_directory_iterator(model.path(), ec))
            files.push_back(f.path());
    std::sort(files.begin(), files.end()); // the same seeds in the same order every run
    for (const fs::path& f : files) {
        const auto ext = f.extension();
        if ((ext != ".gltf" && ext != ".glb") || fs::file_size(f, ec) > config.max_seed_size)
            continue;
        seeds_.push_back(read_file(f));
    }
    if (seeds_.empty()) error = "no glTF seeds under " + config.data_dir.string();
    return !seeds_.empty();
}

std::optional<std::string> ValidateTarget::run() {
    nlohmann::json root;
    if (!scene::detail::parse_gltf_document(bytes_, root).empty()) return std::nullopt; // refused
    const bool glb = bytes_.size() >= 4 && std::equal(bytes_.begin(), bytes_.begin() + 4, "glTF");
    scene::ValidationReport report;
    scene::detail::DocumentValidator validator(root, bytes_, glb, report);
    // Buffers as tinygltf would fill them: the BIN chunk, base64 data URIs.
    std::vector<std::vector<std::uint8_t>> owned;
    std::vector<std::span<const std::uint8_t>> buffers;
    const auto& list =
        root.contains("buffers") && root["buffers"].is_array() ? root["buffers"] : nlohmann::json();
    for (std::size_t i = 0; i < list.size(); ++i) {
        const nlohmann::json& b = list[i];
        const auto uri = b.is_object() ? b.find("uri") : b.end();
        if (b.is_object() && uri != b.end() && uri->is_string()) {
            const std::string& u = uri->get_ref<const std::string&>();
            const auto comma = u.find(',');
            owned.push_back(u.rfind("data:", 0) == 0 && comma != std::string::npos
                                ? base64(std::string_view(u).substr(comma + 1))
                                : std::vector<std::uint8_t>{});
        } else if (glb && i == 0 && bytes_.size() >= 28) {
            const std::size_t at = 20 + std::size_t{le32(bytes_, 12)};
            if (at + 8 <= bytes_.size()) {
                const std::size_t n =
                    std::min<std::size_t>(le32(bytes_, at), bytes_.size() - at - 8);
                owned.emplace_back(bytes_.begin() + static_cast<std::ptrdiff_t>(at + 8),
                                   bytes_.begin() + static_cast<std::ptrdiff_t>(at + 8 + n));
            } else {
                owned.emplace_back();
            }
        } else {
            owned.emplace_back();
        }
    }
    for (const auto& o : owned) buffers.emplace_back(o);
    validator.check_data(buffers);
    if (report.messages.size() > scene::kMaxValidationMessages)
        return "report keeps more messages than its limit";
    for (const scene::ValidationMessage& m : report.messages) {
        if (m.code.empty() || m.message.empty()) return "message without a code or text";
        if (!m.pointer.empty() && m.pointer[0] != '/')
            return m.code + ": pointer '" + m.pointer + "' is not a JSON pointer";
        if (static_cast<int>(m.severity) < 0 || static_cast<int>(m.severity) > 3)
            return m.code + ": severity out of range";
    }
    return std::nullopt;
}

} // namespace sherpa::fuzz
