#include "engine_probe.h"

#include <sherpa/gpu/context.h>
#include <sherpa/gpu/resources.h>
#include <sherpa/gpu/validation.h>
#include <sherpa/render/renderer.h>

#include "gpu_viewport.h"

namespace sherpa::editor::test {

QStringList validation_messages(GpuViewport& gpu) {
    QStringList out;
    for (const gpu::ValidationMessage& m : gpu.renderer().context().validation().messages())
        out << QStringLiteral("[%1] %2").arg(QString::fromStdString(m.id_name),
                                             QString::fromStdString(m.text));
    return out;
}

std::int64_t gpu_object_count(GpuViewport& gpu) {
    // Settle first: objects retired by earlier frames are freed once the GPU is idle.
    gpu.renderer().resources().flush();
    return static_cast<std::int64_t>(gpu.renderer().resources().counts().total());
}

QStringList last_pass_times(GpuViewport& gpu) {
    QStringList out;
    for (const render::PassTiming& p : gpu.presenter().completed().passes)
        out << QStringLiteral("%1 %2 ms").arg(QString::fromStdString(p.name)).arg(p.ms, 0, 'f', 1);
    return out;
}

} // namespace sherpa::editor::test
