/* bsdf.h — the BSDF of a glTF 2.0 material (metallic-roughness, with
 * KHR_materials_transmission and KHR_materials_ior), as the shade stage
 * evaluates and samples it; shared by the kernels and the host.
 *
 * Frame and directions: everything is in the local shading frame, z = the
 * shading normal. wo (towards the previous vertex, the camera side) and wi
 * (towards the light) are unit and point away from the surface. An opaque or
 * thin-walled material needs wo.z > 0 (the caller flips the frame) and is
 * black otherwise; a solid transmissive one (bsdf_has_inside) takes wo on
 * either side, wo.z < 0 meaning the ray arrived from inside.
 *
 * The material, glTF's mix(dielectric, metal, metallic) (spec Appendix B),
 * with KHR_materials_specular's factor and colour shaping the dielectric
 * layer's F_d (F0 = min(F0(ior) specular_color, 1) specular, F90 = specular):
 *  - the interface: GGX microfacets (bsdf/microfacet.h), alpha = roughness^2,
 *    which reflect with R(c) = (1 - metallic) F_d(c) + metallic Schlick(base, c)
 *    and, where transmission > 0, transmit with
 *    T(c) = (1 - metallic) transmission base (1 - F_d(c)), c = wo.wm.
 *    F_d is the dielectric layer's Fresnel: Schlick with F0(ior) =
 *    ((ior-1)/(ior+1))^2 (0.04 at the default ior 1.5) for an opaque or
 *    thin-walled material, as glTF's model has it, and for a solid transmissive
 *    one the exact dielectric reflectance (bsdf/fresnel.h), which has the
 *    inside and total internal reflection, carried from F0(ior)..1 onto the
 *    coloured F0..F90.
 *    Reflection is Cook-Torrance, R D G2 / (4 |wo.z| |wi.z|); transmission is
 *    Walter et al. 2007, T D G2 |wi.wm| |wo.wm| / ((wi.wm + wo.wm/eta')^2
 *    |wi.z| |wo.z|) / eta'^2, eta' = ior entering (wo.z > 0) and 1/ior leaving.
 *    The last 1/eta'^2 makes it a BTDF for radiance (camera paths): radiance
 *    entering a denser medium is concentrated (pbrt-v4's TransportMode::
 *    Radiance). With it the BTDF obeys f(wo,wi)/n_o^2 = f(wi,wo)/n_i^2, n_o and
 *    n_i the indices on the sides of wo and wi (Veach's thesis, 5.14); the white furnace of a clear
 *    dielectric returns 1 only once the eta'^2 is multiplied back.
 *  - a thin wall (glTF's transmission without KHR_materials_volume: a window
 *    pane, a leaf) has no inside: its transmission is the reflection lobe
 *    mirrored through the surface, T D G2 / (4 |wo.z| |wi.z|) at the half
 *    vector of wo and the mirror image of wi, with no bending and no eta'^2,
 *    so a smooth pane lets 1 - F through straight. It is seen the same from
 *    both sides, and reciprocal under the mirror.
 *  - energy compensation (bsdf/albedo.h): a GGX interface of one scattering
 *    event reflects only E(mu) of a white light, losing up to 60% at
 *    roughness 1. A lobe of multiple scattering (Kulla and Conty 2017),
 *    C (1 - E(mu_o))(1 - E(mu_i)) / (pi (1 - E_avg)), outside only, returns it:
 *    C = metallic MS(base, 1) + (1 - metallic)(1 - transmission) MS(F0_d, F90_d),
 *    MS the multiple-scattering colour of a Schlick interface. A white metal
 *    then reflects 1 at every roughness above the Dirac limit. At low
 *    roughness the loss is small on average but peaked at grazing angles, so
 *    the lobe is sampled by its own shape (bsdf_loss_probability,
 *    loss_sample_mu), where the cosine gave weights in the thousands.
 *  - the diffuse base, outside only: (1 - metallic)(1 - transmission) base / pi
 *    (1 - L(mu_o))(1 - L(mu_i)) / (1 - L_avg), L the dielectric layer's whole
 *    albedo (single scattering with Schlick's F_d plus its multiple scattering)
 *    and L_avg its hemispherical average: what the layer does not reflect goes
 *    into the base, and what the base sends back leaves through the layer in
 *    the same proportion, so that a white dielectric reflects exactly 1 and the
 *    lobe stays reciprocal (the albedo scaling of OpenPBR and of Blender's
 *    Principled BSDF). glTF's reference code weighs the diffuse by
 *    1 - F(wo.wh) instead, which is neither bounded nor energy-conserving.
 *    A transmissive material's layer reflects with the exact F_d; its diffuse
 *    part (1 - transmission) is still weighed with Schlick's, an approximation
 *    of well under 1% of its albedo.
 *  - a rough solid glass's multiple scattering: the glass share (1 - metallic)
 *    transmission of the interface's reflection and all its refraction are
 *    divided by E_g(mu_o), the single-scattering albedo of a white glass of
 *    that roughness and ior seen from wo's side (bsdf/albedo.h's tables), so a
 *    clear glass returns 1 at every roughness from outside and inside alike:
 *    the albedo scaling of Cycles' glass. It depends on wo alone, so it is not
 *    reciprocal.
 *
 *  - the sheen (KHR_materials_sheen, bsdf/sheen.h), over the above: the
 *    Charlie lobe, sheen_color D V / max(1, S(mu_o)), S its albedo from the
 *    tables (Neubelt's V lets S pass 1 at grazing views below roughness 0.5;
 *    the division keeps the lobe from reflecting more than it receives), and
 *    the layers below weighed by 1 - max(sheen_color) min(S(mu_o), 1), glTF's
 *    albedo scaling: white sheen over white reflects 1; not reciprocal.
 *  - the clear coat (KHR_materials_clearcoat), over all the above: a GGX
 *    dielectric interface of ior 1.5 (bsdf/coat_fresnel.h) of its own
 *    roughness, weighted by `clearcoat`, with its multiple-scattering lobe,
 *    and what lies below it weighed by 1 - clearcoat C(mu_o), C the coat's
 *    whole directional albedo: a white material under any coat reflects 1.
 *    That weight depends on wo alone (the albedo scaling of OpenPBR and of
 *    Cycles' Principled BSDF), so a coated material is not reciprocal.
 *  A program whose scene has no sheen or no clear coat (WF_HAS_SHEEN,
 *  WF_HAS_CLEARCOAT: compiled_features.h) leaves that lobe's code out; it
 *  only ever ran for a factor above 0, so the bits are the same.
 *
 * The smooth limit: below alpha = WF_BSDF_DELTA_ALPHA (roughness 0.0316), or
 * for a transmissive material of ior exactly 1, the interface is a Dirac
 * mirror and a Dirac refraction (Snell), chosen in proportion to R and T at
 * wo.z. bsdf_eval and bsdf_pdf never include Dirac lobes; bsdf_sample marks
 * them with delta = 1, f = weight / |wi.z| and pdf = the probability of having
 * chosen that lobe, so that f |wi.z| / pdf is the path weight: never evaluate
 * or MIS-weigh them. bsdf_is_delta: every lobe is Dirac (NEE is useless).
 *
 * Sampling, one sample of a mixture: first the clear coat's GGX lobe (a
 * mirror when smooth) with probability p_coat, in proportion to its albedo
 * at wo against that of everything below; else, below the coat,
 * the interface with probability p_int, in
 * proportion to the luminances of R(wo.z) + T(wo.z) against the albedo of the
 * base lobes at wo.z (diffuse, multiple scattering, sheen), which are sampled
 * together: by the hemisphere sampler, or with probability p_loss (at most
 * 0.9, in proportion to its albedo) by the shape of the interface's
 * multiple-scattering lobe, or with probability p_sheen (its share of their
 * albedo) by the sheen's own sampler (bsdf/sheen.h); at least
 * WF_BSDF_MIN_LOBE_PROBABILITY for each while both are there, 1 where
 * none is, and 0 where the interface neither reflects nor transmits (specular
 * 0 on a dielectric: a plain Lambertian surface). The interface samples a GGX visible normal (Heitz 2018) and then
 * reflects or refracts in proportion to the luminances of R and T at wo.wm.
 * bsdf_pdf is the density of that whole procedure (lobe choices included)
 * over the non-Dirac lobes, and a non-Dirac sample returns bsdf_eval and
 * bsdf_pdf of the whole mixture (one-sample MIS over the lobes, balance
 * heuristic). A sample that leaves no valid direction (a reflection below
 * the horizon, a refraction blocked by total internal reflection) returns
 * pdf = 0: the path ends, and that probability is simply lost. u: three
 * uniforms in [0,1): u.x picks the lobes, u.y and u.z the direction. */
