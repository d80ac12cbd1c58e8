// Environment images on the CPU: the built-in room, a uniform environment, HDR/EXR
// files through the texture layer (OpenImageIO, loaded on first use) with every failure a warning
// and a fallback, and the names of the environment settings.
#include <sherpa/render/environment.h>

#include <sherpa/texture/image.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <numbers>

namespace sherpa::render {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kHalfMax = 65504.0f; // the largest finite half float

// The world direction of texel (x, y) of a width x height equirectangular image
// (environment.h: u = atan2(z, x) / 2pi + 0.5, v = asin(y) / pi + 0.5, top row v = 1).
glm::vec3 texel_direction(std::uint32_t x, std::uint32_t y, std::uint32_t w, std::uint32_t h) {
    const float u = (float(x) + 0.5f) / float(w), v = 1.0f - (float(y) + 0.5f) / float(h);
    const float phi = (u - 0.5f) * 2.0f * kPi, theta = (v - 0.5f) * kPi;
    return {std::cos(theta) * std::cos(phi), std::sin(theta), std::cos(theta) * std::sin(phi)};
}

// 1 inside a soft-edged spherical rectangle around `centre` (unit), of angular half
// sizes (radians) along two axes, falling to 0 over `soft` radians.
float soft_panel(glm::vec3 d, glm::vec3 centre, glm::vec3 right, float half_w, float half_h,
                 float soft) {
    const glm::vec3 up = glm::normalize(glm::cross(right, centre));
    const float c = glm::dot(d, centre);
    if (c <= 0.0f) return 0.0f;
    const float a = std::atan2(glm::dot(d, right), c), b = std::atan2(glm::dot(d, up), c);
    const auto edge = [soft](float t, float half) {
        return std::clamp((half - std::abs(t)) / soft + 0.5f, 0.0f, 1.0f);
    };
    return edge(a, half_w) * edge(b, half_h);
}

glm::vec3 room_radiance(glm::vec3 d) {
    // Walls, floor and ceiling of a neutral grey room: brighter above, darker below.
    const float up = d.y;
    glm::vec3 c =
        up >= 0.0f ? glm::mix(glm::vec3(0.32f, 0.32f, 0.33f), glm::vec3(0.55f), up)
                   : glm::mix(glm::vec3(0.30f, 0.29f, 0.28f), glm::vec3(0.12f, 0.115f, 0.11f), -up);
    // A key softbox high on the +Z/+X side, a weaker fill on the -X side, a rim strip
    // behind (-Z) and a ceiling panel: reflections show shape on every material.
    const glm::vec3 key_dir = glm::normalize(glm::vec3(0.6f, 0.6f, 0.55f));
    c += glm::vec3(9.0f, 8.8f, 8.4f) *
         soft_panel(d, key_dir, glm::normalize(glm::vec3(-0.7f, 0.0f, 0.75f)), 0.35f, 0.25f, 0.04f);
    const glm::vec3 fill_dir = glm::normalize(glm::vec3(-0.8f, 0.25f, 0.45f));
    c += glm::vec3(2.2f, 2.3f, 2.5f) *
         soft_panel(d, fill_dir, glm::normalize(glm::vec3(-0.5f, 0.0f, -0.9f)), 0.3f, 0.3f, 0.1f);
    c += glm::vec3(5.0f) *
         soft_panel(d, glm::vec3(0.0f, 0.15f, -1.0f), glm::vec3(-1.0f, 0, 0), 0.9f, 0.05f, 0.02f);
    c += glm::vec3(4.0f) *
         soft_panel(d, glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(1.0f, 0, 0), 0.3f, 0.3f, 0.05f);
    return c;
}

EnvironmentLoad fall_back(const std::string& path, std::string problem) {
    EnvironmentLoad out;
    out.warnings.push_back(path + ": " + std::move(problem) +
                           "; using the built-in room environment instead");
    out.image = room_environment();
    out.fallback = true;
    return out;
}

} // namespace

EnvironmentImage room_environment(std::uint32_t width) {
    EnvironmentImage img;
    img.width = std::max<std::uint32_t>(width, 8);
    img.height = img.width / 2;
    img.name = "room";
    img.rgba.resize(std::size_t{img.width} * img.height * 4);
    for (std::uint32_t y = 0; y < img.height; ++y)
        for (std::uint32_t x = 0; x < img.width; ++x) {
            const glm::vec3 c = room_radiance(texel_direction(x, y, img.width, img.height));
            float* t = &img.rgba[(std::size_t{y} * img.width + x) * 4];
            t[0] = c.r, t[1] = c.g, t[2] = c.b, t[3] = 1.0f;
        }
    return img;
}

EnvironmentImage uniform_environment(glm::vec3 radiance, std::uint32_t width) {
    EnvironmentImage img;
    img.width = std::max<std::uint32_t>(width, 8);
    img.height = img.width / 2;
    img.name = "uniform";
    img.rgba.resize(std::size_t{img.width} * img.height * 4);
    for (std::size_t i = 0; i < img.rgba.size(); i += 4)
        img.rgba[i] = radiance.r, img.rgba[i + 1] = radiance.g, img.rgba[i + 2] = radiance.b,
        img.rgba[i + 3] = 1.0f;
    return img;
}

