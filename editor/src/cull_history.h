#pragma once
// The culling dock's record of the CPU culling passes: the last kCapacity of them,
// oldest first, each with the GPU culling check's answer once it comes (for the pass
// it was asked about only), and the chart's series drawn from them.
#include <QList>
#include <QPointF>

#include <cstdint>

#include <sherpa/scene/culling_passes.h>

namespace sherpa::editor {

struct CullSample {
    scene::CullStats cpu;
    bool frozen = false; // culled with the frozen camera (Culling › Freeze)
    // The GPU culling shader run for the same frustum and method while the GPU path
    // is on (the dock's agreement indicator); -1: not run.
    double gpu_ms = -1.0;
    std::int64_t gpu_visible = -1;
    std::int64_t cpu_gpu_differences = -1; // objects the two paths disagree on
};

// What the GPU culling shader made of a frustum, against the CPU's visible set.
struct GpuCullResult {
    double gpu_ms = -1.0;
    std::int64_t visible = -1;
    std::int64_t differences = -1; // objects the two paths disagree on
};

class CullHistory {
public:
    static constexpr std::size_t kCapacity = 240;

    // Records a pass (the oldest goes when full); returns its serial number, which the
    // GPU check's answer for it names. Serials never repeat, clear() or not.
    std::uint64_t push(CullSample sample);
    // The GPU check's answer for pass `serial`, kept while that pass is the newest;
    // false (dropped) once a newer pass (camera, scene, method) asked again.
    bool answer(std::uint64_t serial, const GpuCullResult& result);
    void clear() { samples_ = scene::RingHistory<CullSample>(kCapacity); }
    std::size_t size() const { return samples_.size(); }
    const CullSample& operator[](std::size_t i) const { return samples_[i]; } // 0 = oldest
    const CullSample* latest() const {
        return samples_.size() ? &samples_[samples_.size() - 1] : nullptr;
    }

private:
    scene::RingHistory<CullSample> samples_{kCapacity};
    std::uint64_t serial_ = 0; // of the newest pass
};

// The chart's series: objects kept and culled per pass at x = its index (oldest 0),
// and the y range's top (the largest object count, at least 1).
struct CullChartSeries {
    QList<QPointF> visible, culled;
    double top = 1.0;
};
CullChartSeries cull_chart_series(const CullHistory& history);

} // namespace sherpa::editor
