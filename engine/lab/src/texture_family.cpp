// The texture-compression family: every BC7 and BC5 level of block_codecs.h on the
// textures the displayed scene's materials use, against the decoded source images.
#include <sherpa/lab/families.h>
#include <sherpa/scene/image_sources.h>
#include <sherpa/texture/block_codecs.h>
#include <sherpa/texture/quality.h>
#include <sherpa/texture/source_export.h>
#include <sherpa/texture/texture_pipeline.h>

#include <algorithm>
#include <cmath>

#include "lab_support.h"

namespace sherpa::lab {
namespace {

constexpr std::uint32_t kTile = 64; // a multiple of the 4x4 block

// Tiles of kTile x kTile spread evenly over `image`, side by side in one image of
// about `texels` texels; the image itself when it is that small (or texels is 0).
tex::RgbaImage sample_mosaic(tex::RgbaImage image, std::uint64_t texels) {
    if (texels == 0 || std::uint64_t(image.width) * image.height <= texels) return image;
    const std::uint32_t tw = std::min(kTile, image.width), th = std::min(kTile, image.height);
    const auto k = std::uint32_t(std::ceil(std::sqrt(double(texels) / double(tw * th))));
    const std::uint32_t kx = std::clamp(image.width / tw, 1u, k);
    const std::uint32_t ky = std::clamp(image.height / th, 1u, k);
    tex::RgbaImage out;
    out.width = kx * tw, out.height = ky * th;
    out.pixels.resize(std::size_t(out.width) * out.height * 4);
    auto start = [](std::uint32_t i, std::uint32_t n, std::uint32_t size, std::uint32_t tile) {
        return n < 2 ? 0u : (std::uint32_t(std::uint64_t(i) * (size - tile) / (n - 1)) & ~3u);
    };
    for (std::uint32_t ty = 0; ty < ky; ++ty)
        for (std::uint32_t tx = 0; tx < kx; ++tx) {
            const std::uint32_t sx = start(tx, kx, image.width, tw);
            const std::uint32_t sy = start(ty, ky, image.height, th);
            for (std::uint32_t y = 0; y < th; ++y)
                std::copy_n(&image.pixels[(std::size_t(sy + y) * image.width + sx) * 4], tw * 4,
                            &out.pixels[(std::size_t(ty * th + y) * out.width + tx * tw) * 4]);
        }
    return out;
}

struct Input {
    scene::TextureRole role = scene::kRoleColor;
    std::string where;
    tex::RgbaImage image; // sampled
    std::uint64_t source_texels = 0;
};

struct Method {
    tex::BlockFormat format;
    int level;
};

std::vector<Method> all_methods() {
    std::vector<Method> m;
    for (int l = tex::kBc7MinLevel; l <= tex::kBc7MaxLevel; ++l)
        m.push_back({tex::BlockFormat::Bc7, l});
    for (int l = tex::kBc5MinLevel; l <= tex::kBc5MaxLevel; ++l)
        m.push_back({tex::BlockFormat::Bc5, l});
    return m;
}

bool applies(const Method& m, scene::TextureRole role) {
    return (m.format == tex::BlockFormat::Bc5) == (role == scene::kRoleNormal);
}

class TextureFamily final : public Family {
public:
    explicit TextureFamily(const TextureFamilyOptions& options) : options_(options) {}
    std::string_view name() const override { return "textures"; }
    std::vector<MethodInfo> methods() const override {
        std::vector<MethodInfo> out;
        for (const Method& m : all_methods())
            out.push_back({m.format == tex::BlockFormat::Bc7 ? "bc7" : "bc5",
                           "level=" + std::to_string(m.level),
                           m.format == tex::BlockFormat::Bc7 ? "BC7 on colour and data textures"
                                                             : "BC5 on normal maps",
                           m.format == tex::BlockFormat::Bc7 ? "bc7" : "bc5"});
        return out;
    }
    FamilyReport run(const scene::Scene& scene, const RunControl& control) const override;

private:
    TextureFamilyOptions options_;
};

FamilyReport TextureFamily::run(const scene::Scene& scene, const RunControl& control) const {
    FamilyReport report;
    report.family = "textures";
    report.reference = "the decoded source images";
    report.time_unit = "ms/MPix";
    report.chart_error = "psnr_db";
    const std::vector<tex::TextureUse> uses = tex::collect_texture_uses(scene);
    const std::vector<Method> methods_list = all_methods();
    std::size_t units = uses.size();
    for (const Method& m : methods_list)
        for (const tex::TextureUse& u : uses) units += applies(m, u.role) ? 1 : 0;
    detail::Progress progress(control, units);
    if (progress.stop()) return detail::cancelled_report(report.family);
    std::vector<Input> inputs;
    std::vector<std::pair<scene::TextureRole, Failure>> failures; // by the role the image has
    bool sampled = false;
    for (const tex::TextureUse& use : uses) {
        if (progress.stop()) return detail::cancelled_report(report.family);
        const scene::ImageRecord& img = scene.images[std::size_t(use.image)];
        Input in;
        in.role = use.role;
        in.where = "image " + std::to_string(use.image) + " " +
                   scene::image_location(scene, use.image) + " (" +
                   std::string(tex::role_name(use.role)) + ")";
        std::string error;
        tex::RgbaImage decoded;
        if (scene::image_is_missing(img))
            failures.push_back({use.role, {"missing", in.where, 1}});
        else if (!tex::decode_image_source(img, decoded, error) || decoded.empty())
            failures.push_back({use.role, {"undecodable: " + error, in.where, 1}});
        else {
            in.source_texels = std::uint64_t(decoded.width) * decoded.height;
            in.image = sample_mosaic(std::move(decoded), options_.sample_texels);
            sampled |= std::uint64_t(in.image.width) * in.image.height < in.source_texels;
            inputs.push_back(std::move(in));
        }
        progress.step();
    }
    if (sampled)
        report.notes.push_back("images over " + std::to_string(options_.sample_texels) +
                               " texels measured on a mosaic of 64x64 tiles spread over them");
    const tex::SimdLevel simd = tex::best_simd_level();
    const std::vector<MethodInfo> infos = methods();
    for (std::size_t k = 0; k < methods_list.size(); ++k) {
        const Method& method = methods_list[k];
        MethodResult r;
        r.method = infos[k];
        tex::SquaredError pooled;
        double worst_psnr = INFINITY, angle_sum = 0.0, mpix = 0.0;
        std::size_t count = 0;
        for (const Input& in : inputs) {
            if (!applies(method, in.role)) continue;
            if (progress.stop()) return detail::cancelled_report(report.family);
            const tex::RgbaImage& im = in.image;
            const double t0 = detail::process_cpu_ms();
            const auto blocks = tex::encode_image(method.format, im.pixels, im.width, im.height,
                                                  {method.level, simd}, options_.threads);
            r.total_ms += detail::process_cpu_ms() - t0;
            const auto decoded = tex::decode_image(method.format, blocks, im.width, im.height);
            const unsigned channels = in.role == scene::kRoleNormal ? tex::kChannelsRg
                                      : im.has_alpha()              ? tex::kChannelsRgba
                                                                    : tex::kChannelsRgb;
            const tex::SquaredError err = tex::squared_error(im.pixels, decoded, channels);
            pooled += err;
            worst_psnr = std::min(worst_psnr, err.psnr());
            if (in.role == scene::kRoleNormal)
                angle_sum += tex::normal_angle_error_vs_rgb(im.pixels, decoded).mean();
            mpix += double(im.width) * im.height / 1e6;
            ++count;
            progress.step();
        }
        for (const auto& [role, failure] : failures)
            if (applies(method, role)) r.failures.push_back(failure);
        if (count == 0) {
            r.note =
                std::string(r.failures.empty() ? "no " : "no decodable ") +
                (method.format == tex::BlockFormat::Bc5 ? "normal map in the scene"
                                                        : "colour or data texture in the scene");
            report.methods.push_back(std::move(r));
            continue;
        }
        r.ran = true;
        r.time = r.total_ms / mpix;
        r.note = std::to_string(count) + " textures, " + std::to_string(mpix) + " MPix measured";
        r.errors.push_back({"psnr_db", pooled.psnr(), true});
        r.errors.push_back({"psnr_min_db", worst_psnr, true});
        if (method.format == tex::BlockFormat::Bc5)
            r.errors.push_back({"angle_mean_deg", angle_sum / double(count)});
        report.methods.push_back(std::move(r));
    }
    progress.finish();
    return report;
}

} // namespace

std::unique_ptr<Family> make_texture_family(const TextureFamilyOptions& options) {
    return std::make_unique<TextureFamily>(options);
}

} // namespace sherpa::lab