EnvironmentLoad load_environment(const std::string& path) {
    // Radiance maps carry no coverage: an alpha channel must not scale the colour
    // (read_float_image_file reads unassociated, RGB only).
    tex::FloatRgbImage file;
    std::string why;
    if (!tex::read_float_image_file(path, kMaxEnvironmentSide, file, why)) {
        if (why.rfind(path + ": ", 0) == 0) why.erase(0, path.size() + 2); // said once
        return fall_back(path, "cannot read the environment image (" + why + ")");
    }
    constexpr int channels = 3;
    const std::vector<float>& raw = file.rgb;
    EnvironmentLoad out;
    EnvironmentImage& img = out.image;
    img.width = file.width;
    img.height = file.height;
    img.name = std::filesystem::path(path).filename().string();
    img.rgba.resize(std::size_t{img.width} * img.height * 4);
    std::uint64_t nonfinite = 0, clamped = 0;
    for (std::size_t i = 0, n = std::size_t{img.width} * img.height; i < n; ++i) {
        const float* s = &raw[i * channels];
        float* d = &img.rgba[i * 4];
        for (int c = 0; c < 3; ++c) {
            float v = s[c];
            if (!std::isfinite(v)) {
                ++nonfinite;
                v = 0.0f;
            } else if (v < 0.0f) {
                v = 0.0f; // negative radiance is not light
            } else if (v > kHalfMax) {
                ++clamped;
                v = kHalfMax;
            }
            d[c] = v;
        }
        d[3] = 1.0f;
    }
    if (nonfinite > 0)
        out.warnings.push_back(path + ": " + std::to_string(nonfinite) +
                               " texel channels are NaN or infinite; read as 0 (black)");
    if (clamped > 0)
        out.warnings.push_back(path + ": " + std::to_string(clamped) +
                               " texel channels exceed the half-float range; clamped to 65504");
    if (img.width != 2 * img.height)
        out.warnings.push_back(path + ": " + std::to_string(img.width) + "x" +
                               std::to_string(img.height) +
                               " is not 2:1; read as equirectangular all the same");
    return out;
}

EnvironmentChoice parse_environment_choice(std::string_view text) {
    EnvironmentChoice c;
    if (text == "room")
        c.kind = EnvironmentChoice::Kind::Room;
    else if (text == "none")
        c.kind = EnvironmentChoice::Kind::None;
    else
        c.kind = EnvironmentChoice::Kind::File, c.path = std::string(text);
    return c;
}

std::optional<EnvironmentImage> make_environment(const EnvironmentChoice& choice,
                                                 std::vector<std::string>& warnings) {
    switch (choice.kind) {
    case EnvironmentChoice::Kind::None:
        return std::nullopt;
    case EnvironmentChoice::Kind::Room:
        return room_environment();
    case EnvironmentChoice::Kind::File:
        break;
    }
    EnvironmentLoad load = load_environment(choice.path);
    warnings.insert(warnings.end(), load.warnings.begin(), load.warnings.end());
    return std::move(load.image);
}

std::vector<std::string> installed_studio_lights() {
    std::vector<std::string> out;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(kStudioLightsDir, ec)) {
        const std::string ext = e.path().extension().string();
        if (e.is_regular_file(ec) && (ext == ".exr" || ext == ".hdr"))
            out.push_back(e.path().string());
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string_view to_string(Background b) {
    switch (b) {
    case Background::Environment:
        return "environment";
    case Background::Blurred:
        return "blurred";
    case Background::Color:
        return "color";
    }
    return "?";
}

std::optional<Background> parse_background(std::string_view text, glm::vec3& color) {
    if (text == "environment") return Background::Environment;
    if (text == "blurred") return Background::Blurred;
    glm::vec3 c{};
    std::size_t at = 0;
    for (int i = 0; i < 3; ++i) {
        const std::size_t end = i < 2 ? text.find(',', at) : text.size();
        if (end == std::string_view::npos) return std::nullopt;
        const std::string_view part = text.substr(at, end - at);
        const auto r = std::from_chars(part.data(), part.data() + part.size(), c[i]);
        if (r.ec != std::errc{} || r.ptr != part.data() + part.size() || !(c[i] >= 0.0f) ||
            c[i] > 1.0f)
            return std::nullopt;
        at = end + 1;
    }
    color = c;
    return Background::Color;
}

namespace {
constexpr std::pair<ToneMap, std::string_view> kToneMaps[] = {{ToneMap::Neutral, "neutral"},
                                                              {ToneMap::Aces, "aces"},
                                                              {ToneMap::Agx, "agx"},
                                                              {ToneMap::Linear, "linear"}};
}

std::string_view to_string(ToneMap t) {
    for (const auto& [k, n] : kToneMaps)
        if (k == t) return n;
    return "?";
}

std::optional<ToneMap> parse_tone_map(std::string_view name) {
    for (const auto& [k, n] : kToneMaps)
        if (n == name) return k;
    return std::nullopt;
}

namespace {
constexpr std::pair<AnisotropyLighting, std::string_view> kAnisotropyLightings[] = {
    {AnisotropyLighting::Isotropic, "isotropic"},
    {AnisotropyLighting::Albedo, "albedo"},
    {AnisotropyLighting::Lobe, "lobe"}};
}

std::string_view to_string(AnisotropyLighting a) {
    for (const auto& [k, n] : kAnisotropyLightings)
        if (k == a) return n;
    return "?";
}

std::optional<AnisotropyLighting> parse_anisotropy_lighting(std::string_view name) {
    for (const auto& [k, n] : kAnisotropyLightings)
        if (n == name) return k;
    return std::nullopt;
}

std::vector<std::string_view> tone_map_names() {
    std::vector<std::string_view> out;
    for (const auto& kv : kToneMaps) out.push_back(kv.second);
    return out;
}

} // namespace sherpa::render
