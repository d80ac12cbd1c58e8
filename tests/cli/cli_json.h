#pragma once
// sherpa-cli's JSON reports for tests that compare against them.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "cli_run.h"

namespace sherpa::test {

// `sherpa-cli info FILE --json EXTRA`, parsed (stderr dropped: the loader's warnings go
// there); an empty object, and a test failure, when it does not exit 0.
inline nlohmann::json info_json(const std::string& file, const std::string& extra = "") {
    const CliRun r = run_cli("info '" + file + "' --json " + extra, "2>/dev/null");
    EXPECT_EQ(r.exit_code, 0) << file << " " << extra << "\n" << r.out;
    return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

} // namespace sherpa::test
