#pragma once
// Records every message the Khronos validation layer (or any debug-utils source)
// emits, so tests can fail on the first one and tools can print them.
#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace sherpa::gpu {

struct ValidationMessage {
    VkDebugUtilsMessageSeverityFlagBitsEXT severity{};
    VkDebugUtilsMessageTypeFlagsEXT types = 0;
    std::string id_name;
    std::string text;
};

class ValidationLog {
public:
    // `enabled`: the validation layer and a messenger feed this log (ContextOptions::validation).
    explicit ValidationLog(bool enabled = false) : enabled_(enabled) {}
    bool enabled() const { return enabled_; }
    void record(ValidationMessage m);
    std::size_t count() const;
    std::vector<ValidationMessage> messages() const;
    void clear();
    // Also print each message to stderr as it arrives (CLI --validation).
    void set_echo(bool echo) { echo_ = echo; }

    static VKAPI_ATTR VkBool32 VKAPI_CALL callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT types,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* user);

private:
    mutable std::mutex mutex_;
    std::vector<ValidationMessage> messages_;
    bool echo_ = false;
    bool enabled_ = false;
};

} // namespace sherpa::gpu
