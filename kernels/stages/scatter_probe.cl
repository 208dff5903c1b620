/* scatter_probe.cl — stages/scatter.inc's own arithmetic at widths 1 and 8
 * over arrays of values: the one-float step (round_away) beside OpenCL's
 * nextafter, for tests/kernels/test_scatter.cpp, and the light sample's MIS
 * weight, for tests/render/test_stability.cpp. */
#include "stages/shade.h" /* scatter.inc at width 1 */
#define WF_W 8
#include "lanes/lane_width.inc"
#include "lights/light_lanes.inc"
#include "stages/scatter.inc"
#undef WF_W

/* out[3i], out[3i + 1], out[3i + 2]: nextafter's answer (moved itself for a
 * step of 0), round_away_x1's and round_away_x8's, for moved[i] and step[i]. */
__kernel void round_away_probe(__global const float* moved, __global const float* step, __global float* out) {
    const uint i = get_global_id(0); /* eight values a work-item */
    const float8 m = vload8(i, moved), s = vload8(i, step);
    float wide[8];
    vstore8(round_away_x8(m, s), 0, wide);
    for (uint k = 0; k < 8u; ++k) {
        const float x = moved[8 * i + k], d = step[8 * i + k];
        out[3 * (8 * i + k)] = d == 0.0f ? x : nextafter(x, copysign(INFINITY, d));
        out[3 * (8 * i + k) + 1] = round_away_x1(x, d);
        out[3 * (8 * i + k) + 2] = wide[k];
    }
}

/* out[2i] and out[2i + 1]: power_heuristic_x1's and power_heuristic_x8's
 * weight of pdfs[i] (this, other), for tests/render/test_stability.cpp's
 * extreme pdfs; eight pdf pairs a work-item. */
__kernel void power_heuristic_probe(__global const float2* pdfs, __global float* out) {
    const uint i = get_global_id(0);
    float this_pdfs[8], other_pdfs[8], wide[8];
    for (uint k = 0; k < 8u; ++k) {
        this_pdfs[k] = pdfs[8 * i + k].x;
        other_pdfs[k] = pdfs[8 * i + k].y;
    }
    vstore8(power_heuristic_x8(vload8(0, this_pdfs), vload8(0, other_pdfs)), 0, wide);
    for (uint k = 0; k < 8u; ++k) {
        out[2 * (8 * i + k)] = power_heuristic_x1(this_pdfs[k], other_pdfs[k]);
        out[2 * (8 * i + k) + 1] = wide[k];
    }
}
