// The validator as the importer runs it: timed passes, and the importer's own
// warnings and refusals as SHERPA_ messages with JSON pointers.
#include "validate_internal.h"

#include "import_context.h"

#include <cctype>
#include <chrono>

namespace sherpa::scene::detail {
namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

DocumentValidator::DocumentValidator(const Json& root, std::span<const std::uint8_t> file, bool glb,
                                     ValidationReport& report, std::string base_dir,
                                     const DocumentOrder* order)
    : v_{report, root, order, false, false, {}, {}, {}, {}, {}, {}, {}, {}} {
    const auto t0 = std::chrono::steady_clock::now();
    v_.glb = glb;
    v_.base_dir = std::move(base_dir);
    if (glb) validate_glb(v_, file);
    validate_document(v_);
    report.ms += ms_since(t0);
}

void DocumentValidator::check_data(std::span<const std::span<const std::uint8_t>> buffers,
                                   std::span<const std::span<const std::uint8_t>> images) {
    const auto t0 = std::chrono::steady_clock::now();
    validate_data(v_, buffers);
    validate_images(v_, buffers, images);
    v_.report.ms += ms_since(t0);
}

std::string pointer_of_path(std::string_view text) {
    std::size_t end = 0;
    while (end < text.size() &&
           (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_' ||
            text[end] == '[' || text[end] == ']' || text[end] == '.'))
        ++end;
    const std::string_view path = text.substr(0, end);
    if (path.empty() || path.find('[') == std::string_view::npos) return {};
    std::string out;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const char c = path[i];
        if (c == '[' || c == '.') {
            if (out.empty() || out.back() != '/') out += '/';
        } else if (c != ']') {
            if (out.empty()) out += '/';
            out += c;
        }
    }
    while (!out.empty() && out.back() == '/') out.pop_back();
    return out;
}

void add_import_message(ValidationReport& report, std::string_view code, Severity severity,
                        const std::string& text) {
    if (report.messages.size() >= kMaxValidationMessages) {
        report.truncated = true;
        return;
    }
    report.messages.push_back({std::string(code), text, pointer_of_path(text), severity});
}

void ImportContext::skip(std::string_view code, const std::string& message) {
    scene.warnings.push_back(message);
    add_import_message(scene.validation, code, Severity::Error, message);
}

} // namespace sherpa::scene::detail
