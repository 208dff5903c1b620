/* ray_offset.h — where a ray leaving a surface must start so it cannot hit that
 * surface again.
 *
 * The offset moves a point along the geometric normal by a fixed number of
 * units in the last place of each coordinate (Wächter and Binder, "A Fast and
 * Robust Method for Avoiding Self-Intersection", Ray Tracing Gems, 2019), so it
 * scales with the coordinates themselves; near the origin, where ULPs vanish,
 * it falls back to a small absolute step. */
#ifndef WF_RAY_OFFSET_H
#define WF_RAY_OFFSET_H

inline float offset_coordinate(float p, float n) {
    const float ulp_steps = 256.0f;
    const float near_origin = 1.0f / 32.0f;
    const float absolute_step = 1.0f / 65536.0f;
    const int step = (int)(ulp_steps * n);
    const float moved = as_float(as_int(p) + (p < 0.0f ? -step : step));
    return fabs(p) < near_origin ? p + absolute_step * n : moved;
}

/* p moved off its surface to the side that n points to. */
inline float3 offset_ray_origin(float3 p, float3 n) {
    return (float3)(offset_coordinate(p.x, n.x), offset_coordinate(p.y, n.y),
                    offset_coordinate(p.z, n.z));
}

#endif
