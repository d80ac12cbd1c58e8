#pragma once
// The end every GPU subcommand shares: with validation on, any message fails the run.
#include <cstdio>

#include <sherpa/gpu/context.h>

namespace sherpa::cli {

// True, with "error: N Vulkan validation message(s)" on stderr, when `validation` was
// asked for and the layer reported anything; the subcommand then exits kExitLoadError.
inline bool validation_failed(const gpu::Context& context, bool validation) {
    const std::size_t n = context.validation().count();
    if (!validation || n == 0) return false;
    std::fprintf(stderr, "error: %zu Vulkan validation message(s)\n", n);
    return true;
}

} // namespace sherpa::cli
