// Usage texts: placeholders filled from the engine's lists (lab families, debug views,
// overlays) and the option parsers shared by several commands, so that the help never
// lists less than the code accepts.
#include "usage.h"

#include "compare_options.h"
#include "environment_options.h"
#include "shadow_options.h"
#include "texture_cli.h"

#include <sherpa/lab/family.h>
#include <sherpa/render/frame_request.h>

#include <cstdio>
#include <utility>
#include <vector>

namespace sherpa::cli {
namespace {

constexpr const char* kCameraHelp =
    "CAMERA (render, cull and --freeze-cull read it with one parser):\n"
    "  auto               frame what is drawn (posed where --time is given)\n"
    "  gltf:N             the file's camera N as placed in the scene ('info' lists them)\n"
    "  eye=x,y,z:target=x,y,z[:up=x,y,z][:fov=DEG][:aspect=A][:near=N][:far=F]\n";

std::string joined(const std::vector<std::string_view>& names, std::string_view separator) {
    std::string out;
    for (std::string_view n : names)
        out += (out.empty() ? "" : std::string(separator)) + std::string(n);
    return out;
}

// "a, b, c" broken into lines of at most ~90 columns, continued under column 21 (the
// option help's description column).
std::string wrapped(const std::vector<std::string_view>& names) {
    constexpr std::size_t kIndent = 21, kWidth = 90;
    std::string out;
    std::size_t column = kIndent;
    for (std::size_t i = 0; i < names.size(); ++i) {
        const std::string item = std::string(names[i]) + (i + 1 < names.size() ? "," : "");
        if (i > 0 && column + 1 + item.size() > kWidth) {
            out += "\n" + std::string(kIndent, ' ');
            column = kIndent;
        } else if (i > 0) {
            out += ' ';
            ++column;
        }
        out += item;
        column += item.size();
    }
    return out;
}

std::string filled(std::string_view text) {
    const std::pair<std::string_view, std::string> fills[] = {
        {"{families}", joined(lab::family_names(), "|")},
        {"{views}", wrapped(render::debug_view_names())},
        {"{overlays}", wrapped(render::overlay_names())},
        {"{texture-options}", kTextureOptionsSynopsis},
        {"{texture-help}", kTextureOptionsHelp},
        {"{compare-options}", kCompareOptionsSynopsis},
        {"{compare-help}", kCompareOptionsHelp},
        {"{shadow-options}", kShadowOptionsSynopsis},
        {"{environment-options}", kEnvironmentOptionsSynopsis},
        {"{camera-help}", kCameraHelp},
    };
    std::string out(text);
    for (const auto& [key, value] : fills)
        for (std::size_t at = out.find(key); at != std::string::npos;
             at = out.find(key, at + value.size()))
            out.replace(at, key.size(), value);
    return out;
}

const Command* find(std::string_view name) {
    for (const Command& c : commands())
        if (c.name == name) return &c;
    return nullptr;
}

} // namespace

std::string usage_text(std::string_view command) {
    const Command* c = find(command);
    return c ? "usage: " + filled(c->usage) : std::string();
}

std::string overview_text() {
    std::string out = "usage: sherpa-cli COMMAND ... (sherpa-cli COMMAND --help for details)\n\n";
    for (const Command& c : commands()) {
        const std::string text = filled(c.usage);
        out += text.substr(0, text.find("\n\n") + 1);
    }
    out += "\nSCENE is a .gltf/.glb path, builtin:default or builtin:grid?n=N.\n"
           "Exit status: 0 done, 1 load, GPU or output error, 2 bad usage.\n";
    return out;
}

int usage_error(std::string_view message, std::string_view command) {
    std::fprintf(stderr, "error: %.*s\n", int(message.size()), message.data());
    if (find(command))
        std::fprintf(stderr, "run 'sherpa-cli %.*s --help' for usage\n", int(command.size()),
                     command.data());
    else
        std::fprintf(stderr, "%.*s", int(command.size()), command.data());
    return kExitUsage;
}

} // namespace sherpa::cli
