#include "findings.h"

#include <cctype>
#include <cstdio>
#include <deque>
#include <fcntl.h>
#include <fstream>
#include <map>
#include <unistd.h>

namespace sherpa::fuzz {

namespace fs = std::filesystem;

namespace {

constexpr int kReproducersPerSignature = 3;

// The last lines of the worker's log: the sanitizer report of the case that died.
std::string tail_of(const fs::path& log, std::size_t lines) {
    std::ifstream in(log);
    std::deque<std::string> last;
    for (std::string line; std::getline(in, line);) {
        last.push_back(line);
        if (last.size() > lines) last.pop_front();
    }
    std::string out;
    for (const auto& l : last) out += l + "\n";
    return out;
}

// What identifies a cause: the sanitizer's SUMMARY line without addresses, else
// the finding's text without numbers.
std::string signature_of(const std::string& what, const std::string& report) {
    std::string sig = what;
    // An uncaught exception leaves no SUMMARY, only its what().
    for (const char* mark : {"SUMMARY: ", "what():  "}) {
        const auto at = report.rfind(mark);
        if (at == std::string::npos) continue;
        sig = report.substr(at, report.find('\n', at) - at);
        break;
    }
    // Numbers (addresses, lines of a log, sizes) vary between cases of one cause.
    std::string out;
    for (std::size_t i = 0; i < sig.size(); ++i) {
        const bool hex = sig.compare(i, 2, "0x") == 0;
        if (hex || std::isdigit(static_cast<unsigned char>(sig[i]))) {
            i += hex ? 2 : 0;
            while (i < sig.size() && std::isxdigit(static_cast<unsigned char>(sig[i]))) ++i;
            out += 'N';
            --i;
        } else {
            out += sig[i] == '\t' || sig[i] == '\n' ? ' ' : sig[i];
        }
    }
    return out;
}

std::map<std::string, std::pair<int, std::string>> read_index(const fs::path& index) {
    std::map<std::string, std::pair<int, std::string>> counts; // signature -> count, first dir
    std::ifstream in(index);
    for (std::string line; std::getline(in, line);) {
        const auto tab = line.find('\t');
        if (tab == std::string::npos) continue;
        auto& [count, dir] = counts[line.substr(tab + 1)];
        if (count++ == 0) dir = line.substr(0, tab);
    }
    return counts;
}

} // namespace

FindingLog::FindingLog(fs::path dir) : dir_(std::move(dir)) {}

void FindingLog::save(const Target& target, std::uint64_t seed, std::uint64_t index,
                      const std::string& what, const fs::path& report) {
    std::error_code ec;
    fs::create_directories(dir_, ec);
    const std::string log_text = report.empty() ? "" : tail_of(report, 80);
    const std::string sig = target.name() + ": " + signature_of(what, log_text);
    const std::string name =
        target.name() + "-seed" + std::to_string(seed) + "-case" + std::to_string(index);
    const auto counts = read_index(dir_ / "index.tsv");
    const auto known = counts.find(sig);
    const bool keep = known == counts.end() || known->second.first < kReproducersPerSignature;
    const std::string line = (keep ? name : "-") + "\t" + sig + "\n";
    const int fd = ::open((dir_ / "index.tsv").c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0) {
        if (::write(fd, line.data(), line.size()) < 0) std::perror("sherpa-fuzz: index.tsv");
        ::close(fd);
    }
    if (!keep) return;
    const fs::path out = dir_ / name;
    fs::create_directories(out, ec);
    for (const fs::path& f : target.case_files())
        if (fs::is_regular_file(f, ec))
            fs::copy_file(f, out / f.filename(), fs::copy_options::overwrite_existing, ec);
    std::ofstream info(out / "finding.txt");
    info << what << "\nsignature: " << sig << "\ncase directory: "
         << (target.case_files().empty() ? fs::path() : target.case_files().front().parent_path())
                .string()
         << "\nreplay: sherpa-fuzz --target " << target.name() << " --seed " << seed << " --case "
         << index << "\n\n"
         << log_text;
}

void FindingLog::print_summary() const {
    const auto counts = read_index(dir_ / "index.tsv");
    for (const auto& [sig, entry] : counts)
        std::printf("%6d x %s\n         e.g. %s\n", entry.first, sig.c_str(),
                    (dir_ / entry.second).c_str());
}

} // namespace sherpa::fuzz
