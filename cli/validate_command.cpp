// sherpa-cli validate FILE|DIR [--json] [--max-severity error|warning|info|hint] [--jobs N]
// The validator's report in the Khronos glTF-Validator's JSON shape; a directory gives
// one line per file and a summary. Exit status: 2 when a reported message is an error
// (a refused file included), 1 when the worst is a warning, 0 otherwise.
#include "cli_common.h"

#include <sherpa/scene/scene_loader.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include <nlohmann/json.hpp>

namespace sherpa::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: sherpa-cli validate FILE|DIR [--json] [--max-severity error|warning|info|hint]\n"
    "                                    [--jobs N]\n"
    "  Reports what is wrong with glTF files, with the Khronos glTF-Validator's codes,\n"
    "  severities and JSON pointers (SHERPA_... for checks of Sherpa's own). --max-severity\n"
    "  (default: hint) reports messages up to that severity. A directory is searched for\n"
    "  .gltf and .glb files: one line per file, then a summary; --jobs N validates N at once.\n"
    "  Exit status: 2 when a reported message is an error or a file cannot be loaded,\n"
    "  1 when the worst is a warning, 0 otherwise (usage errors also exit 2).\n";

struct FileReport {
    std::string path;
    std::vector<scene::ValidationMessage> messages; // reported ones, most severe first
    std::size_t counts[4] = {0, 0, 0, 0};
    bool truncated = false, refused = false;
    double ms = 0;
};

FileReport validate_file(const std::string& path, scene::Severity max) {
    FileReport out;
    out.path = path;
    scene::LoadResult r = scene::load_scene(path);
    scene::ValidationReport& report = r.scene ? r.scene->validation : r.validation;
    out.refused = !r.scene;
    out.truncated = report.truncated;
    out.ms = report.ms;
    for (scene::ValidationMessage& m : report.messages) {
        if (m.severity > max) continue;
        ++out.counts[static_cast<int>(m.severity)];
        out.messages.push_back(std::move(m));
    }
    if (out.refused && report.messages.empty()) { // refused before the validator ran
        out.messages.push_back({"SHERPA_LOAD_REFUSED", r.error, "", scene::Severity::Error});
        ++out.counts[0];
    }
    std::stable_sort(out.messages.begin(), out.messages.end(),
                     [](const auto& a, const auto& b) { return a.severity < b.severity; });
    return out;
}

int exit_status(const FileReport& f) {
    return f.counts[0] ? 2 : f.counts[1] ? 1 : 0;
}

nlohmann::json report_json(const FileReport& f) {
    nlohmann::json messages = nlohmann::json::array();
    for (const auto& m : f.messages) {
        nlohmann::json j = {
            {"code", m.code}, {"message", m.message}, {"severity", static_cast<int>(m.severity)}};
        if (!m.pointer.empty()) j["pointer"] = m.pointer;
        messages.push_back(std::move(j));
    }
    const bool glb = f.path.size() >= 4 && f.path.compare(f.path.size() - 4, 4, ".glb") == 0;
    return {{"uri", f.path},
            {"mimeType", glb ? "model/gltf-binary" : "model/gltf+json"},
            {"validatorVersion", "sherpa"},
            {"loaded", !f.refused},
            {"validation_ms", f.ms},
            {"issues",
             {{"numErrors", f.counts[0]},
              {"numWarnings", f.counts[1]},
              {"numInfos", f.counts[2]},
              {"numHints", f.counts[3]},
              {"messages", std::move(messages)},
              {"truncated", f.truncated}}}};
}

std::string counts_text(const FileReport& f) {
    char text[160];
    std::snprintf(text, sizeof(text), "%zu errors, %zu warnings, %zu infos, %zu hints%s",
                  f.counts[0], f.counts[1], f.counts[2], f.counts[3],
                  f.refused ? " (not loaded)" : "");
    return text;
}

