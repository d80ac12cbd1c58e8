#pragma once
// Runs the three.js posing oracle (tools/motion/three_oracle.mjs, installed into
// SHERPA_THREE_CACHE by the three_oracle CTest fixture) on one animation of a glTF
// file at the given times; shared by the scene-layer and the CLI motion tests.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace sherpa::test {

// The oracle's JSON ({"frames": [...]}), or an empty object and a test failure when
// it did not run.
inline nlohmann::json run_three_oracle(const std::string& file, int animation,
                                       const std::vector<double>& times) {
    std::string cmd = std::string("'") + SHERPA_NODE + "' '" + SHERPA_THREE_SCRIPT + "' '" +
                      SHERPA_THREE_CACHE + "' '" + file + "' " + std::to_string(animation);
    for (double t : times) cmd += " " + std::to_string(t);
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
    std::string out;
    char buf[65536];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe.get())) > 0;) out.append(buf, n);
    if (out.empty() || out[0] != '{') {
        ADD_FAILURE() << "three.js oracle failed (is the three_oracle fixture installed?): " << cmd;
        return nlohmann::json::object();
    }
    return nlohmann::json::parse(out);
}

} // namespace sherpa::test
