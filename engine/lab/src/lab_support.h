#pragma once
// Helpers the families share: CPU clocks, names of scene objects in failures, and a
// counter of work units for RunControl::progress.
#include <algorithm>
#include <cstdint>
#include <ctime>
#include <string>
#include <vector>

#include <sherpa/lab/family.h>

namespace sherpa::lab::detail {

// CPU time of the calling thread: the machine may be shared, and what a method costs
// per core is what the Lab compares.
inline double thread_cpu_ms() {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}
// CPU time of the whole process (OpenMP encoders run on worker threads).
inline double process_cpu_ms() {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// The median of frame times (the upper middle of an even count); 0 for none.
inline double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// "mesh 0 primitive 1 'Helmet'" (the glTF mesh and primitive of an engine mesh).
std::string describe_mesh(const scene::Mesh& mesh);

// Counts units of work and reports them; stop() polls the cancel token.
class Progress {
public:
    Progress(const RunControl& control, std::size_t total) : control_(control), total_(total) {
        report();
    }
    void step() {
        ++done_;
        report();
    }
    bool stop() const { return core::is_cancelled(control_.cancel); }
    // Units skipped (a method that could not run) count as done.
    void finish() {
        done_ = total_;
        report();
    }

private:
    void report() const {
        if (control_.progress) control_.progress(done_, total_);
    }
    const RunControl& control_;
    std::size_t done_ = 0, total_ = 0;
};

// The report a cancelled run returns.
FamilyReport cancelled_report(std::string family);

} // namespace sherpa::lab::detail
