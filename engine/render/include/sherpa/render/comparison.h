#pragma once
// A/B comparison of two renderers' frames (the editor's split/difference viewport,
// `sherpa-cli render --compare`, `sherpa-cli compare --image`): each side is drawn
// by its own Renderer (another scene, file, texture setting, view or raster vs ray
// traced) at one size with one camera, then one compositing pass writes the target:
// Split (A left of a divider line, B right of it) or Difference (a heat map of
// |A - B|). The same pass reduces the difference statistics on the GPU
// (comparison_pass.cpp, shaders/compare.comp and compare.frag).
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <sherpa/gpu/frame_source.h>
#include <sherpa/render/renderer.h>

namespace sherpa::render {

enum class CompareMode : std::uint32_t { Split, Difference };
std::string_view to_string(CompareMode m);                            // "split", "difference"
std::optional<CompareMode> parse_compare_mode(std::string_view name); // nullopt: unknown

struct ComparisonSettings {
    CompareMode mode = CompareMode::Split;
    float divider = 0.5f;         // Split: fraction of the width; A left of it, B right
    float threshold = 2.0f / 255; // a pixel "differs" when any channel differs by more
    // Difference: this difference (and above) is full heat. 0 or below: the 99.9th
    // percentile of the pixels that differ at all (render_comparison: of this frame;
    // ComparisonFrame: of the latest completed one).
    float heat_max = 16.0f / 255;
};

// Bins of ComparisonStats::histogram: one per 8-bit difference value.
inline constexpr std::uint32_t kDifferenceBins = 256;

// Per frame, over all pixels of the side images (sRGB-encoded values in 0..1, the
// difference of a pixel is its largest over R, G and B).
struct ComparisonStats {
    bool valid = false;
    std::uint64_t pixels = 0;
    double mean = 0, max = 0, psnr_db = 0; // psnr over RGB; infinity when identical
    double over_threshold_percent = 0;
    // Pixels per difference value d (0..255): d = round(255 * difference).
    std::array<std::uint64_t, kDifferenceBins> histogram{};
    // GPU time of the comparison pass: the statistics dispatch and the composite (0
    // without device timestamps); the sides' own frames are in their FrameStats.
    double reduce_ms = 0, composite_ms = 0;
    // The 99.9th percentile of the differences above 0 (0 when none): the auto heat scale.
    double percentile_999() const;
};

// The heat colour of difference t in 0..1 (black, blue, red, yellow, white), as the
// shader draws it: the one source for legends (editor, CLI images).
std::array<std::uint8_t, 3> heat_colour(double t);

// A presented frame comparing two sides: each side is a Renderer with its own scene
// (the same scene loaded twice, another file, other load/texture settings) and its own
// FrameRequest (raster or RendererKind::RayTraced, any view). Both are drawn at the
// target's size (times `resolution_scale`) with one camera (the caller passes the same
// CameraSpec to both), then composited into the target. Made per presented frame,
// like PresentedFrame; the compositing resources and statistics buffers live in `a`,
// so the presenter must have been made with a.resources(): the frame also signals
// b's submission timeline. `a` and `b` must be two renderers on one Context.
// Stats come from the GPU, for the latest completed frame.
class ComparisonFrame final : public gpu::FrameSource {
public:
    // Throws GpuError for what either side cannot draw (e.g. a view the ray tracer
    // refuses), before anything is recorded.
    ComparisonFrame(Renderer& a, const FrameRequest& a_settings, Renderer& b,
                    const FrameRequest& b_settings, const ComparisonSettings& compare,
                    float resolution_scale = 1.0f);

    std::uint32_t frames_in_flight() const override { return Renderer::kFramesInFlight; }
    void wait_for_slot(std::uint32_t slot) override;
    void record(VkCommandBuffer cmd, std::uint32_t slot, const gpu::RenderTarget& target) override;
    std::span<const VkSemaphoreSubmitInfo> signals(std::uint32_t slot) const override;
    void submitted(std::uint32_t slot, std::uint64_t submission) override;

    const ComparisonStats& completed_comparison() const { return completed_; }
    const FrameStats& completed_stats_a() const { return completed_a_; }
    const FrameStats& completed_stats_b() const { return completed_b_; }

private:
    friend ComparisonStats render_comparison(Renderer&, const FrameRequest&, Renderer&,
                                             const FrameRequest&, const ComparisonSettings&,
                                             std::vector<std::uint8_t>*);
    Renderer& a_;
    Renderer& b_;
    FrameRequest a_settings_, b_settings_;
    ComparisonSettings compare_;
    float resolution_scale_;
    ComparisonStats completed_;
    FrameStats completed_a_, completed_b_;
    VkSemaphoreSubmitInfo b_signal_{};
};

// The same offscreen, waited for: the composited image as RGBA8 rows (top first,
// a_settings' width x height; b_settings' size is replaced by it), and the stats.
ComparisonStats render_comparison(Renderer& a, const FrameRequest& a_settings, Renderer& b,
                                  const FrameRequest& b_settings, const ComparisonSettings& compare,
                                  std::vector<std::uint8_t>* rgba = nullptr);

} // namespace sherpa::render
