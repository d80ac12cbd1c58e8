#pragma once
// Runs sherpa-cli with arguments through the shell; captures stdout+stderr.
#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace sherpa::test {

struct CliRun {
    int exit_code;
    std::string out;
};

inline CliRun run_cli(const std::string& args) {
    const std::string cmd = std::string(SHERPA_CLI_PATH) + " " + args + " 2>&1";
    FILE* p = popen(cmd.c_str(), "r");
    CliRun r{-1, {}};
    if (!p) return r;
    std::array<char, 4096> buf;
    std::size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
    const int status = pclose(p);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

} // namespace sherpa::test
