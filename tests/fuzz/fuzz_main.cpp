// sherpa-fuzz: the in-tree mutation fuzzer. Cases run in-process in a forked worker
// (thousands per second); the parent notices a worker that dies (crash, sanitizer
// report) or stops advancing (hang), rebuilds the case from (seed, target, index) to
// save it as a reproducer, and restarts a worker at the next case. Usage: see kUsage.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <map>
#include <omp.h>
#include <sstream>
#include <sys/mman.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "findings.h"
#include "targets.h"

// The fuzzer's own sanitizer defaults (the environment's ASAN_OPTIONS still win):
// an allocation of a gigabyte from a file of a few megabytes is a finding, not a
// reason to swap; leaks are the unit tests' business (workers end with _exit).
extern "C" const char* __asan_default_options() {
    return "max_allocation_size_mb=1024:allocator_may_return_null=0:detect_leaks=0:"
           "hard_rss_limit_mb=4096";
}

namespace {

namespace fs = std::filesystem;
using namespace sherpa::fuzz;
using Clock = std::chrono::steady_clock;

constexpr const char* kUsage =
    "usage: sherpa-fuzz [--seed S] [--runs N] [--time-limit SECONDS] [--target a,b,..]\n"
    "                   [--findings DIR] [--work DIR] [--assets DIR] [--data DIR]\n"
    "                   [--max-size BYTES] [--max-seed-size BYTES] [--case-timeout SECONDS]\n"
    "                   [--max-image-texels N] [--jobs J] [--case I]\n"
    "Runs N cases per target (default all targets; 1000 cases, or as many as fit\n"
    "--time-limit when only that is given), case i of target t made from (S, t, i)\n"
    "alone. --time-limit stops each target after its share. --max-image-texels: the\n"
    "image target probes, without decoding, images declaring more texels.\n"
    "--jobs J runs J worker processes, each every J-th case (the same cases as one job).\n"
    "--case I runs that one case in this process (to debug a reproducer). Exit 0: no\n"
    "findings, 1: findings (saved under --findings), 2: bad usage or no seeds.\n";

void print_usage(const std::vector<std::unique_ptr<Target>>& targets) {
    std::fputs(kUsage, stderr);
    std::fputs("Targets:", stderr);
    for (const auto& t : targets) std::fprintf(stderr, " %s", t->name().c_str());
    std::fputs("\n", stderr);
}

struct Options {
    // runs: cases per target; without --runs, 1000, or no limit with --time-limit.
    std::uint64_t seed = 1, runs = 1000, jobs = 1;
    bool runs_given = false;
    double time_limit = 0;
    double case_timeout = 30;
    std::vector<std::string> targets;
    fs::path findings = "fuzz-findings", work;
    TargetConfig config;
    std::optional<std::uint64_t> single_case;
};

// What the worker and the supervisor share.
struct Shared {
    std::atomic<std::uint64_t> next_case; // the case the worker runs now (or next)
    std::atomic<std::uint64_t> executions;
    std::atomic<std::uint64_t> logic_findings;
};

bool parse(int argc, char** argv, Options& o) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (i + 1 >= argc) return false;
        const std::string v = argv[++i];
        try {
            if (a == "--jobs")
                o.jobs = std::max<std::uint64_t>(1, std::stoull(v));
            else if (a == "--seed")
                o.seed = std::stoull(v);
            else if (a == "--runs")
                o.runs = std::stoull(v), o.runs_given = true;
            else if (a == "--time-limit")
                o.time_limit = std::stod(v);
            else if (a == "--case-timeout")
                o.case_timeout = std::stod(v);
            else if (a == "--findings")
                o.findings = v;
            else if (a == "--work")
                o.work = v;
            else if (a == "--assets")
                o.config.assets_dir = v;
            else if (a == "--data")
                o.config.data_dir = v;
            else if (a == "--max-size")
                o.config.max_size = std::stoull(v);
            else if (a == "--max-image-texels")
                o.config.max_image_texels = std::stoull(v);
            else if (a == "--max-seed-size")
                o.config.max_seed_size = std::stoull(v);
            else if (a == "--case")
                o.single_case = std::stoull(v);
            else if (a == "--target") {
                std::stringstream ss(v);
                for (std::string t; std::getline(ss, t, ',');) o.targets.push_back(t);
            } else
                return false;
        } catch (const std::exception&) {
            return false;
        }
    }
    return true;
}

