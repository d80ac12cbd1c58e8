#pragma once
// What is wrong with a glTF file, as the Khronos glTF-Validator reports it: a code
// (the validator's own names, or SHERPA_... for checks it does not make), a message,
// the RFC 6901 JSON pointer of the object it is about and a severity. The importer
// fills Scene::validation while it loads; a file with problems still loads.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace sherpa::scene {

// The validator's severities, with its numeric values.
enum class Severity { Error = 0, Warning = 1, Information = 2, Hint = 3 };
// "error", "warning", "info", "hint" (the words `--max-severity` takes).
std::string_view to_string(Severity s);
// Parses those words; false when `text` is none of them.
bool parse_severity(std::string_view text, Severity& out);

struct ValidationMessage {
    std::string code;    // e.g. "ACCESSOR_MIN_MISMATCH", "SHERPA_ANIMATION_SKIPPED"
    std::string message; // one readable line
    std::string pointer; // e.g. "/meshes/0/primitives/1/attributes/POSITION"; empty: whole file
    Severity severity = Severity::Error;
};

struct ValidationReport {
    std::vector<ValidationMessage> messages;
    std::size_t count(Severity s) const;
    bool truncated = false; // more messages than the report keeps (kMaxValidationMessages)
    double ms = 0;          // time the validator took
};

// Most messages one report keeps; the rest are counted in `truncated` only.
inline constexpr std::size_t kMaxValidationMessages = 10000;

} // namespace sherpa::scene
