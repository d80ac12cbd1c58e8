#pragma once
// One usage text per sherpa-cli command, in main.cpp's command table: printed by
// `sherpa-cli COMMAND --help` and `sherpa-cli --help`, and checked against the README
// (tests/cli/check_readme_usage.py). A usage error prints one line and a pointer to
// --help.
#include "cli_common.h"

#include <span>
#include <string>
#include <string_view>

namespace sherpa::cli {

struct Command {
    std::string_view name;
    int (*run)(Args);
    // "SYNOPSIS\n[\nDETAILS]": the synopsis lines start with "sherpa-cli NAME" (or
    // continue one with an indent); the details follow one blank line. Placeholders
    // {families}, {views}, {overlays}, {texture-options}, {texture-help},
    // {compare-options}, {compare-help}, {shadow-options}, {environment-options} and {camera-help}
    // are filled from the engine's own lists and the shared option parsers.
    std::string_view usage;
};

// main.cpp's table.
std::span<const Command> commands();

// The command's usage text with its placeholders filled; empty for an unknown name.
std::string usage_text(std::string_view command);

// The help of the whole CLI: every command's synopsis, and where the details are.
std::string overview_text();

} // namespace sherpa::cli
