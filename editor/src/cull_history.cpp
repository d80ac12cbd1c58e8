#include "cull_history.h"

#include <algorithm>

namespace sherpa::editor {

std::uint64_t CullHistory::push(CullSample sample) {
    samples_.push(std::move(sample));
    return ++serial_;
}

bool CullHistory::answer(std::uint64_t serial, const GpuCullResult& result) {
    if (serial != serial_ || samples_.size() == 0) return false;
    CullSample& s = samples_.back();
    s.gpu_ms = result.gpu_ms;
    s.gpu_visible = result.visible;
    s.cpu_gpu_differences = result.differences;
    s.cpu.cpu_gpu_differences = result.differences;
    return true;
}

CullChartSeries cull_chart_series(const CullHistory& history) {
    CullChartSeries out;
    for (std::size_t i = 0; i < history.size(); ++i) {
        const scene::CullStats& c = history[i].cpu;
        out.visible << QPointF(static_cast<double>(i), static_cast<double>(c.visible));
        out.culled << QPointF(static_cast<double>(i), static_cast<double>(c.culled));
        out.top = std::max(out.top, static_cast<double>(c.total));
    }
    return out;
}

} // namespace sherpa::editor
