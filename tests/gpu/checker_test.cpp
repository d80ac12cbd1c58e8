// The uv checker views: the density setting sets the checks per UV unit, and the
// checker is filtered, so a ground plane seen at a grazing angle shows no moiré. The
// reference for "no moiré" is the same view rendered at 4× the resolution and box
// filtered down (supersampling), which an unfiltered checker at the low resolution
// misses by far, since its far checks alias into stripes.
#include "gpu_test_support.h"

#include <cmath>
#include <cstdlib>

namespace sherpa::test {
namespace {

constexpr std::uint32_t kLow = 96, kScale = 4;
// Low over the built-in ground plane, looking towards the horizon.
constexpr const char* kGrazing = "eye=0,0.6,9:target=0,0,-20:fov=60";

class CheckerTest : public GpuTest {
protected:
    std::vector<std::uint8_t> render(std::uint32_t size, float density) {
        render::FrameRequest s;
        s.width = s.height = size;
        s.view = render::DebugView::Uv0Checker;
        s.uv_checker_density = density;
        std::string error;
        EXPECT_TRUE(render::parse_camera_spec(kGrazing, s.camera, error)) << error;
        return draw(s);
    }
};

// Mean absolute difference per channel of a low-resolution render and a high one
// box-filtered down to it, over the lower half of the image (the ground plane).
double difference_to_supersampled(const std::vector<std::uint8_t>& low,
                                  const std::vector<std::uint8_t>& high) {
    double sum = 0.0;
    std::size_t n = 0;
    const std::uint32_t hi = kLow * kScale;
    for (std::uint32_t y = kLow / 2; y < kLow; ++y)
        for (std::uint32_t x = 0; x < kLow; ++x)
            for (std::uint32_t c = 0; c < 3; ++c) {
                double mean = 0.0;
                for (std::uint32_t dy = 0; dy < kScale; ++dy)
                    for (std::uint32_t dx = 0; dx < kScale; ++dx)
                        mean += high[((y * kScale + dy) * hi + x * kScale + dx) * 4 + c];
                mean /= kScale * kScale;
                sum += std::abs(double(low[(y * kLow + x) * 4 + c]) - mean);
                ++n;
            }
    return sum / double(n);
}

TEST_F(CheckerTest, DensitySetsChecksPerUnit) {
    auto scene = load("builtin:default");
    ASSERT_TRUE(scene);
    renderer().load(*scene);
    const std::vector<std::uint8_t> coarse = render(kLow, 8.0f), fine = render(kLow, 32.0f);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < coarse.size(); i += 4)
        differ += std::abs(int(coarse[i]) - int(fine[i])) > 8;
    EXPECT_GT(differ, std::size_t(kLow * kLow / 8));
    renderer().unload();
}

TEST_F(CheckerTest, FilteredAtGrazingAngles) {
    auto scene = load("builtin:default");
    ASSERT_TRUE(scene);
    renderer().load(*scene);
    for (const float density : {8.0f, 64.0f}) {
        const double d =
            difference_to_supersampled(render(kLow, density), render(kLow * kScale, density));
        EXPECT_LT(d, 10.0) << "density " << density << ": moiré against the supersampled view";
    }
    renderer().unload();
}

} // namespace
} // namespace sherpa::test
