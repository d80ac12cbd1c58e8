#version 460
// Difference statistics of two side images (comparison_pass.cpp): per pixel the
// largest byte difference d over R, G, B, counted into a 256-bin histogram (from
// which the host takes sum, mean, max and the count over a threshold), and the
// squared byte differences of R, G, B summed for the PSNR. Each invocation walks a
// run of RUN pixels of one row, keeping its zeros and squares in registers; a
// subgroup adds those with one atomic each (the 64-bit sum of squares as two 32-bit
// words with a carry), a differing pixel adds to its bin. No shared memory and no
// barriers: lavapipe runs a workgroup's barriers as coroutine switches, which cost
// more than the reduction (1280x720 on lavapipe, medians of 5 in three alternating
// runs: 16x16 groups with shared bins and two barriers took 1.5x to 3.6x as long).
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_basic : require
#include "compare.glsl"

const uint RUN = 16; // pixels per invocation; comparison_pass.cpp's kRun

layout(local_size_x = 64) in;

layout(set = 0, binding = 2, std430) buffer Stats {
    uint histogram[256];
    uint squared_lo;
    uint squared_hi;
} stats;

void main() {
    const uint runs_per_row = (pc.side_size.x + RUN - 1u) / RUN;
    const uint y = gl_GlobalInvocationID.x / runs_per_row;
    const uint x0 = (gl_GlobalInvocationID.x % runs_per_row) * RUN;
    uint zeros = 0u, squared = 0u; // at most RUN * 3 * 255^2 = 3.1M
    if (y < pc.side_size.y) {
        const uint x1 = min(x0 + RUN, pc.side_size.x);
        for (uint x = x0; x < x1; ++x) {
            const ivec2 p = ivec2(x, y);
            const ivec3 d = abs(bytes_a(p) - bytes_b(p));
            const uint largest = uint(max(d.r, max(d.g, d.b)));
            squared += uint(d.r * d.r + d.g * d.g + d.b * d.b);
            if (largest == 0u)
                ++zeros;
            else
                atomicAdd(stats.histogram[largest], 1u);
        }
    }
    // At most 128 lanes * 3.1M: fits 32 bits.
    const uint subgroup_zeros = subgroupAdd(zeros);
    const uint subgroup_squared = subgroupAdd(squared);
    if (subgroupElect()) {
        if (subgroup_zeros != 0u) atomicAdd(stats.histogram[0], subgroup_zeros);
        if (subgroup_squared != 0u) {
            const uint before = atomicAdd(stats.squared_lo, subgroup_squared);
            if (before + subgroup_squared < before) atomicAdd(stats.squared_hi, 1u); // carry
        }
    }
}
