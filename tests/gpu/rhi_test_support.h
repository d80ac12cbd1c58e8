#pragma once
// The RHI's own tests (engine/gpu, label `gpu`): a Vulkan context under the Khronos
// validation layer and nothing of the renderer above it.
#include <gtest/gtest.h>

#include <cstddef>
#include <memory>

#include <sherpa/core/heap_tuning.h>
#include <sherpa/gpu/context.h>

namespace sherpa::test {

// Fails the running test for every validation message after the first `seen`.
inline void expect_no_validation_since(const gpu::Context& context, std::size_t seen) {
    const auto messages = context.validation().messages();
    for (std::size_t i = seen; i < messages.size(); ++i)
        ADD_FAILURE() << "validation: [" << messages[i].id_name << "] " << messages[i].text;
}

inline gpu::Context& rhi_context() {
    static const std::unique_ptr<gpu::Context> context = [] {
        core::keep_freed_memory_mapped(); // as every application does, before any device exists
        gpu::ContextOptions options;
        options.validation = true; // every GPU test runs under the Khronos layer
        return std::make_unique<gpu::Context>(options);
    }();
    return *context;
}

class RhiTest : public ::testing::Test {
protected:
    gpu::Context& context() { return rhi_context(); }
    void SetUp() override { seen_ = context().validation().count(); }
    void TearDown() override { expect_no_validation_since(context(), seen_); }

private:
    std::size_t seen_ = 0;
};

} // namespace sherpa::test
