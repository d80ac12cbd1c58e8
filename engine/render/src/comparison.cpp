// Two renderers' frames compared (sherpa/render/comparison.h): each side recorded
// into its renderer's side image (renderer_side.cpp), then side A's renderer's
// ComparisonPass reduces the statistics and composites the target.
#include "frame_recorder.h"

#include <sherpa/gpu/gpu_error.h>
#include <sherpa/render/comparison.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sherpa::render {
namespace {

std::uint32_t scaled(std::uint32_t side, float scale) {
    if (!(scale > 0.0f && scale < 1.0f)) return side;
    return std::max(1u, static_cast<std::uint32_t>(static_cast<float>(side) * scale));
}

CompositeMode composite_mode(CompareMode m) {
    return m == CompareMode::Split ? CompositeMode::Split : CompositeMode::Difference;
}

ComparisonStats to_stats(const GPUCompareStats& g, std::uint64_t pixels, float threshold) {
    ComparisonStats s;
    s.valid = true;
    s.pixels = pixels;
    std::uint64_t sum = 0, over = 0;
    const double over_byte = double(threshold) * 255.0;
    for (std::uint32_t d = 0; d < kDifferenceBins; ++d) {
        s.histogram[d] = g.histogram[d];
        sum += std::uint64_t(d) * g.histogram[d];
        if (g.histogram[d] != 0) s.max = double(d) / 255.0;
        // The threshold is a byte difference in 0..1: compare in bytes, with slack
        // for the float in which 2/255 arrives.
        if (double(d) > over_byte + 1e-3) over += g.histogram[d];
    }
    const double n = double(std::max<std::uint64_t>(pixels, 1));
    s.mean = double(sum) / 255.0 / n;
    s.over_threshold_percent = 100.0 * double(over) / n;
    const double squared = std::ldexp(double(g.squared_hi), 32) + double(g.squared_lo);
    s.psnr_db = squared <= 0.0
                    ? std::numeric_limits<double>::infinity()
                    : 10.0 * std::log10(255.0 * 255.0 * 3.0 * n / squared); // tex::psnr's MSE
    return s;
}

float heat_max_of(const ComparisonSettings& c, const ComparisonStats& latest) {
    if (c.heat_max > 0.0f) return c.heat_max;
    // Auto: the 99.9th percentile of the pixels that differ, at least one byte step.
    return float(std::max(latest.valid ? latest.percentile_999() : 16.0 / 255, 1.0 / 255));
}

void check_sides(Renderer& a, Renderer& b) {
    if (&a == &b)
        throw gpu::GpuError(
            "a comparison needs two renderers (one per side): the same renderer was "
            "given for both");
    if (&a.context() != &b.context())
        throw gpu::GpuError("a comparison's two renderers must share one Context");
}

} // namespace

std::string_view to_string(CompareMode m) {
    return m == CompareMode::Split ? "split" : "difference";
}

std::optional<CompareMode> parse_compare_mode(std::string_view name) {
    if (name == "split") return CompareMode::Split;
    if (name == "difference") return CompareMode::Difference;
    return std::nullopt;
}

std::array<std::uint8_t, 3> heat_colour(double t) {
    static constexpr std::array<std::array<double, 3>, 5> stops{
        {{0, 0, 0}, {0, 0, 255}, {255, 0, 0}, {255, 255, 0}, {255, 255, 255}}};
    t = std::clamp(std::isnan(t) ? 0.0 : t, 0.0, 1.0) * 4.0;
    const std::size_t i = std::min<std::size_t>(3, std::size_t(t));
    const double f = t - double(i);
    std::array<std::uint8_t, 3> c{};
    for (int k = 0; k < 3; ++k)
        c[k] = std::uint8_t(std::floor(stops[i][k] + f * (stops[i + 1][k] - stops[i][k]) + 0.5));
    return c;
}

double ComparisonStats::percentile_999() const {
    std::uint64_t nonzero = 0;
    for (std::uint32_t d = 1; d < kDifferenceBins; ++d) nonzero += histogram[d];
    if (nonzero == 0) return 0.0;
    // The element at rank floor(0.999 * n) of the sorted nonzero differences.
    const std::uint64_t rank =
        std::min<std::uint64_t>(nonzero - 1, std::uint64_t(0.999 * double(nonzero)));
    std::uint64_t seen = 0;
    for (std::uint32_t d = 1; d < kDifferenceBins; ++d) {
        seen += histogram[d];
        if (seen > rank) return double(d) / 255.0;
    }
    return 1.0;
}

ComparisonFrame::ComparisonFrame(Renderer& a, const FrameRequest& a_settings, Renderer& b,
                                 const FrameRequest& b_settings, const ComparisonSettings& compare,
                                 float resolution_scale)
    : a_(a), b_(b), a_settings_(a_settings), b_settings_(b_settings), compare_(compare),
      resolution_scale_(resolution_scale) {
    check_sides(a, b);
    a_.frames().rays().check_drawable(a_settings_);
    b_.frames().rays().check_drawable(b_settings_);
}

