// The engine's headers come first: Qt's QVulkanInstance defines VK_NO_PROTOTYPES,
// which would hide the Vulkan prototypes the engine's handle types are built on.
#include <sherpa/gpu/context.h>
#include <sherpa/gpu/devices.h>
#include <sherpa/render/renderer.h>
#include <sherpa/render/scene_textures.h>

#include "gpu_viewport.h"

#include <QVulkanInstance>

namespace sherpa::editor {

GpuViewport::GpuViewport(std::unique_ptr<gpu::Context> context, bool ray_tracing)
    : context_(std::move(context)) {
    // Acceleration structures only where the device ray traces: without, nothing
    // RT-related is allocated.
    render::RendererOptions options;
    options.ray_tracing = ray_tracing;
    renderer_ = std::make_unique<render::Renderer>(*context_, options);
    scene_ = std::make_unique<ViewportScene>(*renderer_);
    presenter_ = std::make_unique<ViewportPresenter>(*context_, *renderer_, *scene_);
    readbacks_ = std::make_unique<ViewportReadbacks>(*context_, *renderer_, *scene_);
}

GpuViewport::~GpuViewport() {
    // What uses the renderer goes before it, the renderer before the session and
    // environment it was given (ViewportScene) and before its device.
    readbacks_.reset();
    presenter_.reset();
    renderer_.reset();
    scene_.reset();
    context_.reset();
}

void GpuViewport::configureInstance(QVulkanInstance& instance) {
    const bool validation = gpu::ContextOptions::default_validation();
    QByteArrayList extensions;
    for (const std::string& e : gpu::Context::required_instance_extensions(validation, true))
        extensions << QByteArray::fromStdString(e);
    instance.setApiVersion(QVersionNumber(1, 3));
    instance.setExtensions(extensions); // Qt adds the platform's surface extension itself
    if (validation) instance.setLayers({QByteArrayLiteral("VK_LAYER_KHRONOS_validation")});
}

std::unique_ptr<GpuViewport> GpuViewport::create(QVulkanInstance& instance, bool ray_tracing,
                                                 QString& error) {
    try {
        gpu::ContextOptions options;
        options.external_instance = instance.vkInstance();
        options.presentation = true;
        options.ray_tracing = ray_tracing;
        auto context = std::make_unique<gpu::Context>(options);
        const bool rays = context->info().ray_tracing_enabled;
        return std::unique_ptr<GpuViewport>(new GpuViewport(std::move(context), rays));
    } catch (const std::exception& e) {
        error = QString::fromUtf8(e.what());
        return nullptr;
    }
}

QStringList GpuViewport::deviceNames(void* instance) {
    QStringList names;
    for (const gpu::DeviceSummary& d : gpu::enumerate_devices(static_cast<VkInstance>(instance)))
        names << QString::fromStdString(gpu::describe(d));
    return names;
}

QString GpuViewport::deviceName() const {
    const gpu::DeviceInfo& info = context_->info();
    return QStringLiteral("%1 (Vulkan %2.%3.%4)")
        .arg(QString::fromStdString(info.name))
        .arg(VK_API_VERSION_MAJOR(info.api_version))
        .arg(VK_API_VERSION_MINOR(info.api_version))
        .arg(VK_API_VERSION_PATCH(info.api_version));
}

tex::TextureTarget GpuViewport::textureTarget() const {
    return render::texture_target(context_->info(), render::TextureSettings{});
}

bool GpuViewport::rayTracing() const {
    return context_->info().ray_tracing_enabled;
}

UploadedScene GpuViewport::load(SharedSession session, const ViewportRequest& frame,
                                bool missing_checker) {
    readbacks_->forgetScene(); // its buffers were built for the scene that leaves
    return scene_->load(std::move(session), frame, missing_checker);
}

void GpuViewport::finish() {
    context_->wait_idle();
}

} // namespace sherpa::editor
