#pragma once
// Shared checks of the validator suites (validation_test, validation_coverage_test):
// the per-code case files of tools/gltf_validator/make_cases.py and a report's messages.
#include "test_support.h"

#include <sherpa/scene/validation.h>

#include <cctype>
#include <string>

#include <gtest/gtest.h>

namespace sherpa::test {

inline std::string case_path(const std::string& name) {
    return (data_dir() / "validation" / name).string();
}

// Whether `r` has a message with `code` at `pointer`.
inline bool has(const scene::ValidationReport& r, const std::string& code,
                const std::string& pointer) {
    for (const auto& m : r.messages)
        if (m.code == code && m.pointer == pointer) return true;
    return false;
}

// Every message of `r`, one a line, for failure output.
inline std::string dump(const scene::ValidationReport& r) {
    std::string s;
    for (const auto& m : r.messages) s += m.code + " " + m.pointer + ": " + m.message + "\n";
    return s;
}

// A case file, a code and the pointer it must be reported at.
struct Expect {
    const char* file;
    const char* code;
    const char* pointer;
};

// gtest parameter names: "INDEX_FILE_CODE" with every other character as '_'.
inline std::string expect_name(const ::testing::TestParamInfo<Expect>& info) {
    std::string n = std::to_string(info.index) + "_" + info.param.file + "_" + info.param.code;
    for (char& c : n)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return n;
}

} // namespace sherpa::test