void ComparisonFrame::wait_for_slot(std::uint32_t slot) {
    completed_a_ = a_.frames().slot_stats(slot);
    completed_b_ = b_.frames().slot_stats(slot);
    const ReducedStats r = a_.frames().comparison().take_stats(slot);
    if (r.raw) {
        completed_ = to_stats(*r.raw, r.pixels, compare_.threshold);
        completed_.reduce_ms = r.reduce_ms;
    }
    // render_comparison's automatic heat scale composites in a second submission.
    if (r.composite_ms > 0.0) completed_.composite_ms = r.composite_ms;
}

// Both sides at the (scaled) target size into their renderers' side images.
static CompositeInputs record_sides(VkCommandBuffer cmd, std::uint32_t slot, FrameRecorder& a,
                                    FrameRequest& a_settings, FrameRecorder& b,
                                    FrameRequest& b_settings, std::uint32_t width,
                                    std::uint32_t height) {
    a_settings.width = b_settings.width = width;
    a_settings.height = b_settings.height = height;
    CompositeInputs in;
    in.width = width;
    in.height = height;
    in.a = record_side(a, cmd, slot, a_settings);
    in.b = record_side(b, cmd, slot, b_settings);
    a.comparison().bind(slot, in);
    return in;
}

void ComparisonFrame::record(VkCommandBuffer cmd, std::uint32_t slot,
                             const gpu::RenderTarget& target) {
    FrameRecorder& a = a_.frames();
    const CompositeInputs in = record_sides(cmd, slot, a, a_settings_, b_.frames(), b_settings_,
                                            scaled(target.width, resolution_scale_),
                                            scaled(target.height, resolution_scale_));
    a.comparison().record_stats(cmd, slot, in);
    a.comparison().record_composite(cmd, slot, in, target, composite_mode(compare_.mode),
                                    compare_.divider, heat_max_of(compare_, completed_));
    // The submission also completes b's frame: it signals b's timeline too.
    gpu::SubmissionTimeline& timeline = b_.resources().timeline();
    b_signal_ = gpu::vk_init<VkSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO);
    b_signal_.semaphore = timeline.semaphore();
    b_signal_.value = timeline.begin_submission();
    b_signal_.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
}

std::span<const VkSemaphoreSubmitInfo> ComparisonFrame::signals(std::uint32_t) const {
    return {&b_signal_, 1};
}

void ComparisonFrame::submitted(std::uint32_t slot, std::uint64_t submission) {
    a_.frames().slots().finish(slot, submission);
    b_.frames().slots().finish(slot, b_signal_.value);
    b_.resources().collect_garbage(); // the presenter collects a's
}

ComparisonStats render_comparison(Renderer& a, const FrameRequest& a_settings, Renderer& b,
                                  const FrameRequest& b_settings, const ComparisonSettings& compare,
                                  std::vector<std::uint8_t>* rgba) {
    const std::uint32_t width = a_settings.width, height = a_settings.height;
    if (width == 0 || height == 0 || width > 16384 || height > 16384)
        throw gpu::GpuError("comparison size " + std::to_string(width) + "x" +
                            std::to_string(height) + " is out of range");
    ComparisonFrame frame(a, a_settings, b, b_settings, compare);
    FrameRecorder& ai = a.frames();
    constexpr std::uint32_t slot = 0;
    frame.wait_for_slot(slot);
    const gpu::RenderTarget target = ai.targets().offscreen(width, height);
    gpu::CommandRecorder& recorder = ai.slots().recorder(slot);
    // Sides and statistics first; an automatic heat scale needs them before the
    // composite, which then goes in a second submission.
    VkCommandBuffer cmd = recorder.begin();
    const CompositeInputs in = record_sides(cmd, slot, ai, frame.a_settings_, b.frames(),
                                            frame.b_settings_, width, height);
    ai.comparison().record_stats(cmd, slot, in);
    const bool auto_heat = compare.mode == CompareMode::Difference && compare.heat_max <= 0.0f;
    const auto submit = [&] {
        gpu::SubmissionTimeline& timeline = b.resources().timeline();
        auto signal = gpu::vk_init<VkSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO);
        signal.semaphore = timeline.semaphore();
        signal.value = timeline.begin_submission();
        signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        const std::uint64_t value = recorder.submit(a.resources(), nullptr, 0, &signal, 1);
        ai.slots().finish(slot, value);
        b.frames().slots().finish(slot, signal.value);
    };
    if (auto_heat) {
        submit();
        frame.wait_for_slot(slot);
        cmd = recorder.begin();
        ai.comparison().bind(slot, in); // its previous frame (the sides) has completed
    }
    ai.comparison().record_composite(cmd, slot, in, target, composite_mode(compare.mode),
                                     compare.divider, heat_max_of(compare, frame.completed_));
    if (rgba) ai.targets().record_readback(cmd, width, height);
    submit();
    frame.wait_for_slot(slot); // with an automatic heat scale the stats came before
    if (rgba) ai.targets().read_offscreen(*rgba, width, height);
    a.resources().collect_garbage();
    b.resources().collect_garbage();
    return frame.completed_;
}

} // namespace sherpa::render
