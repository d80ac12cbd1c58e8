#pragma once
// Validation messages in the shape of the Khronos glTF-Validator's report: a code
// (Khronos's name, or SHERPA_... for checks of our own), the message, the severity
// and an RFC 6901 JSON pointer into the file ("/meshes/0/primitives/1").
#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace sherpa {

enum class Severity { Error = 0, Warning = 1, Information = 2, Hint = 3 };

struct ValidationMessage {
    std::string code;
    std::string message;
    std::string pointer;
    Severity severity;
};

struct ValidationReport {
    std::vector<ValidationMessage> messages;
    std::size_t count(Severity s) const {
        return static_cast<std::size_t>(
            std::count_if(messages.begin(), messages.end(),
                          [s](const ValidationMessage& m) { return m.severity == s; }));
    }
    bool truncated = false;
    double ms = 0;
};

} // namespace sherpa
