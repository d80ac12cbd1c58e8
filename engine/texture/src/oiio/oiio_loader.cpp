// Loads libsherpa_oiio.so on first use. Looked for, in order: $SHERPA_OIIO_PLUGIN (a
// file), next to the running executable, and where the build put it.
#include "oiio_plugin_api.h"

#include <dlfcn.h>

#include <atomic>
#include <cstdlib>
#include <mutex>
#include <system_error>
#include <vector>

namespace sherpa::tex::oiio {
namespace {

constexpr const char* kModuleName = "libsherpa_oiio.so";

std::vector<std::filesystem::path> candidate_paths() {
    std::vector<std::filesystem::path> paths;
    if (const char* env = std::getenv("SHERPA_OIIO_PLUGIN"); env && *env) paths.emplace_back(env);
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) paths.push_back(exe.parent_path() / kModuleName);
#ifdef SHERPA_OIIO_PLUGIN_BUILD_PATH
    paths.emplace_back(SHERPA_OIIO_PLUGIN_BUILD_PATH);
#endif
    return paths;
}

struct Loaded {
    const PluginApi* api = nullptr;
    std::string error;
};

Loaded load() {
    Loaded l;
    std::string tried;
    for (const std::filesystem::path& path : candidate_paths()) {
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) {
            tried += "\n  " + path.string() + ": not found";
            continue;
        }
        // Never closed: decoded images and OpenImageIO's own state outlive any caller.
        void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!module) {
            tried += "\n  " + path.string() + ": " + dlerror();
            continue;
        }
        const auto entry = reinterpret_cast<EntryPoint>(dlsym(module, kEntryPoint));
        const PluginApi* api = entry ? entry() : nullptr;
        if (!api || api->abi != kPluginAbi) {
            tried += "\n  " + path.string() + ": not a matching Sherpa OpenImageIO plugin";
            continue;
        }
        l.api = api;
        return l;
    }
    l.error = std::string("OpenImageIO plugin (") + kModuleName + ") not loaded:" + tried;
    return l;
}

std::atomic<bool> g_loaded{false};

} // namespace

const PluginApi* plugin(std::string& error) {
    static const Loaded loaded = [] {
        Loaded l = load();
        g_loaded = l.api != nullptr;
        return l;
    }();
    if (!loaded.api) error = loaded.error;
    return loaded.api;
}

bool plugin_loaded() {
    return g_loaded;
}

} // namespace sherpa::tex::oiio
