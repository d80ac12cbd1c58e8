#pragma once
// Shared conventions of sherpa-cli subcommands: exit codes and argument access.
#include <span>
#include <string>
#include <string_view>

namespace sherpa::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitLoadError = 1; // message on stderr starting "error:"
inline constexpr int kExitUsage = 2;

using Args = std::span<const std::string_view>;

int run_info(Args args);
int run_cull(Args args);
int run_tangents(Args args);
int run_textures(Args args);
int run_render(Args args);
int run_lab(Args args);
int run_compare(Args args);
int run_budget(Args args);
int run_rt(Args args);

} // namespace sherpa::cli
