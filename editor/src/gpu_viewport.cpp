// The engine's headers come first: Qt's QVulkanInstance defines VK_NO_PROTOTYPES,
// which would hide the Vulkan prototypes the engine's handle types are built on.
#include <sherpa/gpu/context.h>
#include <sherpa/gpu/devices.h>
#include <sherpa/gpu/gpu_error.h>
#include <sherpa/gpu/presenter.h>
#include <sherpa/render/acceleration_structures.h>
#include <sherpa/render/cull_check.h>
#include <sherpa/render/gpu_scene.h>
#include <sherpa/render/material_readback.h>
#include <sherpa/render/presented_frame.h>
#include <sherpa/render/renderer.h>

#include "gpu_viewport_impl.h"

#include <QVulkanInstance>
#include <cstring>

namespace sherpa::editor {

GpuViewport::GpuViewport(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

GpuViewport::~GpuViewport() {
    if (!impl_) return;
    impl_->culler.reset();
    impl_->presenter.reset();
    impl_->b = {};
    impl_->renderer.reset();
    impl_->context.reset();
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
        auto impl = std::make_unique<Impl>();
        gpu::ContextOptions options;
        options.external_instance = instance.vkInstance();
        options.presentation = true;
        options.ray_tracing = ray_tracing;
        impl->context = std::make_unique<gpu::Context>(options);
        // Acceleration structures only where the device ray traces: without, nothing
        // RT-related is allocated.
        gpu::RendererOptions renderer;
        renderer.ray_tracing = impl->context->info().ray_tracing_enabled;
        impl->renderer = std::make_unique<gpu::Renderer>(*impl->context, renderer);
        return std::unique_ptr<GpuViewport>(new GpuViewport(std::move(impl)));
    } catch (const std::exception& e) {
        error = QString::fromUtf8(e.what());
        return nullptr;
    }
}

QString GpuViewport::deviceName() const {
    const gpu::DeviceInfo& info = impl_->context->info();
    return QStringLiteral("%1 (Vulkan %2.%3.%4)")
        .arg(QString::fromStdString(info.name))
        .arg(VK_API_VERSION_MAJOR(info.api_version))
        .arg(VK_API_VERSION_MINOR(info.api_version))
        .arg(VK_API_VERSION_PATCH(info.api_version));
}

tex::TextureTarget GpuViewport::textureTarget() const {
    return gpu::texture_target(impl_->context->info(), gpu::TextureSettings{});
}

void GpuViewport::setReducedFramePrepass(bool prepass) {
    impl_->reduced_prepass = prepass;
}

GpuViewport::Uploaded GpuViewport::load(SharedSession session, const ViewportRequest& frame,
                                        bool missing_checker) {
    // The old scene leaves first (its memory is free for the new one), and the stream
    // policy and missing-texture mode are set before the one upload.
    impl_->culler.reset();
    impl_->session.reset();
    impl_->renderer->unload();
    impl_->missing =
        missing_checker ? gpu::MissingTextures::Checker : gpu::MissingTextures::Neutral;
    impl_->all_streams = gpu::needs_all_streams(frame.request);
    impl_->session = std::move(session);
    upload();
    Uploaded out;
    if (const gpu::GpuScene* scene = impl_->renderer->scene())
        out.textureBytes = scene->materials().textures().gpu_bytes();
    if (const gpu::AccelerationStats* stats = impl_->renderer->resident().acceleration)
        out.acceleration = std::make_shared<const gpu::AccelerationStats>(*stats);
    return out;
}

// The current scene to the GPU with the current stream policy.
void GpuViewport::upload() {
    if (!impl_->session) {
        impl_->renderer->unload();
        return;
    }
    load_session(*impl_->renderer, *impl_->session, impl_->all_streams, impl_->missing);
}

void load_session(gpu::Renderer& renderer, const SceneSession& session, bool all_streams,
                  gpu::MissingTextures missing) {
    // No textures prepared (cancelled, no plan): an empty set, so that load() does
    // not run the texture pipeline on this thread.
    PreparedTextures textures = session.textures;
    if (!textures) textures = std::make_shared<const tex::PreparedTextureSet>();
    gpu::SceneSetup setup;
    setup.streams =
        all_streams ? gpu::StreamPolicy::AllPresent : gpu::StreamPolicy::UsedByMaterials;
    setup.missing_textures = missing;
    renderer.load(*session.scene, std::move(textures), setup); // hidden nodes: per present()
}

QStringList GpuViewport::setEnvironment(const gpu::EnvironmentChoice& choice) {
    std::vector<std::string> warnings;
    auto image = gpu::make_environment(choice, warnings);
    impl_->environment =
        image ? std::make_shared<const gpu::EnvironmentImage>(std::move(*image)) : nullptr;
    impl_->renderer->set_environment(impl_->environment.get());
    // A comparison's side B is lit alike (its renderer keeps its own maps).
    if (impl_->b.renderer) impl_->b.renderer->set_environment(impl_->environment.get());
    QStringList out;
    for (const std::string& w : warnings) out << QString::fromStdString(w);
    return out;
}

void GpuViewport::useStreamsFor(const ViewportRequest& frame) {
    const bool all = gpu::needs_all_streams(frame.request);
    if (all == impl_->all_streams) return;
    impl_->all_streams = all;
    upload();
}

gpu::Renderer& GpuViewport::renderer() {
    return *impl_->renderer;
}

const Scene* GpuViewport::scene() const {
    return impl_->session ? impl_->session->scene.get() : nullptr;
}

bool GpuViewport::rayTracing() const {
    return impl_->context->info().ray_tracing_enabled;
}

QStringList GpuViewport::lastPassTimes() const {
    QStringList out;
    if (!impl_->presenter) return out;
    for (const gpu::PassTiming& p : impl_->completed.passes)
        out << QStringLiteral("%1 %2 ms").arg(QString::fromStdString(p.name)).arg(p.ms, 0, 'f', 1);
    return out;
}

void GpuViewport::finish() {
    impl_->context->wait_idle();
}

void GpuViewport::releaseSurface() {
    impl_->presenter.reset();
    impl_->completed = {};
    impl_->surface = 0;
}

void apply_display(const ViewportDisplay& d, gpu::FrameRequest& settings) {
    settings.environment_rotation = d.environmentRotation;
    settings.environment_intensity = d.environmentIntensity;
    settings.background = d.background;
    if (d.background == gpu::Background::Color)
        settings.clear_color = glm::vec4(d.backgroundColor, 1.0f);
    settings.tone_map = d.toneMap;
    settings.exposure = d.exposure;
    settings.sun = d.sun;
    settings.energy_compensation = d.energyCompensation;
}

gpu::FrameRequest drawn_request(const ViewportRequest& frame, float scale, bool reduced_prepass) {
    gpu::FrameRequest settings = frame.request;
    // A reduced frame means a slow device while the camera moves: the shadow cascades
    // follow the camera and cost the same at any resolution (DamagedHelmet on lavapipe:
    // 165 of 245 ms), so moving frames go without them; the still frame has them.
    // So does the depth prepass, unless asked for (setReducedFramePrepass).
    if (scale < 1.0f) settings.shadows = false;
    if (scale < 1.0f && !reduced_prepass) settings.depth_prepass = gpu::PrepassMode::Off;
    // Rays draw the surface only: overlays and the selection are the rasterizer's,
    // and a comparison shows the two sides' surfaces, nothing drawn over one of them.
    if (frame.compare.rays() || frame.compare.comparing()) {
        settings.overlays = 0;
        settings.highlight_instance.reset();
        settings.highlight_triangle.reset();
        settings.highlight_vertex.reset();
        settings.highlight_outline.clear();
    }
    if (frame.compare.mode == ViewportMode::RayTraced) {
        settings.renderer = gpu::RendererKind::RayTraced;
        // The lit view is path traced: one sample per frame, accumulated while
        // nothing changes (the render thread keeps drawing until kPathSamples).
        settings.path.samples = 1;
        settings.path.max_samples = GpuViewport::kPathSamples;
    }
    return settings;
}

void GpuViewport::preparePresenter(std::uint64_t surface, const gpu::FrameRequest& frame) {
    if (!impl_->presenter || impl_->surface != surface) {
        impl_->presenter.reset();
        // Not FIFO: the render thread must not block on the display's refresh, and
        // Mesa's X11 path then puts the image to the server within the present call,
        // so a screenshot taken after it sees this frame, not an earlier one.
        gpu::PresenterOptions options;
        options.vsync = false;
        impl_->presenter = std::make_unique<gpu::Presenter>(
            *impl_->context, impl_->renderer->resources(), reinterpret_cast<VkSurfaceKHR>(surface),
            frame.width, frame.height, options);
        impl_->surface = surface;
        impl_->width = frame.width;
        impl_->height = frame.height;
    } else if (frame.width != impl_->width || frame.height != impl_->height) {
        impl_->presenter->resize(frame.width, frame.height);
        impl_->width = frame.width;
        impl_->height = frame.height;
    }
}

PresentOutcome GpuViewport::present(std::uint64_t surface, const ViewportRequest& frame,
                                    float scale) {
    return outcome(draw(surface, frame, scale));
}

PresentOutcome GpuViewport::outcome(bool shown) const {
    const Impl& i = *impl_;
    PresentOutcome out;
    out.shown = shown;
    out.refused = i.refusal;
    out.difference = i.difference;
    out.path_traced = i.path_traced;
    out.path_samples = i.path_samples;
    out.path_error = i.path_error;
    // GPU time (timestamps, first to last pass) of the latest completed frame.
    if (i.presenter && !i.completed.passes.empty()) out.gpu_ms = i.completed.gpu_ms;
    const auto& h = i.renderer->cull_history();
    if (h.size() > 0) {
        const gpu::CullFrame& f = h[h.size() - 1];
        out.cull_passes = true;
        out.passes = f.passes;
        out.cached_shadows = !f.shadows_rendered;
    }
    return out;
}

bool GpuViewport::draw(std::uint64_t surface, const ViewportRequest& frame, float scale) {
    impl_->refusal.clear();
    if (!surface || frame.request.width == 0 || frame.request.height == 0) return false;
    const gpu::FrameRequest settings = drawn_request(frame, scale, impl_->reduced_prepass);
    preparePresenter(surface, frame.request);
    impl_->renderer->set_hidden_nodes(frame.hiddenNodes); // unchanged: one comparison
    if (frame.compare.comparing()) return presentComparison(frame, settings, scale);
    impl_->b = {}; // side B lives only while comparing
    impl_->difference = {};
    std::optional<gpu::PresentedFrame> presented;
    try {
        presented.emplace(*impl_->renderer, settings, scale);
    } catch (const gpu::GpuError& e) { // refused before anything was recorded
        if (settings.renderer != gpu::RendererKind::RayTraced) throw;
        impl_->refusal = QString::fromUtf8(e.what());
        return false;
    }
    const bool shown = impl_->presenter->present_frame(*presented);
    impl_->completed = presented->completed_stats(); // garbage: the presenter collects it
    notePathSamples(settings);
    return shown;
}

// The accumulation after this frame (the renderer counts it when it records), and its
// error read back at each power of two from 4 samples (the sums are read back: a cost
// that halves in frequency as the image converges).
void GpuViewport::notePathSamples(const gpu::FrameRequest& settings) {
    Impl& i = *impl_;
    if (settings.renderer != gpu::RendererKind::RayTraced || settings.view != gpu::DebugView::Lit) {
        i.path_traced = false;
        i.path_samples = i.path_error_samples = 0;
        i.path_error = -1.0;
        return;
    }
    i.path_traced = true;
    // The completed frame's count (kFramesInFlight behind): no readback for it.
    const std::uint32_t n = i.completed.path.samples;
    if (n < i.path_samples) i.path_error = -1.0; // started over
    i.path_samples = n;
    if (n >= 4 && (n & (n - 1)) == 0 && n != i.path_error_samples) {
        i.path_error = gpu::path_trace_error(*i.renderer).relative_error;
        i.path_error_samples = n;
    }
}

std::optional<GpuMaterialReadback> GpuViewport::readMaterial(int material) {
    if (!scene()) return std::nullopt;
    std::optional<gpu::MaterialReadback> r =
        gpu::read_material(*impl_->renderer, *scene(), material);
    if (!r) return std::nullopt;
    return GpuMaterialReadback{r->record, std::move(r->bindless_to_texture)};
}

} // namespace sherpa::editor

namespace sherpa::editor {} // namespace sherpa::editor

namespace sherpa::editor {

bool GpuViewport::checkGpuCulling(const Frustum& frustum, CullMethod method,
                                  const std::vector<std::uint8_t>& cpu_visible, GpuCullCheck& out) {
    const Scene* scene = this->scene();
    if (!scene || scene->instances.empty()) return false;
    if (!impl_->culler || &impl_->culler->scene() != scene)
        impl_->culler = std::make_unique<gpu::GpuCullChecker>(*impl_->context,
                                                              impl_->renderer->resources(), *scene);
    const gpu::GpuCullComparison r = impl_->culler->compare(frustum, method, cpu_visible);
    out = {};
    out.gpu_ms = r.gpu_ms;
    out.visible = static_cast<decltype(out.visible)>(r.visible.size());
    out.differences = static_cast<decltype(out.differences)>(r.differences);
    return true;
}

QStringList GpuViewport::deviceNames(void* instance) {
    QStringList names;
    for (const gpu::DeviceSummary& d : gpu::enumerate_devices(static_cast<VkInstance>(instance)))
        names << QString::fromStdString(gpu::describe(d));
    return names;
}

} // namespace sherpa::editor
