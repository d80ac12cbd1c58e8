#pragma once
// Rays against raster, pixel by pixel (the exactness tests' measure): the fraction of
// covered pixels where two RGBA8 images agree within a tolerance, a one-pixel band at
// coverage edges aside, and the holes one leaves inside the other's coverage.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include <sherpa/render/frame_request.h>
#include <sherpa/render/renderer.h>

namespace sherpa::test {

struct Agreement {
    std::size_t compared = 0, agreeing = 0, covered_a = 0, covered_b = 0;
    // Holes: pixels one image leaves at the clear colour inside the other's coverage
    // (the pixel and its 8 neighbours covered there). No silhouette band explains them.
    std::size_t holes_a = 0, holes_b = 0;
    int max_difference = 0;
    double fraction() const { return compared ? double(agreeing) / double(compared) : 1.0; }
};

// Covered: differs from the clear colour. Compared: covered in either image and not
// within one pixel of a coverage edge of either image (a region only one renderer
// covers is compared, and disagrees).
inline Agreement compare(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                         std::uint32_t w, std::uint32_t h, int tolerance) {
    auto covered = [&](const std::vector<std::uint8_t>& img, std::size_t p) {
        for (int c = 0; c < 3; ++c)
            if (img[4 * p + c] != img[c]) return true; // pixel (0,0) shows the clear colour
        return false;
    };
    std::vector<char> ca(std::size_t(w) * h), cb(ca.size());
    for (std::size_t p = 0; p < ca.size(); ++p) {
        ca[p] = covered(a, p);
        cb[p] = covered(b, p);
    }
    auto edge = [&](const std::vector<char>& m, std::uint32_t x, std::uint32_t y) {
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int nx = int(x) + dx, ny = int(y) + dy;
                if (nx < 0 || ny < 0 || nx >= int(w) || ny >= int(h)) continue;
                if (m[std::size_t(ny) * w + nx] != m[std::size_t(y) * w + x]) return true;
            }
        return false;
    };
    auto interior = [&](const std::vector<char>& m, std::uint32_t x, std::uint32_t y) {
        return m[std::size_t(y) * w + x] && !edge(m, x, y);
    };
    Agreement r;
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            const std::size_t p = std::size_t(y) * w + x;
            r.covered_a += ca[p];
            r.covered_b += cb[p];
            r.holes_a += !ca[p] && interior(cb, x, y);
            r.holes_b += !cb[p] && interior(ca, x, y);
            if (!(ca[p] || cb[p]) || edge(ca, x, y) || edge(cb, x, y)) continue;
            int d = 0;
            for (int c = 0; c < 3; ++c)
                d = std::max(d, std::abs(int(a[4 * p + c]) - int(b[4 * p + c])));
            ++r.compared;
            r.agreeing += d <= tolerance;
            r.max_difference = std::max(r.max_difference, d);
        }
    return r;
}

// The frame `s` drawn by the raster and by the ray tracer, compared as compare() does.
// `s.renderer` is left at RayTraced.
inline Agreement rays_against_raster(render::Renderer& renderer, render::FrameRequest& s,
                                     int tolerance) {
    std::vector<std::uint8_t> raster, rays;
    s.renderer = render::RendererKind::Raster;
    renderer.render(s, &raster);
    s.renderer = render::RendererKind::RayTraced;
    renderer.render(s, &rays);
    return compare(raster, rays, s.width, s.height, tolerance);
}

} // namespace sherpa::test