std::vector<std::string> gltf_files(const fs::path& dir, std::string& error) {
    std::vector<std::string> files;
    std::error_code ec;
    for (fs::recursive_directory_iterator
             it(dir, fs::directory_options::skip_permission_denied, ec),
         end;
         !ec && it != end; it.increment(ec)) {
        const auto ext = it->path().extension();
        if ((ext == ".gltf" || ext == ".glb") && it->is_regular_file(ec))
            files.push_back(it->path().string());
    }
    if (ec) error = dir.string() + ": " + ec.message();
    std::sort(files.begin(), files.end());
    return files;
}

} // namespace

int run_validate(Args args) {
    std::string_view target;
    bool as_json = false;
    scene::Severity max = scene::Severity::Hint;
    unsigned jobs = 1;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--json") {
            as_json = true;
        } else if (args[i] == "--max-severity" && i + 1 < args.size()) {
            if (!scene::parse_severity(args[++i], max))
                return usage_error("--max-severity takes error, warning, info or hint", kUsage);
        } else if (args[i] == "--jobs" && i + 1 < args.size()) {
            if (!parse_number(args[++i], jobs) || jobs == 0 || jobs > 256)
                return usage_error("--jobs takes a number from 1 to 256", kUsage);
        } else if (args[i] == "--help" || args[i] == "-h") {
            std::printf("%s", kUsage);
            return kExitOk;
        } else if (!args[i].empty() && args[i][0] == '-') {
            return usage_error("unknown option '" + std::string(args[i]) + "'", kUsage);
        } else if (target.empty()) {
            target = args[i];
        } else {
            return usage_error("more than one FILE|DIR given", kUsage);
        }
    }
    if (target.empty()) return usage_error("no FILE or DIR given", kUsage);
    std::error_code ec;
    if (!fs::is_directory(fs::path(target), ec)) {
        const FileReport f = validate_file(std::string(target), max);
        if (as_json) {
            std::cout << report_json(f).dump(2) << "\n";
        } else {
            std::printf("%s: %s\n", f.path.c_str(), counts_text(f).c_str());
            for (const auto& m : f.messages)
                std::printf("  %s %s%s%s: %s\n", std::string(to_string(m.severity)).c_str(),
                            m.code.c_str(), m.pointer.empty() ? "" : " ", m.pointer.c_str(),
                            m.message.c_str());
            if (f.truncated) std::printf("  (more messages than the report keeps)\n");
        }
        return exit_status(f);
    }
    std::string error;
    const std::vector<std::string> files = gltf_files(fs::path(target), error);
    if (!error.empty()) {
        std::fprintf(stderr, "error: %s\n", error.c_str());
        return kExitLoadError;
    }
    std::vector<FileReport> reports(files.size());
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        for (std::size_t i; (i = next.fetch_add(1)) < files.size();)
            reports[i] = validate_file(files[i], max);
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < std::min<std::size_t>(jobs, files.size()); ++t)
        pool.emplace_back(work);
    work();
    for (auto& t : pool) t.join();
    std::size_t with_errors = 0, with_warnings = 0, refused = 0;
    int status = 0;
    for (const auto& f : reports) {
        with_errors += f.counts[0] > 0;
        with_warnings += f.counts[0] == 0 && f.counts[1] > 0;
        refused += f.refused;
        status = std::max(status, exit_status(f));
    }
    if (as_json) {
        nlohmann::json list = nlohmann::json::array();
        for (const auto& f : reports) list.push_back(report_json(f));
        std::cout << nlohmann::json{{"files", std::move(list)},
                                    {"summary",
                                     {{"files", reports.size()},
                                      {"with_errors", with_errors},
                                      {"with_warnings", with_warnings},
                                      {"not_loaded", refused}}}}
                         .dump(2)
                  << "\n";
    } else {
        for (const auto& f : reports)
            std::printf("%s: %s\n", f.path.c_str(), counts_text(f).c_str());
        std::printf(
            "%zu files: %zu with errors, %zu with warnings only, %zu clean; %zu not loaded\n",
            reports.size(), with_errors, with_warnings,
            reports.size() - with_errors - with_warnings, refused);
    }
    return status;
}

} // namespace sherpa::cli
