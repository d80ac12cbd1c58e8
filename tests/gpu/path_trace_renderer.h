#pragma once
// The one ray-tracing renderer of the path tracer's GPU tests (path_trace_tests): made on
// first use on the tests' device, shared by every fixture of the binary.
#include "gpu_test_support.h"

#include <memory>

namespace sherpa::test {

inline render::Renderer& path_trace_renderer() {
    static std::unique_ptr<render::Renderer> r = [] {
        render::RendererOptions options;
        options.ray_tracing = true;
        options.textures = test_texture_settings();
        return std::make_unique<render::Renderer>(*GpuEnvironment::get().context, options);
    }();
    return *r;
}

} // namespace sherpa::test
