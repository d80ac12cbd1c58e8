// sherpa-bench-startup [--rounds N] [--cli PATH] [--baseline PATH] [--editor PATH]: wall
// time of a whole
// process, exec to exit, for `sherpa-cli info Box.gltf` (and other short commands)
// against /bin/true and a hello-world linked to the same libc, measured in the same
// run, interleaved round by round so that the machine's load hits all alike. Prints
// the median and minimum of each and their ratios to both references. --baseline adds
// another sherpa-cli (e.g. an older build) to the same rounds.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <string>
#include <vector>

namespace {

struct Command {
    std::string label;
    std::vector<std::string> argv;
    std::vector<double> ms;
};

// Runs argv with stdout and stderr on /dev/null; wall milliseconds, or -1 on failure.
double run_once(const std::vector<std::string>& argv) {
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const auto t0 = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid == 0) {
        const int null = open("/dev/null", O_WRONLY);
        dup2(null, 1);
        dup2(null, 2);
        execv(args[0], args.data());
        _exit(127);
    }
    int status = 0;
    if (pid < 0 || waitpid(pid, &status, 0) != pid) return -1.0;
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? ms : -1.0;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

} // namespace

int main(int argc, char** argv) {
    int rounds = 30;
    std::string cli = SHERPA_CLI_PATH, hello = SHERPA_HELLO_PATH;
    std::string editor, baseline;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--rounds" && i + 1 < argc)
            rounds = std::max(1, std::atoi(argv[++i]));
        else if (a == "--cli" && i + 1 < argc)
            cli = argv[++i];
        else if (a == "--baseline" && i + 1 < argc)
            baseline = argv[++i];
        else if (a == "--editor" && i + 1 < argc)
            editor = argv[++i];
        else {
            std::fprintf(stderr,
                         "usage: sherpa-bench-startup [--rounds N] [--cli PATH] [--baseline PATH] "
                         "[--editor PATH]\n");
            return 2;
        }
    }
    const std::string assets = SHERPA_ASSETS_DIR;
    std::vector<Command> commands = {
        {"/bin/true", {"/bin/true"}, {}},
        {"hello-world (same libc)", {hello}, {}},
        {"sherpa-cli --help", {cli, "--help"}, {}},
        {"sherpa-cli info Box.gltf", {cli, "info", assets + "/gltf/Box/glTF/Box.gltf"}, {}},
        {"sherpa-cli info BoxTextured.gltf (PNG)",
         {cli, "info", assets + "/gltf/BoxTextured/glTF/BoxTextured.gltf"},
         {}},
    };
    if (!baseline.empty())
        commands.push_back({"baseline: info Box.gltf",
                            {baseline, "info", assets + "/gltf/Box/glTF/Box.gltf"},
                            {}});
    // The editor's start-up without a display: parse, --help, exit.
    if (!editor.empty()) commands.push_back({"sherpa --help (editor)", {editor, "--help"}, {}});
    for (Command& c : commands) run_once(c.argv); // page cache warm
    for (int r = 0; r < rounds; ++r)
        for (Command& c : commands) {
            const double ms = run_once(c.argv);
            if (ms < 0.0) {
                std::fprintf(stderr, "error: %s failed\n", c.label.c_str());
                return 1;
            }
            c.ms.push_back(ms);
        }
    const double t_true = median(commands[0].ms), t_hello = median(commands[1].ms);
    std::printf("%d rounds, interleaved; wall ms per process (exec to exit)\n", rounds);
    std::printf("%-42s %9s %9s %10s %10s\n", "command", "median", "min", "/ true", "/ hello");
    for (const Command& c : commands) {
        const double m = median(c.ms);
        std::printf("%-42s %9.2f %9.2f %10.2f %10.2f\n", c.label.c_str(), m,
                    *std::min_element(c.ms.begin(), c.ms.end()), m / t_true, m / t_hello);
    }
    return 0;
}