#ifndef WF_BSDF_H
#define WF_BSDF_H

#include "wavefront/compat.h"
#include "wavefront/techniques.h"
#include "compiled_features.h"
#include "common/sampling.h"
#include "bsdf/albedo.h"
#include "bsdf/coat_fresnel.h"
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"
#include "bsdf/sheen.h"

#define WF_BSDF_DELTA_ALPHA 1e-3f
/* The coat's multiple scattering, sampled by the cosine with the base, is left
 * out below this 1 - E_avg: it would return at most 0.1% of its tiny share. */
#define WF_BSDF_COAT_MIN_LOSS 1e-3f
#define WF_BSDF_MIN_LOBE_PROBABILITY 0.05f

WF_DEVICE_BEGIN

typedef struct BsdfParams {
    float3 base_color;
    float metallic;
    float roughness;    /* glTF's perceptual roughness; alpha = roughness^2 */
    float transmission; /* KHR_materials_transmission */
    float ior;          /* KHR_materials_ior, 1.5 by default */
    float specular;     /* KHR_materials_specular's factor: scales F_d; 0 leaves a plain Lambertian base */
    float3 specular_color; /* KHR_materials_specular's colour: tints F_d's F0 */
    uint32_t thin_walled; /* transmission through a thin sheet: no bending, both sides alike */
    float clearcoat;           /* KHR_materials_clearcoat: the coat's weight, 0 for none */
    float clearcoat_roughness; /* perceptual, alpha = roughness^2 */
    float3 sheen_color;        /* KHR_materials_sheen: black for none */
    float sheen_roughness;
    uint32_t hemisphere; /* WF_HEMISPHERE_*: how the diffuse lobe samples */
#if WF_GLASS_TABLE_IN_SCENE
    __global const float* glass_table; /* the scene's copy of glass_albedo_table (bsdf/albedo.h) */
#endif
} BsdfParams;

