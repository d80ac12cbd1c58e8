#pragma once
// Shared conventions of sherpa-cli subcommands: exit codes, argument access and the
// parsing every subcommand does the same way.
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <string_view>

namespace sherpa::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitLoadError = 1; // message on stderr starting "error:"
inline constexpr int kExitUsage = 2;

using Args = std::span<const std::string_view>;

// "error: MESSAGE" and a pointer to `sherpa-cli COMMAND --help` on stderr; returns
// kExitUsage. (`command` that names no command is printed as given: a usage text.)
int usage_error(std::string_view message, std::string_view command);

// A number, all of `v` (std::from_chars: no sign for unsigned, "nan"/"inf" for floats).
template <typename T> bool parse_number(std::string_view v, T& out) {
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), out);
    return ec == std::errc{} && end == v.data() + v.size();
}

// A non-negative integer, all of `v`.
inline bool parse_index(std::string_view v, std::int32_t& out) {
    return parse_number(v, out) && out >= 0;
}

int run_info(Args args);
int run_cull(Args args);
int run_tangents(Args args);
int run_textures(Args args);
int run_render(Args args);
int run_lab(Args args);
int run_compare(Args args);
int run_budget(Args args);
int run_rt(Args args);
int run_validate(Args args);

} // namespace sherpa::cli
