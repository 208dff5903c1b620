/* layout_probe.cl — reports the device compiler's sizes and offsets of the
 * shared structs, in the order of include/wavefront/layout_fields.h, for the
 * host to compare with its own (host/device/layout_check.cpp). */
#include "wavefront/scene_types.h"
#include "wavefront/render_params.h"
#include "wavefront/layout_fields.h"

#define WF_DEVICE_OFFSETOF(S, m) ((uint)(size_t) & (((__global S*)0)->m))
#define WF_PROBE_SIZE(S) out[i++] = (uint)sizeof(S);
#define WF_PROBE_OFFSET(S, m) out[i++] = WF_DEVICE_OFFSETOF(S, m);

__kernel void layout_probe(__global uint* out) {
    uint i = 0;
    WF_LAYOUT_STRUCTS(WF_PROBE_SIZE)
    WF_LAYOUT_MEMBERS(WF_PROBE_OFFSET)
}
