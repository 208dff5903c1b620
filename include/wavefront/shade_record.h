/* shade_record.h — what the wavefront's shade stage carries from its first
 * kernel to its second, a slot at a time, where it runs as two kernels over
 * the extension queue (--shade-kernels; by default a GPU's program on the
 * global-queue schedules: shade_in_two_kernels, host/integrator/path_integrator.h):
 * `surface` (the arrival and the surface, with the emission it finds) and
 * `shade` (the light sample, the BSDF core and the scatter), so that neither
 * holds the other's registers. On gfx90a the one kernel took 120 VGPRs on the
 * Cornell box, the two take 74 and 94 (bench/results/gpu-isa.md). The
 * megakernel and the group schedule, which keep a path in one kernel, shade
 * it in one step.
 *
 * One buffer of float4s, WF_SHADE_RECORD_ROWS rows of pool_size, row r of
 * slot s at r * pool_size + s, so that a GPU's neighbouring work-items read
 * neighbouring entries. The rows, declared once here; the kernels pack and
 * unpack them (kernels/stages/shade_two_kernels.h), the host allocates them
 * (host/integrator/path_pool.cpp). The sheen's row is neither written nor
 * read by a program without a sheen (kernels/compiled_features.h). The last
 * three are the second kernel's own: what its scatter needs of the light
 * sample and of the BSDF there, kept in memory rather than in registers
 * while the BSDF samples.
 *   X(row, what-it-holds) */
#ifndef WAVEFRONT_SHADE_RECORD_H
#define WAVEFRONT_SHADE_RECORD_H

#define WF_SHADE_RECORD(X)                                                                          \
    X(base_color, "rgb: the BSDF's base colour; w: metallic")                                        \
    X(specular, "rgb: KHR_materials_specular's colour; w: its factor")                               \
    X(interface, "roughness, ior, transmission, thin-walled (1 or 0)")                               \
    X(sheen, "rgb: the sheen's colour; w: its roughness")                                            \
    X(wo, "xyz: the way back along the ray, in the shading frame; w: WF_SHADE_RECORD_* flags as bits") \
    X(u, "xyz: BSDF sampling's numbers; w: roulette's")                                              \
    X(light_u, "the light sample's numbers")                                                         \
    X(position, "xyz: the hit point; w: the clear coat's weight")                                    \
    X(position_error, "xyz: the hit point's error bound; w: the clear coat's roughness")             \
    X(geometric_normal, "xyz: on the shading frame's side")                                          \
    X(frame_z, "xyz: the shading normal, the frame's z")                                           \
    X(light_wi, "the second kernel's: xyz, the light sample's direction; w: a delta light (1 or 0)")  \
    X(light_radiance, "the second kernel's: rgb, the light sample's radiance; w: its pdf")            \
    X(light_f, "the second kernel's: rgb, the BSDF at the light sample's direction; w: its pdf")

#define WF_SHADE_RECORD_ROW_ENUM(row, what) WF_SHADE_ROW_##row,
enum ShadeRecordRow { WF_SHADE_RECORD(WF_SHADE_RECORD_ROW_ENUM) WF_SHADE_RECORD_ROWS };
#undef WF_SHADE_RECORD_ROW_ENUM

/* In wo.w: the path goes on from this surface (else it ended there), and it
 * takes a light sample. */
#define WF_SHADE_RECORD_GOES_ON 1u
#define WF_SHADE_RECORD_LIGHT 2u

#endif /* WAVEFRONT_SHADE_RECORD_H */
