// Severity words and report counts (see validation.h).
#include <sherpa/scene/validation.h>

#include <algorithm>

namespace sherpa::scene {

std::string_view to_string(Severity s) {
    switch (s) {
    case Severity::Error:
        return "error";
    case Severity::Warning:
        return "warning";
    case Severity::Information:
        return "info";
    case Severity::Hint:
        return "hint";
    }
    return "error";
}

bool parse_severity(std::string_view text, Severity& out) {
    for (Severity s : {Severity::Error, Severity::Warning, Severity::Information, Severity::Hint})
        if (text == to_string(s)) {
            out = s;
            return true;
        }
    if (text == "information") {
        out = Severity::Information;
        return true;
    }
    return false;
}

std::size_t ValidationReport::count(Severity s) const {
    return static_cast<std::size_t>(
        std::count_if(messages.begin(), messages.end(),
                      [s](const ValidationMessage& m) { return m.severity == s; }));
}

} // namespace sherpa::scene