// Runs cases [shared.next_case, runs) until done or `deadline`; never returns.
[[noreturn]] void worker(Target& target, std::uint64_t target_id, const Options& o, Shared& shared,
                         Clock::time_point deadline, FindingLog& log, const fs::path& stderr_log) {
    const int fd = ::open(stderr_log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) ::dup2(fd, STDERR_FILENO), ::close(fd);
    for (std::uint64_t i = shared.next_case; i < o.runs; shared.next_case = (i += o.jobs)) {
        if (o.time_limit > 0 && Clock::now() > deadline) break;
        ++shared.executions;
        Rng rng = case_rng(o.seed, target_id, i);
        target.make_case(rng);
        if (const auto finding = target.run()) {
            log.save(target, o.seed, i, "wrong result: " + *finding, "");
            ++shared.logic_findings;
        }
    }
    std::fflush(nullptr);
    ::_exit(0);
}

struct TargetResult {
    std::uint64_t executions = 0;
    double seconds = 0;
    std::size_t findings = 0;
    bool init_failed = false; // no seeds: nothing ran
};

// Supervises workers running cases first_case, first_case + jobs, ... of one target.
TargetResult fuzz_target(Target& target, std::uint64_t target_id, const Options& o, Shared& shared,
                         std::uint64_t first_case, FindingLog& log) {
    const auto start = Clock::now();
    const auto deadline =
        start + std::chrono::duration_cast<Clock::duration>(
                    std::chrono::duration<double>(o.time_limit > 0 ? o.time_limit : 1e9));
    const fs::path stderr_log =
        o.work / (target.name() + "-job" + std::to_string(first_case) + "-worker.log");
    shared.next_case = first_case;
    shared.executions = 0;
    shared.logic_findings = 0;
    std::size_t crashes = 0;
    while (shared.next_case < o.runs && !(o.time_limit > 0 && Clock::now() > deadline)) {
        std::fflush(nullptr);
        const pid_t pid = ::fork();
        if (pid == 0) worker(target, target_id, o, shared, deadline, log, stderr_log);
        std::uint64_t last = shared.next_case;
        auto last_progress = Clock::now();
        int status = 0;
        bool hung = false;
        while (::waitpid(pid, &status, WNOHANG) == 0) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            if (shared.next_case != last)
                last = shared.next_case, last_progress = Clock::now();
            else if (Clock::now() - last_progress > std::chrono::duration<double>(o.case_timeout)) {
                ::kill(pid, SIGKILL);
                ::waitpid(pid, &status, 0);
                hung = true;
                break;
            }
        }
        if (!hung && WIFEXITED(status) && WEXITSTATUS(status) == 0) continue;
        // The worker died in case `next_case`: rebuild it here to save it.
        const std::uint64_t i = shared.next_case;
        Rng rng = case_rng(o.seed, target_id, i);
        target.make_case(rng);
        std::string what =
            hung ? "hang: no progress for " + std::to_string(int(o.case_timeout)) + " s"
            : WIFSIGNALED(status) ? "crash: signal " + std::to_string(WTERMSIG(status))
                                  : "crash: exit status " + std::to_string(WEXITSTATUS(status));
        log.save(target, o.seed, i, what, stderr_log);
        ++crashes;
        shared.next_case = i + o.jobs; // the worker counted the case when it began
    }
    TargetResult r;
    r.executions = shared.executions;
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    r.findings = crashes + shared.logic_findings;
    return r;
}

} // namespace

