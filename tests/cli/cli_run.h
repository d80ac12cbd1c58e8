#pragma once
// Runs sherpa-cli with arguments and collects its exit code and output.
#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace sherpa::test {

// `s` in single quotes, for a path in a shell command line.
inline std::string quoted(const std::string& s) {
    return "'" + s + "'";
}

struct CliRun {
    int exit_code;
    std::string out;
};

// `args` is appended to the CLI path as shell text; `stderr_redirect` decides
// where stderr goes ("2>&1" merges it into `out`).
inline CliRun run_cli(const std::string& args, const std::string& stderr_redirect = "2>&1") {
    const std::string cmd = std::string(SHERPA_CLI_PATH) + " " + args + " " + stderr_redirect;
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
