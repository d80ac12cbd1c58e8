#version 460
// Difference statistics of two side images (comparison_pass.cpp): per pixel the
// largest byte difference d over R, G, B, counted into a 256-bin histogram (from
// which the host takes sum, mean, max and the count over a threshold), and the
// squared byte differences of R, G, B summed for the PSNR. Each workgroup reduces
// in shared memory, then adds into the buffer with integer atomics; the 64-bit sum
// of squares is two 32-bit words with a carry.
#extension GL_GOOGLE_include_directive : require
#include "compare.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = 2, std430) buffer Stats {
    uint histogram[256];
    uint squared_lo;
    uint squared_hi;
} stats;

shared uint bins[256];
shared uint squared;

void main() {
    const uint local = gl_LocalInvocationIndex;
    bins[local] = 0u;
    if (local == 0u) squared = 0u;
    barrier();
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(gl_GlobalInvocationID.xy, pc.side_size))) {
        const ivec3 d = abs(bytes_a(p) - bytes_b(p));
        atomicAdd(bins[max(d.r, max(d.g, d.b))], 1u);
        // At most 256 * 3 * 255^2 per workgroup: fits 32 bits.
        const uint sq = uint(d.r * d.r + d.g * d.g + d.b * d.b);
        if (sq != 0u) atomicAdd(squared, sq);
    }
    barrier();
    if (bins[local] != 0u) atomicAdd(stats.histogram[local], bins[local]);
    if (local == 0u && squared != 0u) {
        const uint before = atomicAdd(stats.squared_lo, squared);
        if (before + squared < before) atomicAdd(stats.squared_hi, 1u); // wrapped: carry
    }
}
