#include <sherpa/gpu/validation.h>

#include <cstdio>

namespace sherpa::gpu {

void ValidationLog::record(ValidationMessage m) {
    std::lock_guard lock(mutex_);
    if (echo_) std::fprintf(stderr, "vulkan: [%s] %s\n", m.id_name.c_str(), m.text.c_str());
    messages_.push_back(std::move(m));
}

std::size_t ValidationLog::count() const {
    std::lock_guard lock(mutex_);
    return messages_.size();
}

std::vector<ValidationMessage> ValidationLog::messages() const {
    std::lock_guard lock(mutex_);
    return messages_;
}

void ValidationLog::clear() {
    std::lock_guard lock(mutex_);
    messages_.clear();
}

VKAPI_ATTR VkBool32 VKAPI_CALL ValidationLog::callback(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* log = static_cast<ValidationLog*>(user);
    ValidationMessage m;
    m.severity = severity;
    m.types = types;
    if (data) {
        m.id_name = data->pMessageIdName ? data->pMessageIdName : "";
        m.text = data->pMessage ? data->pMessage : "";
    }
    log->record(std::move(m));
    return VK_FALSE; // never abort the call: the test decides what a message means
}

} // namespace sherpa::gpu