typedef struct BsdfSample {
    float3 wi;
    float3 f;  /* without the cosine */
    float pdf; /* solid angle; for a Dirac lobe the lobe's probability; 0: no sample */
    int delta; /* a Dirac lobe was chosen */
} BsdfSample;

WF_INLINE float bsdf_luminance(float3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

WF_INLINE float3 bsdf_gray(float v) { return make_float3(v, v, v); }

WF_INLINE int bsdf_interface_smooth(const BsdfParams* p) {
    return p->roughness * p->roughness < WF_BSDF_DELTA_ALPHA || (p->transmission > 0.0f && p->ior == 1.0f);
}

/* A solid transmissive material: wo may arrive from inside (wo.z < 0), and
 * refraction bends. Opaque and thin-walled materials are seen from outside. */
WF_INLINE int bsdf_has_inside(const BsdfParams* p) { return p->transmission > 0.0f && !p->thin_walled; }

/* The dielectric layer's Schlick F0, min(F0(ior) specular_color, 1) specular;
 * its F90 is the specular factor (KHR_materials_specular). */
WF_INLINE float3 bsdf_layer_f0(const BsdfParams* p) {
    return p->specular * min(fresnel_f0(p->ior) * p->specular_color, bsdf_gray(1.0f));
}

/* F_d, the dielectric layer's reflectance; cos_i < 0 from inside. A solid
 * transmissive layer follows the exact Fresnel term from its F0 to 1 (its
 * total internal reflection included), remapped to the coloured F0. */
WF_INLINE float3 bsdf_layer_fresnel(const BsdfParams* p, float cos_i) {
    const float3 f0 = bsdf_layer_f0(p);
    if (!bsdf_has_inside(p)) return f0 + (bsdf_gray(p->specular) - f0) * schlick_weight(cos_i);
    const float f0_ior = fresnel_f0(p->ior);
    const float toward_one = (fresnel_dielectric(cos_i, p->ior) - f0_ior) / (1.0f - f0_ior);
    return f0 + (bsdf_gray(p->specular) - f0) * toward_one;
}

WF_INLINE float3 bsdf_reflectance(const BsdfParams* p, float cos_i) {
    return (1.0f - p->metallic) * bsdf_layer_fresnel(p, cos_i) + p->metallic * fresnel_schlick(p->base_color, cos_i);
}

WF_INLINE float3 bsdf_transmittance(const BsdfParams* p, float cos_i) {
    if (!(p->transmission > 0.0f)) return bsdf_gray(0.0f);
    return ((1.0f - p->metallic) * p->transmission) * (bsdf_gray(1.0f) - bsdf_layer_fresnel(p, cos_i)) *
           p->base_color;
}

WF_INLINE float3 bsdf_diffuse_albedo(const BsdfParams* p) {
    return ((1.0f - p->metallic) * (1.0f - p->transmission)) * p->base_color;
}

/* What the BSDF needs at one wo, whatever wi: the interface's albedo tables
 * at mu_o and averaged, what follows from them, and the probabilities of
 * sampling's lobe choices. The shade stage computes it once per shading point
 * (bsdf_at_wo) for light sampling's evaluation and BSDF sampling alike. */
typedef struct BsdfAtWo {
    float2 at_o;
    float2 average;
    float3 layer_f0;             /* bsdf_layer_f0 */
    float3 layer_multiple_color; /* MS(F0_d, F90_d), the dielectric layer's alone */
    float3 multiple_color;       /* C of the multiple-scattering lobe */
    float3 layer_o;              /* L(mu_o), the dielectric layer's whole albedo */
    float3 layer_average;        /* L_avg */
    float glass_scale;           /* 1 / E_g(mu_o) for a rough solid glass, else 1 */
    /* The clear coat, when there is one and wo is outside: */
    float2 coat_at_o;       /* its {E, B} at mu_o */
    float coat_e_average;   /* its E_avg */
    float coat_multiple;    /* clearcoat MS(F0_c, 1): its multiple-scattering lobe's colour */
    float coat_o;           /* clearcoat times its whole albedo at mu_o */
    float under_coat;       /* 1 - coat_o: what reaches the layers below from wo */
    /* The sheen, when there is one and wo is outside: */
    float sheen_norm;       /* 1 / max(1, S(mu_o)): its lobe never reflects more than it receives */
    float sheen_o;          /* max(sheen_color) S(mu_o) sheen_norm, at most 1 */
    float under_sheen;      /* 1 - sheen_o: what reaches the layers below the sheen */
    /* Sampling's choices (bsdf_coat_probability, bsdf_interface_probability,
     * bsdf_loss_probability): */
    float p_coat;
    float p_interface;
    float p_loss;  /* within the base lobes: drawing from the multiple-scattering lobe's shape */
    float p_sheen; /* within the base lobes: drawing from the sheen's sampler (bsdf/sheen.h) */
} BsdfAtWo;

WF_INLINE int bsdf_coat_smooth(const BsdfParams* p) {
    return p->clearcoat_roughness * p->clearcoat_roughness < WF_BSDF_DELTA_ALPHA;
}

/* L at one cosine from its {E, B}, or L_avg from the averages. */
WF_INLINE float3 bsdf_layer_albedo(const BsdfParams* p, const BsdfAtWo* a, float2 eb) {
    return schlick_albedo(eb, a->layer_f0, p->specular) + a->layer_multiple_color * (1.0f - eb.x);
}

WF_INLINE BsdfAtWo bsdf_albedo(const BsdfParams* p, float mu_o) {
    BsdfAtWo a;
    a.at_o = ggx_albedo(fabs(mu_o), p->roughness);
    a.average = ggx_albedo_average(p->roughness);
    const float e_avg = a.average.x;
    a.layer_f0 = bsdf_layer_f0(p);
    a.layer_multiple_color = multiple_scattering_color(a.layer_f0, p->specular, e_avg);
    /* A Dirac interface loses nothing, and its lobes must stay Dirac alone. */
    a.multiple_color = bsdf_interface_smooth(p)
                           ? bsdf_gray(0.0f)
                           : p->metallic * multiple_scattering_color(p->base_color, 1.0f, e_avg) +
                                 ((1.0f - p->metallic) * (1.0f - p->transmission)) * a.layer_multiple_color;
    a.layer_o = bsdf_layer_albedo(p, &a, a.at_o);
    a.layer_average = bsdf_layer_albedo(p, &a, a.average);
    a.glass_scale = bsdf_has_inside(p) && !bsdf_interface_smooth(p)
                        ? 1.0f / glass_albedo(WF_GLASS_TABLE(p), fabs(mu_o), p->roughness, p->ior, mu_o < 0.0f)
                        : 1.0f;
    a.coat_at_o = make_float2(1.0f, 0.0f);
    a.coat_e_average = 1.0f;
    a.coat_multiple = 0.0f;
    a.coat_o = 0.0f;
    if (WF_HAS_CLEARCOAT && p->clearcoat > 0.0f && mu_o > 0.0f) {
        if (bsdf_coat_smooth(p)) {
            a.coat_o = p->clearcoat * coat_fresnel(mu_o);
        } else {
            a.coat_at_o = ggx_albedo(mu_o, p->clearcoat_roughness);
            a.coat_e_average = ggx_albedo_average(p->clearcoat_roughness).x;
            a.coat_multiple =
                1.0f - a.coat_e_average > WF_BSDF_COAT_MIN_LOSS
                    ? p->clearcoat * multiple_scattering_color(bsdf_gray(WF_BSDF_COAT_F0), 1.0f, a.coat_e_average).x
                    : 0.0f;
            a.coat_o = p->clearcoat * schlick_albedo(a.coat_at_o, bsdf_gray(WF_BSDF_COAT_F0), 1.0f).x +
                       a.coat_multiple * (1.0f - a.coat_at_o.x);
        }
    }
    a.under_coat = 1.0f - a.coat_o;
    a.sheen_norm = 1.0f;
    a.sheen_o = 0.0f;
    const float sheen_max = max(max(p->sheen_color.x, p->sheen_color.y), p->sheen_color.z);
    if (WF_HAS_SHEEN && sheen_max > 0.0f && mu_o > 0.0f) {
        const float s = sheen_albedo(mu_o, p->sheen_roughness);
        a.sheen_norm = 1.0f / max(1.0f, s);
        a.sheen_o = sheen_max * s * a.sheen_norm;
    }
    a.under_sheen = 1.0f - a.sheen_o;
    return a;
}

/* The diffuse and multiple-scattering lobes together, wo.z > 0 and wi.z > 0. */
WF_INLINE float3 bsdf_base_eval(const BsdfParams* p, const BsdfAtWo* a, float mu_i) {
    const float2 at_i = ggx_albedo(mu_i, p->roughness);
    const float3 one = bsdf_gray(1.0f);
    const float3 layer_i = bsdf_layer_albedo(p, a, at_i);
    const float3 diffuse = bsdf_diffuse_albedo(p) * (one - a->layer_o) * (one - layer_i) /
                           (WF_PI * max(one - a->layer_average, bsdf_gray(1e-6f)));
    return diffuse + a->multiple_color * multiple_scattering_lobe(a->at_o.x, at_i.x, a->average.x);
}

/* The albedo at wo of what bsdf_base_eval gives, outside. */
WF_INLINE float3 bsdf_base_albedo(const BsdfParams* p, const BsdfAtWo* a) {
    return bsdf_diffuse_albedo(p) * (bsdf_gray(1.0f) - a->layer_o) + a->multiple_color * (1.0f - a->at_o.x);
}

/* The luminances at wo that sampling's lobe choices weigh, computed once by
 * bsdf_at_wo: the interface's R + T, the albedo of bsdf_base_eval's lobes, and
 * that of every lobe the base sampling draws for (those, the coat's multiple
 * scattering and the sheen; 0 from inside). */
typedef struct BsdfLobeAlbedos {
    float interface;
    float base_eval;
    float base_group;
} BsdfLobeAlbedos;

/* The probability that sampling chooses the clear coat's GGX lobe (its
 * multiple scattering is sampled with the base, by the hemisphere sampler),
 * in proportion to its albedo at wo against the layers' below it. */
WF_INLINE float bsdf_coat_probability(const BsdfAtWo* a, const BsdfLobeAlbedos* e) {
    if (!WF_HAS_CLEARCOAT || !(a->coat_o > 0.0f)) return 0.0f;
    const float e_coat = a->coat_o - a->coat_multiple * (1.0f - a->coat_at_o.x);
    const float e_below = a->under_coat * (a->under_sheen * (e->interface + e->base_eval) + a->sheen_o) +
                          a->coat_multiple * (1.0f - a->coat_at_o.x);
    if (!(e_below > 0.0f)) return 1.0f;
    return min(max(e_coat / (e_coat + e_below), WF_BSDF_MIN_LOBE_PROBABILITY), 1.0f - WF_BSDF_MIN_LOBE_PROBABILITY);
}

/* Within the base lobes, the probability of drawing from the interface's
 * multiple-scattering lobe's shape rather than the hemisphere sampler, in
 * proportion to that lobe's albedo; at most 0.9, so that the hemisphere
 * sampler still covers every lobe. */
WF_INLINE float bsdf_loss_probability(const BsdfParams* p, const BsdfAtWo* a, float3 wo, const BsdfLobeAlbedos* e) {
    const float e_loss = wo.z > 0.0f ? bsdf_luminance(a->multiple_color) * (1.0f - a->at_o.x) : 0.0f;
    if (!(e_loss > 0.0f) || !(e->base_group > 0.0f) || loss_histogram_empty(p->roughness)) return 0.0f;
    return min(e_loss / e->base_group, 0.9f);
}

/* Within the base lobes, the probability of drawing from the sheen's own
 * sampler, its share of their albedo. The loss's and the sheen's albedos are
 * parts of base_group, so with p_loss it stays at most 1. */
WF_INLINE float bsdf_sheen_probability(const BsdfAtWo* a, const BsdfLobeAlbedos* e) {
    return WF_HAS_SHEEN && a->sheen_o > 0.0f && e->base_group > 0.0f ? min(a->sheen_o / e->base_group, 1.0f - a->p_loss)
                                                                     : 0.0f;
}

/* The probability that sampling chooses the interface rather than the base lobes. */
WF_INLINE float bsdf_interface_probability(const BsdfLobeAlbedos* e) {
    if (!(e->base_group > 0.0f)) return 1.0f;
    if (!(e->interface > 0.0f)) return 0.0f; /* a plain Lambertian surface: no sample is wasted */
    /* Neither lobe starves: a weight f |cos| / pdf stays within 1 / 0.05 of its lobe's. */
    return min(max(e->interface / (e->interface + e->base_group), WF_BSDF_MIN_LOBE_PROBABILITY),
               1.0f - WF_BSDF_MIN_LOBE_PROBABILITY);
}

WF_INLINE BsdfAtWo bsdf_at_wo(const BsdfParams* p, float3 wo) {
    BsdfAtWo a = bsdf_albedo(p, wo.z);
    BsdfLobeAlbedos e;
    e.interface = bsdf_luminance(bsdf_reflectance(p, wo.z)) + bsdf_luminance(bsdf_transmittance(p, wo.z));
    e.base_eval = bsdf_luminance(bsdf_base_albedo(p, &a));
    e.base_group = wo.z > 0.0f ? e.base_eval + a.coat_multiple * (1.0f - a.coat_at_o.x) + a.sheen_o : 0.0f;
    a.p_coat = bsdf_coat_probability(&a, &e);
    a.p_interface = bsdf_interface_probability(&e);
    a.p_loss = bsdf_loss_probability(p, &a, wo, &e);
    a.p_sheen = bsdf_sheen_probability(&a, &e);
    return a;
}

/* The probability of reflecting rather than refracting, given R and T. */
WF_INLINE float bsdf_reflect_probability(float3 r, float3 t) {
    const float lr = bsdf_luminance(r), lt = bsdf_luminance(t);
    return lr + lt > 0.0f ? lr / (lr + lt) : 1.0f;
}

/* The rough interface's f and, in *pdf, the density of sampling wi given that
 * the interface was chosen. */
WF_INLINE float3 bsdf_interface_eval(const BsdfParams* p, const BsdfAtWo* a, float3 wo, float3 wi, float* pdf) {
    *pdf = 0.0f;
    if (wo.z == 0.0f || wi.z == 0.0f) return bsdf_gray(0.0f);
    const int reflect = wo.z * wi.z > 0.0f;
    if (!reflect && !(p->transmission > 0.0f)) return bsdf_gray(0.0f);
    /* A thin wall transmits into the mirror image of its reflection lobe. */
    const int thin_transmission = !reflect && p->thin_walled;
    if (thin_transmission) wi.z = -wi.z;
    const float cos_o = wo.z, cos_i = wi.z;
    const float etap = reflect || thin_transmission ? 1.0f : (cos_o > 0.0f ? p->ior : 1.0f / p->ior);
    float3 wm = wi * etap + wo;
    const float len2 = dot(wm, wm);
    if (!(len2 > 0.0f)) return bsdf_gray(0.0f);
    wm = wm / sqrt(len2);
    if (wm.z < 0.0f) wm = -wm;
    const float dot_o = dot(wo, wm), dot_i = dot(wi, wm);
    /* Microfacets seen from behind by either direction carry nothing. */
    if (!(dot_o * cos_o > 0.0f) || !(dot_i * cos_i > 0.0f)) return bsdf_gray(0.0f);
    const float alpha = p->roughness * p->roughness;
    float3 r = bsdf_reflectance(p, dot_o);
    float3 t = bsdf_transmittance(p, dot_o);
    const float p_reflect = bsdf_reflect_probability(r, t);
    if (a->glass_scale != 1.0f) {
        /* The glass share's reflection and its refraction, made whole. */
        r = r + ((a->glass_scale - 1.0f) * (1.0f - p->metallic) * p->transmission) * bsdf_layer_fresnel(p, dot_o);
        t = a->glass_scale * t;
    }
    const float d = ggx_d(wm, alpha);
    const float g = ggx_g2(wo, wi, alpha);
    const float pdf_wm = ggx_pdf_visible(wo, wm, alpha);
    if (reflect || thin_transmission) {
        *pdf = (reflect ? p_reflect : 1.0f - p_reflect) * pdf_wm / (4.0f * fabs(dot_o));
        return (reflect ? r : t) * (d * g / (4.0f * fabs(cos_o) * fabs(cos_i)));
    }
    const float denom = dot_i + dot_o / etap;
    const float denom2 = denom * denom;
    if (!(denom2 > 0.0f)) return bsdf_gray(0.0f);
    *pdf = (1.0f - p_reflect) * pdf_wm * fabs(dot_i) / denom2;
    return t * (d * g * fabs(dot_i * dot_o) / (denom2 * fabs(cos_i) * fabs(cos_o) * etap * etap));
}

/* The density of the base lobes' sampling: the hemisphere sampler, or with
 * probability p_loss the multiple-scattering lobe's shape, or with
 * probability p_sheen the sheen's sampler. */
WF_INLINE float bsdf_base_pdf(const BsdfParams* p, const BsdfAtWo* a, float3 wi) {
    if (!(wi.z > 0.0f)) return 0.0f;
    const float hemisphere = p->hemisphere == WF_HEMISPHERE_COSINE ? wi.z * WF_INV_PI : 0.5f * WF_INV_PI;
    if (!(a->p_loss > 0.0f) && !(a->p_sheen > 0.0f)) return hemisphere;
    float pdf = (1.0f - a->p_loss - a->p_sheen) * hemisphere;
    if (a->p_loss > 0.0f) pdf += a->p_loss * loss_pdf(p->roughness, wi.z);
    if (WF_HAS_SHEEN && a->p_sheen > 0.0f) pdf += a->p_sheen * sheen_sample_pdf(p->sheen_roughness, wi.z);
    return pdf;
}

/* The clear coat's f (both its lobes) and, in *pdf, the density of sampling
 * wi given that its GGX lobe was chosen; wo.z > 0 and wi.z > 0. */
WF_INLINE float bsdf_coat_eval(const BsdfParams* p, const BsdfAtWo* a, float3 wo, float3 wi, float* pdf) {
    *pdf = 0.0f;
    if (bsdf_coat_smooth(p)) return 0.0f;
    const float alpha = p->clearcoat_roughness * p->clearcoat_roughness;
    const float3 wm = normalize(wo + wi);
    const float dot_o = dot(wo, wm);
    if (!(dot_o > 0.0f)) return 0.0f;
    *pdf = ggx_pdf_visible(wo, wm, alpha) / (4.0f * dot_o);
    const float single = p->clearcoat * coat_fresnel(dot_o) * ggx_d(wm, alpha) *
                         ggx_g2(wo, wi, alpha) / (4.0f * wo.z * wi.z);
    return single +
           a->coat_multiple * multiple_scattering_lobe(a->coat_at_o.x, ggx_albedo(wi.z, p->clearcoat_roughness).x,
                                                       a->coat_e_average);
}

/* f and pdf of the non-Dirac lobes together. The clear coat lies over the
 * rest and keeps from it what it reflects at wo: the rest is weighed by
 * under_coat = 1 - clearcoat C(mu_o), C the coat's whole albedo (the albedo
 * scaling of OpenPBR and of Cycles' Principled BSDF: white under a white coat
 * reflects exactly 1, though the weight depends on wo alone and is not
 * reciprocal). */
WF_INLINE float3 bsdf_eval_pdf_at(const BsdfParams* p, const BsdfAtWo* at, float3 wo, float3 wi, float* pdf) {
    *pdf = 0.0f;
    float3 f = bsdf_gray(0.0f);
    if (!bsdf_has_inside(p) && !(wo.z > 0.0f)) return f;
    const float p_coat = at->p_coat;
    const float p_interface = at->p_interface;
    if (!bsdf_interface_smooth(p)) {
        float pdf_interface;
        f = bsdf_interface_eval(p, at, wo, wi, &pdf_interface);
        *pdf = p_interface * pdf_interface;
    }
    if (wo.z > 0.0f && wi.z > 0.0f) {
        f = f + bsdf_base_eval(p, at, wi.z);
        *pdf += (1.0f - p_interface) * bsdf_base_pdf(p, at, wi);
    }
    if (WF_HAS_SHEEN && at->sheen_o > 0.0f) {
        f = at->under_sheen * f;
        if (wi.z > 0.0f) f = f + p->sheen_color * (at->sheen_norm * sheen_eval(wo, wi, p->sheen_roughness));
    }
    if (WF_HAS_CLEARCOAT && at->coat_o > 0.0f) {
        f = at->under_coat * f;
        *pdf = (1.0f - p_coat) * *pdf;
        if (wi.z > 0.0f) {
            float pdf_coat;
            f = f + bsdf_gray(bsdf_coat_eval(p, at, wo, wi, &pdf_coat));
            *pdf += p_coat * pdf_coat;
        }
    }
    return f;
}

WF_INLINE float3 bsdf_eval_pdf(const BsdfParams* p, float3 wo, float3 wi, float* pdf) {
    const BsdfAtWo at = bsdf_at_wo(p, wo);
    return bsdf_eval_pdf_at(p, &at, wo, wi, pdf);
}

WF_INLINE float3 bsdf_eval(const BsdfParams* p, float3 wo, float3 wi) {
    float pdf;
    return bsdf_eval_pdf(p, wo, wi, &pdf);
}

WF_INLINE float bsdf_pdf(const BsdfParams* p, float3 wo, float3 wi) {
    float pdf;
    bsdf_eval_pdf(p, wo, wi, &pdf);
    return pdf;
}

WF_INLINE int bsdf_is_delta(const BsdfParams* p) {
    const float3 albedo = bsdf_diffuse_albedo(p);
    return bsdf_interface_smooth(p) && !(albedo.x + albedo.y + albedo.z > 0.0f) &&
           (!(p->clearcoat > 0.0f) || bsdf_coat_smooth(p)) &&
           !(p->sheen_color.x + p->sheen_color.y + p->sheen_color.z > 0.0f);
}

WF_INLINE BsdfSample bsdf_sample_at(const BsdfParams* p, const BsdfAtWo* at, float3 wo, float3 u) {
    BsdfSample s;
    s.wi = make_float3(0.0f, 0.0f, 1.0f);
    s.f = bsdf_gray(0.0f);
    s.pdf = 0.0f;
    s.delta = 0;
    if (wo.z == 0.0f || (!bsdf_has_inside(p) && !(wo.z > 0.0f))) return s;
    const float p_coat = at->p_coat;
    if (WF_HAS_CLEARCOAT && u.x < p_coat) {
        if (bsdf_coat_smooth(p)) {
            s.wi = make_float3(-wo.x, -wo.y, wo.z);
            s.f = bsdf_gray(at->coat_o / wo.z);
            s.pdf = p_coat;
            s.delta = 1;
            return s;
        }
        const float alpha = p->clearcoat_roughness * p->clearcoat_roughness;
        const float3 wm = ggx_sample_visible(wo, alpha, make_float2(u.y, u.z));
        s.wi = 2.0f * dot(wo, wm) * wm - wo;
        if (!(s.wi.z > 0.0f)) return s;
        float pdf;
        const float3 f = bsdf_eval_pdf_at(p, at, wo, s.wi, &pdf);
        if (pdf > 0.0f) {
            s.f = f;
            s.pdf = pdf;
        }
        return s;
    }
    /* (u.x - p_coat) / (1 - p_coat) is uniform again: it chooses below the coat. */
    u.x = min((u.x - p_coat) / (1.0f - p_coat), 0x1.fffffep-1f);
    const float p_below = 1.0f - p_coat;
    const float below = at->under_coat * at->under_sheen; /* the weight of Dirac lobes below coat and sheen */
    const float p_interface = at->p_interface;
    if (u.x < p_interface) {
        /* u.x / p_interface is uniform again: it picks reflection or refraction. */
        const float u_choice = min(u.x / p_interface, 0x1.fffffep-1f);
        if (bsdf_interface_smooth(p)) {
            const float3 r = bsdf_reflectance(p, wo.z);
            const float3 t = bsdf_transmittance(p, wo.z);
            const float p_reflect = bsdf_reflect_probability(r, t);
            if (u_choice < p_reflect) {
                s.wi = make_float3(-wo.x, -wo.y, wo.z);
                s.f = below * r / fabs(wo.z);
                s.pdf = p_below * p_interface * p_reflect;
            } else if (p->thin_walled) {
                s.wi = -wo;
                s.f = below * t / fabs(wo.z);
                s.pdf = p_below * p_interface * (1.0f - p_reflect);
            } else {
                float3 wi;
                if (!fresnel_refract(wo, make_float3(0.0f, 0.0f, 1.0f), p->ior, &wi) || wi.z == 0.0f) return s;
                const float etap = wo.z > 0.0f ? p->ior : 1.0f / p->ior;
                s.wi = wi;
                s.f = below * t / (fabs(wi.z) * etap * etap);
                s.pdf = p_below * p_interface * (1.0f - p_reflect);
            }
            s.delta = 1;
            return s;
        }
        const float alpha = p->roughness * p->roughness;
        const float3 wm = ggx_sample_visible(wo.z > 0.0f ? wo : -wo, alpha, make_float2(u.y, u.z));
        const float dot_o = dot(wo, wm);
        const float p_reflect = bsdf_reflect_probability(bsdf_reflectance(p, dot_o), bsdf_transmittance(p, dot_o));
        float3 wi;
        if (u_choice < p_reflect || p->thin_walled) {
            wi = 2.0f * dot_o * wm - wo;
            if (!(wi.z * wo.z > 0.0f)) return s;
            if (!(u_choice < p_reflect)) wi.z = -wi.z; /* through the thin wall */
        } else {
            if (!fresnel_refract(wo, wm, p->ior, &wi) || !(wi.z * wo.z < 0.0f)) return s;
        }
        s.wi = wi;
    } else {
        /* (u.x - p_interface) / (1 - p_interface) is uniform again: it picks the base lobes' sampler. */
        const float u_base = min((u.x - p_interface) / (1.0f - p_interface), 0x1.fffffep-1f);
        if (u_base < at->p_loss + at->p_sheen) {
            /* A cosine from the loss's shape or the sheen's sampler, and a uniform azimuth. */
            const float mu = !WF_HAS_SHEEN || u_base < at->p_loss ? loss_sample_mu(p->roughness, u.y)
                                                                  : sheen_sample_mu(p->sheen_roughness, u.y);
            const float r = sqrt(max(0.0f, 1.0f - mu * mu));
            s.wi = make_float3(r * cospi(2.0f * u.z), r * sinpi(2.0f * u.z), mu);
        } else {
            const float2 ud = make_float2(u.y, u.z);
            s.wi = p->hemisphere == WF_HEMISPHERE_COSINE ? sample_cosine_hemisphere(ud) : sample_uniform_hemisphere(ud);
        }
    }
    float pdf;
    const float3 f = bsdf_eval_pdf_at(p, at, wo, s.wi, &pdf);
    if (!(pdf > 0.0f)) return s;
    s.f = f;
    s.pdf = pdf;
    return s;
}

WF_INLINE BsdfSample bsdf_sample(const BsdfParams* p, float3 wo, float3 u) {
    const BsdfAtWo at = bsdf_at_wo(p, wo);
    return bsdf_sample_at(p, &at, wo, u);
}

WF_DEVICE_END

#endif /* WF_BSDF_H */
