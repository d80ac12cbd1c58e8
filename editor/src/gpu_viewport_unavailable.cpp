// GpuViewport for builds without the engine renderer (engine/gpu not yet merged):
// creation fails with a clear message and the viewport stays empty. Nothing here
// draws; it only lets the rest of the editor build and run.
#include "gpu_viewport.h"

#include <QVulkanInstance>

namespace sherpa::editor {

struct GpuViewport::Impl {};

GpuViewport::GpuViewport(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GpuViewport::~GpuViewport() = default;

void GpuViewport::configureInstance(QVulkanInstance& instance) {
    instance.setApiVersion(QVersionNumber(1, 3));
}

std::unique_ptr<GpuViewport> GpuViewport::create(QVulkanInstance&, bool, QString& error) {
    error = QStringLiteral("this build has no renderer (engine/gpu)");
    return nullptr;
}

QString GpuViewport::deviceName() const {
    return {};
}
TexturePlan GpuViewport::texturePlan() const {
    return {};
}
PreparedTextures prepareTextures(const TexturePlan&, const Scene&, const ProgressCallback&,
                                 const CancelToken*) {
    return nullptr;
}
void GpuViewport::setMissingTexturesChecker(bool) {}
void GpuViewport::setReducedFramePrepass(bool) {}
void GpuViewport::setSession(SharedSession) {}
void GpuViewport::useStreamsFor(const ViewportFrame&) {}
void GpuViewport::upload() {}
void GpuViewport::finish() {}
QString GpuViewport::lastRefusal() const {
    return {};
}
DifferenceNumbers GpuViewport::lastDifference() const {
    return {};
}
bool GpuViewport::rayTracing() const {
    return false;
}
std::shared_ptr<const gpu::AccelerationStats> GpuViewport::accelerationStats() const {
    return nullptr;
}
QStringList GpuViewport::lastPassTimes() const {
    return {};
}
double GpuViewport::lastGpuMs() const {
    return -1.0;
}
const Scene* GpuViewport::scene() const {
    return nullptr;
}
bool GpuViewport::checkGpuCulling(const Frustum&, CullMethod, const std::vector<std::uint8_t>&,
                                  GpuCullCheck&) {
    return false;
}
bool GpuViewport::lastCullPasses(std::vector<CullStats>&, bool&) const {
    return false;
}
bool GpuViewport::present(std::uint64_t, const ViewportFrame&, float) {
    return false;
}
void GpuViewport::releaseSurface() {}
std::optional<GpuMaterialReadback> GpuViewport::readMaterial(int) {
    return std::nullopt;
}
QStringList GpuViewport::validationMessages() const {
    return {};
}
std::int64_t GpuViewport::objectCount() const {
    return -1;
}
std::uint64_t GpuViewport::textureBytes() const {
    return 0;
}

QStringList GpuViewport::deviceNames(void*) {
    return {};
}

} // namespace sherpa::editor