int main(int argc, char** argv) {
    // One thread: cases are tiny, and idle OpenMP workers spinning between them took
    // more CPU than the cases (the fuzzer runs many processes in parallel instead).
    omp_set_num_threads(1);
    Options o;
    o.config.assets_dir = SHERPA_FUZZ_ASSETS_DIR;
    o.config.data_dir = SHERPA_FUZZ_DATA_DIR;
    auto targets = make_targets();
    if (!parse(argc, argv, o)) {
        print_usage(targets);
        return 2;
    }
    // --time-limit alone runs until the time is up, not until the default case count.
    if (o.time_limit > 0 && !o.runs_given) o.runs = UINT64_MAX;
    const bool own_work = o.work.empty(); // a scratch directory of our own: removed at the end
    if (own_work) {
        // Each case is written as files: on a disk, ext4 flushes a rewritten file on
        // close (auto_da_alloc) and cases run 30x slower than in memory.
        std::error_code ec;
        const fs::path shm = "/dev/shm";
        const fs::path base = ::access(shm.c_str(), W_OK) == 0 ? shm : fs::temp_directory_path(ec);
        o.work = base / ("sherpa-fuzz-" + std::to_string(::getpid()));
    }
    std::vector<std::pair<std::uint64_t, Target*>> chosen;
    for (std::uint64_t id = 0; id < targets.size(); ++id)
        if (o.targets.empty() ||
            std::find(o.targets.begin(), o.targets.end(), targets[id]->name()) != o.targets.end())
            chosen.emplace_back(id, targets[id].get());
    if (chosen.empty() || (!o.targets.empty() && chosen.size() != o.targets.size())) {
        std::fputs("sherpa-fuzz: unknown target\n", stderr);
        print_usage(targets);
        return 2;
    }
    if (o.time_limit > 0) o.time_limit /= double(chosen.size());
    // Per job: what its worker and supervisor share, and the supervisor's result.
    struct Job {
        Shared shared;
        TargetResult result;
    };
    auto* jobs = static_cast<Job*>(::mmap(nullptr, sizeof(Job) * o.jobs, PROT_READ | PROT_WRITE,
                                          MAP_SHARED | MAP_ANONYMOUS, -1, 0));
    FindingLog log(o.findings);
    std::size_t total_findings = 0;
    for (auto [id, target] : chosen) {
        auto init = [&, id = id, target = target](const fs::path& work_dir) {
            TargetConfig config = o.config;
            config.work_dir = work_dir;
            std::error_code ec;
            fs::create_directories(config.work_dir, ec);
            std::string error;
            if (target->init(config, error)) return true;
            std::fprintf(stderr, "sherpa-fuzz: %s: %s\n", target->name().c_str(), error.c_str());
            return false;
        };
        if (o.single_case) { // in-process, no fork: for a debugger or a sanitizer report
            if (!init(o.work / target->name())) return 2;
            Rng rng = case_rng(o.seed, id, *o.single_case);
            const fs::path dir = target->make_case(rng);
            std::printf("%s case %llu in %s\n", target->name().c_str(),
                        static_cast<unsigned long long>(*o.single_case), dir.c_str());
            std::fflush(stdout);
            const auto finding = target->run();
            std::printf("%s\n", finding ? finding->c_str() : "no finding");
            total_findings += finding ? 1 : 0;
            continue;
        }
        // One supervisor process per job, each with its own scratch directory.
        std::vector<pid_t> supervisors;
        for (std::uint64_t k = 0; k < o.jobs; ++k) {
            new (&jobs[k]) Job{};
            std::fflush(nullptr);
            const pid_t pid = ::fork();
            if (pid == 0) {
                const fs::path work = o.work / target->name() / ("job" + std::to_string(k));
                if (!init(work))
                    jobs[k].result.init_failed = true;
                else
                    jobs[k].result = fuzz_target(*target, id, o, jobs[k].shared, k, log);
                std::fflush(nullptr);
                ::_exit(0);
            }
            supervisors.push_back(pid);
        }
        TargetResult r;
        for (std::uint64_t k = 0; k < o.jobs; ++k) {
            int status = 0;
            ::waitpid(supervisors[k], &status, 0);
            if (jobs[k].result.init_failed) return 2;
            if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
                // The supervisor itself died (it rebuilds a crashed case to save it): its
                // job's cases are not counted, and the run must not pass as clean.
                std::fprintf(stderr, "sherpa-fuzz: %s job %llu: supervisor died (%s %d)\n",
                             target->name().c_str(), static_cast<unsigned long long>(k),
                             WIFSIGNALED(status) ? "signal" : "exit status",
                             WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
                ++r.findings;
            }
            r.executions += jobs[k].result.executions;
            r.findings += jobs[k].result.findings;
            r.seconds = std::max(r.seconds, jobs[k].result.seconds);
        }
        std::printf("%-8s %10llu executions %8.1f s %9.0f exec/s %6zu findings\n",
                    target->name().c_str(), static_cast<unsigned long long>(r.executions),
                    r.seconds, r.seconds > 0 ? double(r.executions) / r.seconds : 0.0, r.findings);
        std::fflush(stdout);
        total_findings += r.findings;
    }
    log.print_summary();
    std::error_code ec;
    if (own_work) fs::remove_all(o.work, ec);
    return total_findings ? 1 : 0;
}
