/* shade — what happens where a ray landed.
 *
 * For each path in the extension queue: a miss adds the environment's radiance,
 * if the scene has one, and ends the path; a hit on an emitter adds its
 * radiance; then, unless the path has reached --max-depth, one light sample is
 * prepared for intersect_shadow (next-event estimation, over every kind of
 * light) and the material's BSDF (its kind's, bsdf/kinds.h) chooses the
 * continuation ray, which roulette may end. --light-sampling decides which of the two
 * techniques counts emitted light: BRDF sampling alone, NEE alone, or both
 * weighted by the power heuristic (MIS), so that no light is counted twice.
 * Delta lights are found by NEE alone, whatever the technique; a Dirac lobe
 * (mirror, smooth glass) takes no light sample and passes pdf 0 on, so the
 * emission its ray finds is counted whole.
 *
 * In steps, so that the group schedule can run all but the first in SIMD
 * lanes (stages/shade_lanes.h): shade_arrival (the path state, a miss, the
 * sample numbers), shade_surface (the above up to a BsdfQuery:
 * stages/surface.inc), shade_light (the light sample: lights/light_lanes.inc
 * for emissive triangles), the BSDF core (the BSDF at the light sample, and a
 * sample), and the scatter (the shadow and continuation rays,
 * stages/scatter.inc, and the next queue). shade_path runs them for one path
 * at width 1. */
#ifndef WF_STAGE_SHADE_H
#define WF_STAGE_SHADE_H

#include "wavefront/compat.h"
#include "wavefront/stage_graph.h"
#include "path_view.h"
#include "scene_view.h"
#include "film_view.h"
#include "common/bounce_layers.h"
#include "common/first_hit_aovs.h"
#include "common/sample_values.h"
#include "materials/surface_material.h"
#include "bsdf/kinds.h"
#include "stages/stage_step.h"
#include "lights/choose_light.h"
#include "geometry/ray_offset.h"
#include "geometry/instance_map.h"
#include "geometry/triangle_blocks.h"
#include "lanes/lanes.h"

/* What shade_surface reads of a hit triangle beyond its corners, which the
 * traversal that found it has just read: asked for early by a schedule that
 * knows its hits before it shades them (the group schedule, after each
 * intersect region), so that a work-group's misses overlap instead of each
 * stalling its path's shading in turn. On a scene larger than the caches the
 * shading normals' miss was most of surface_at's time. */
WF_INLINE void prefetch_surface(const Scene* scene, int triangle) {
    if (triangle < 0) return;
    __global const char* normals = (__global const char*)&scene->normals[triangle];
    WF_PREFETCH(normals);
    WF_PREFETCH(normals + sizeof(TriangleNormals) - 1);
#if WF_HAS_TEXTURES
    __global const char* texcoords = (__global const char*)&scene->texcoords[triangle];
    WF_PREFETCH(texcoords);
    WF_PREFETCH(texcoords + sizeof(TriangleTexcoords) - 1);
#endif
}

/* Radiance the path gathers, into its sum and its bounce layer. */
WF_INLINE void add_radiance(PathState* path, const RenderParams* params, const FilmBuffers* film, uint slot, uint pixel,
                         uint depth, float3 radiance) {
    path->radiance[slot].xyz += radiance;
    add_to_bounce_layer(params, film, pixel, depth, radiance);
}

/* The local shading frame: z is the shading normal. */
typedef struct ShadingFrame {
    float3 x, y, z;
} ShadingFrame;

/* What the surface hands on to the scatter, around the BSDF core. */
typedef struct ShadeContext {
    BsdfQuery query;
    float3 position, position_error, geometric_normal; /* geometric_normal on the frame's side */
    ShadingFrame frame;
    float3 throughput;
    float4 light_u;    /* the light sample's numbers, where query.light */
    float roulette_u;  /* the number roulette draws for the continuation */
    LightSample light; /* shade_light's, where query.light */
} ShadeContext;

/* What a path brings to the surface it arrived at: its ray and hit, as the
 * path state holds them, and the numbers its next bounce draws. */
typedef struct Arrival {
    uint triangle; /* the BVH position of the hit triangle */
#if WF_HAS_INSTANCES
    int instance; /* the placement whose triangle it is */
#endif
    float t, b1, b2;
    float3 direction;
    float pdf_previous; /* 0 for camera rays and delta bounces: nothing to weigh against */
    float3 throughput;
    uint depth, pixel, sample;
    bool goes_on;   /* below --max-depth: the path scatters here */
    float4 light_u; /* the light sample's numbers, where the path goes on and the scene has lights */
    float4 u;       /* BSDF sampling's three, then roulette's */
} Arrival;

/* The scatter's and the surface's arithmetic, written once for any lane
 * width: width 1 here, the group schedule's lanes at theirs (stages/shade_lanes.h). */
#define WF_W 1
#include "lanes/lane_width.inc"
#include "stages/scatter.inc"
#include "stages/surface.inc"
#undef WF_W

#if WF_HAS_INSTANCES
/* surface_geometry of a hit on a placement's mesh: found in the mesh's space,
 * then taken to the world, the point's error bound grown by the map's
 * rounding (geometry/instance_map.h), the normals by the inverse transpose and
 * made unit again. The inverse transpose keeps a normal's side, so the front
 * face is the mesh's. The area stays the mesh's, which is the world's for
 * the one placement whose triangles may emit: the world's, under the identity. */
WF_INLINE SurfaceGeometry_x1 placed_surface_geometry(const Scene* scene, const Arrival* a) {
    __global const Instance* placement = scene->instances + a->instance;
    const float3 direction = map_vector(placement->world_to_object, a->direction);
    SurfaceGeometry_x1 s = surface_geometry_x1(scene, (int)a->triangle, a->b1, a->b2, vec_from_float3(direction));
    const float3 position = vec_to_float3(s.position);
    s.position_error =
        vec_from_float3(map_point_error(placement->object_to_world, position, vec_to_float3(s.position_error),
                                        placement->error_scale));
    s.position = vec_from_float3(map_point(placement->object_to_world, position));
    s.geometric_normal =
        vec_from_float3(normalize(map_normal(placement->world_to_object, vec_to_float3(s.geometric_normal))));
    s.normal = vec_from_float3(normalize(map_normal(placement->world_to_object, vec_to_float3(s.normal))));
    return s;
}
#endif

/* A path's arrival: on a miss, the environment it sees, if any, ends it;
 * on a hit, its ray and hit, but for the sample numbers (arrival_numbers).
 * Returns whether it hit. */
WF_INLINE bool path_arrival(PathState* path, const RenderParams* params, uint slot, const Scene* scene,
                            const FilmBuffers* film, Arrival* a) {
    const float4 hit = path->hit[slot];
    const int triangle = path_hit_triangle(path, slot);
    const float4 ray = path->ray_direction[slot];
    a->direction = ray.xyz;
    a->pdf_previous = ray.w;
    a->depth = path_depth(path, slot);
    const PathSample current = current_sample(path, params, slot);
    a->pixel = current.pixel;
    a->sample = current.sample;
    a->throughput = path->throughput[slot].xyz;

    if (triangle < 0) { /* escaped: the environment, if any, is what it sees */
#if WF_HAS_ENVIRONMENT
        if (params->environment_light != WF_NO_LIGHT) {
            const float pdf_light = scene->lights[params->environment_light].pmf *
                                    environment_pdf(params->environment, scene->environment_texels, a->direction);
            const float weight = emission_weight_x1(params->light_sampling, a->pdf_previous, pdf_light);
            add_radiance(path, params, film, slot, a->pixel, a->depth,
                         weight * a->throughput *
                             environment_radiance(params->environment, scene->environment_texels, a->direction));
        }
#endif
        return false;
    }
    a->triangle = (uint)triangle;
#if WF_HAS_INSTANCES
    a->instance = path_hit_instance(path, slot);
#endif
    a->t = hit.x;
    a->b1 = hit.y;
    a->b2 = hit.z;
    a->goes_on = a->depth < params->max_depth;
    return true;
}

/* Next-event estimation's numbers for a hit's bounce, where the path goes on
 * and the scene has lights; used unless the BSDF is a Dirac one. */
WF_INLINE void arrival_light_numbers(const RenderParams* params, Arrival* a) {
    a->light_u = (float4)(0.0f);
    if (a->goes_on && params->light_count > 0u)
        a->light_u = sample_values(params, a->pixel, a->sample, a->depth, WF_RNG_LIGHT);
}

/* The numbers a hit's bounce draws, where the path goes on. The BSDF group's
 * fourth number is roulette's: drawn with the direction, independent of it,
 * and handed on so that roulette need not draw the group again. */
WF_INLINE void arrival_numbers(const RenderParams* params, Arrival* a) {
    arrival_light_numbers(params, a);
    a->u = a->goes_on ? sample_values(params, a->pixel, a->sample, a->depth, WF_RNG_BSDF) : (float4)(0.0f);
}

/* path_arrival, and on a hit its numbers. */
WF_INLINE bool shade_arrival(PathState* path, const RenderParams* params, uint slot, const Scene* scene,
                             const FilmBuffers* film, Arrival* a) {
    if (!path_arrival(path, params, slot, scene, film, a)) return false;
    arrival_numbers(params, a);
    return true;
}

/* The surface a path arrived at: the emission it found, weighed by MIS,
 * then, unless the path ends here, the shading frame and the BSDF's
 * parameters: the BSDF core's query, but for its light sample (shade_light).
 * Returns whether the path needs the core. */
WF_GPU_INLINE bool shade_surface(PathState* path, const RenderParams* params, uint slot, const Scene* scene,
                             const FilmBuffers* film, const Arrival* a, ShadeContext* c) {
    SurfacePoint point;
    point.triangle = a->triangle;
    point.material = triangle_material(scene->triangles, a->triangle);
    point.b1 = a->b1;
    point.b2 = a->b2;
    const __global Material* m = &scene->materials[point.material];
    const lvec1 direction = vec_from_float3(a->direction);
#if WF_HAS_INSTANCES
    point.instance = a->instance;
    const SurfaceGeometry_x1 s = placed_surface_geometry(scene, a);
#else
    const SurfaceGeometry_x1 s = surface_geometry_x1(scene, (int)a->triangle, a->b1, a->b2, direction);
#endif
    const float3 geometric_normal = vec_to_float3(s.geometric_normal);
    const float3 shading_normal =
        surface_normal(scene, &point, vec_to_float3(s.normal), geometric_normal, -a->direction);
#if WF_HAS_AOVS
    if (a->depth == 0u) /* camera rays are unit: t is the distance */
        add_first_hit_aovs(film, a->pixel, surface_bsdf(m, scene, &point, params->hemisphere).base_color,
                           shading_normal, a->t);
#endif

    /* Emission seen along the ray. */
    const int light = triangle_light(scene->triangles, a->triangle);
    if (light >= 0 && (s.front_face || (m->flags & WF_MATERIAL_DOUBLE_SIDED))) {
        const float cos_light = -vec_dot_x1(s.geometric_normal, direction);
        const float pdf_light = light_pdf_solid_angle_x1(scene->lights[light].pmf, s.area, a->t * a->t, cos_light);
        const float weight = emission_weight_x1(params->light_sampling, a->pdf_previous, pdf_light);
        add_radiance(path, params, film, slot, a->pixel, a->depth,
                     weight * a->throughput * surface_emission(m, scene, &point, geometric_normal, -a->direction));
    }
    if (!a->goes_on) return false;

    BsdfQuery* q = &c->query;
    q->params = surface_bsdf(m, scene, &point, params->hemisphere);
    /* An opaque or thin-walled surface is shaded on the side the ray arrived
     * from; a solid transmissive one keeps its front (counter-clockwise) side
     * as +z, so that wo.z < 0 says the ray arrived from inside. */
    const bool flip = bsdf_has_inside(&q->params) && !s.front_face;
    c->frame.z = flip ? -shading_normal : shading_normal;
    c->geometric_normal = flip ? -geometric_normal : geometric_normal;
    lvec1 frame_x, frame_y;
    const lvec1 frame_z = vec_from_float3(c->frame.z);
    orthonormal_basis_x1(frame_z, &frame_x, &frame_y);
    c->frame.x = vec_to_float3(frame_x);
    c->frame.y = vec_to_float3(frame_y);
    q->wo = vec_to_float3(vec_in_frame_x1(vec_scale_x1(direction, -1.0f), frame_x, frame_y, frame_z));
    c->position = vec_to_float3(s.position);
    c->position_error = vec_to_float3(s.position_error);
    c->throughput = a->throughput;

    /* Next-event estimation: one point on, or direction to, one light. Delta
     * lights are sampled whatever the technique: nothing else finds them. */
    q->light = params->light_count > 0u && !bsdf_is_delta(&q->params);
    c->light_u = a->light_u;
    q->u = a->u.xyz;
    c->roulette_u = a->u.w;
    return true;
}

/* The light sample's direction in the shading frame. */
WF_INLINE float3 light_in_frame(const ShadeContext* c) {
    return vec_to_float3(vec_in_frame_x1(vec_from_float3(c->light.wi), vec_from_float3(c->frame.x),
                                         vec_from_float3(c->frame.y), vec_from_float3(c->frame.z)));
}

/* The light sample of the query, where it takes one, and its direction in
 * the shading frame (as the lanes find it: stages/shade_lanes.h). */
WF_INLINE void shade_light(const RenderParams* params, const Scene* scene, ShadeContext* c) {
    c->light = no_light_sample();
    c->query.wi_light = (float3)(0.0f, 0.0f, 1.0f);
    if (!c->query.light) return;
    c->light = sample_light(params, scene, c->position, c->light_u);
    c->query.wi_light = light_in_frame(c);
}

/* The scatter's inputs for one path, at width 1: its surface, its light
 * sample, and the BSDF core's answer. The frame's x and y are found again
 * from its z, as shade_surface found them (the same bits), so that they need
 * not live through the core: 7 of a GPU's registers. */
WF_INLINE ScatterSurface_x1 scatter_surface_x1(const ShadeContext* c) {
    ScatterSurface_x1 s;
    s.position = vec_from_float3(c->position);
    s.position_error = vec_from_float3(c->position_error);
    s.geometric_normal = vec_from_float3(c->geometric_normal);
    s.frame_z = vec_from_float3(c->frame.z);
    orthonormal_basis_x1(s.frame_z, &s.frame_x, &s.frame_y);
    s.throughput = rgb_from_float3(c->throughput);
    return s;
}

WF_INLINE ScatterLight_x1 scatter_light_x1(const ShadeContext* c) {
    ScatterLight_x1 l;
    l.present = c->query.light;
    l.sample.wi = vec_from_float3(c->light.wi);
    l.sample.radiance = rgb_from_float3(c->light.radiance);
    l.sample.pdf = c->light.pdf;
    l.sample.delta = c->light.delta;
    l.sample.segment_end = (int)c->light.segment_end;
    l.sample.point = vec_from_float3(c->light.point);
    l.sample.point_error = vec_from_float3(c->light.point_error);
    l.sample.normal = vec_from_float3(c->light.normal);
    l.wi_local_z = c->query.wi_light.z;
    return l;
}

WF_INLINE ScatterAnswer_x1 scatter_answer_x1(const BsdfAnswer* a) {
    ScatterAnswer_x1 answer;
    answer.f_light = rgb_from_float3(a->f_light);
    answer.pdf_light = a->pdf_light;
    answer.wi = vec_from_float3(a->sample.wi);
    answer.f = rgb_from_float3(a->sample.f);
    answer.pdf = a->sample.pdf;
    answer.delta = a->sample.delta;
    return answer;
}

/* A shadow ray (stages/scatter.inc) into the path state. */
WF_INLINE void write_shadow_ray(PathState* path, uint slot, const ShadowRay_x1* r) {
    path->shadow_origin[slot] = (float4)(vec_to_float3(r->origin), 0.0f);
    path->shadow_segment[slot] = (float4)(vec_to_float3(r->segment), 0.0f);
}

/* A path's scatter (stages/scatter.inc), at any width, into its path state,
 * its shadow ray already there (write_shadow_ray); returns the queue the path
 * goes to next. A path with a shadow ray waits for it there
 * (intersect_shadow sends it on), so no stage can overwrite the pending ray
 * whatever order the scheduler launches them in. */
WF_INLINE uint write_scatter(PathState* path, uint slot, const Scatter_x1* out, float roulette_u) {
    const uint depth = path_depth(path, slot);
    if (out->shadow)
        /* What intersect_shadow needs to send the path on: the bounce layer
         * the light joins if it arrives, and whether the path goes on after it. */
        set_shadow_light(path, slot, rgb_to_float3(out->shadow_light), depth + 1u, out->continues);
    if (out->continues) {
        set_path_throughput(path, slot, rgb_to_float3(out->throughput), depth + 1u);
        set_path_ray(path, slot, vec_to_float3(out->ray_origin), vec_to_float3(out->ray_direction), out->ray_pdf,
                     roulette_u);
    }
    return out->shadow ? WF_QUEUE_SHADOW : out->continues ? WF_QUEUE_CONTINUE : WF_QUEUE_FINISHED;
}

/* The shadow ray of a path's light sample, into its path state before the
 * BSDF core runs (stages/scatter.inc says why); where the scatter then keeps
 * no shadow ray, nothing reads it. */
WF_INLINE void shade_shadow_ray(PathState* path, const RenderParams* params, uint slot, const ShadeContext* c) {
    if (!c->query.light) return;
    const ScatterSurface_x1 s = scatter_surface_x1(c);
    const ScatterLight_x1 l = scatter_light_x1(c);
    const ShadowRay_x1 r = shadow_ray_x1(&s, &l.sample, 2.0f * params->scene_diameter);
    write_shadow_ray(path, slot, &r);
}

/* The scatter of one path: the shadow ray's light, weighed by MIS, and the
 * continuation ray of the BSDF sample, into the path state (after
 * shade_shadow_ray); returns the queue the path goes to next. */
WF_INLINE uint shade_scatter(PathState* path, const RenderParams* params, uint slot, const ShadeContext* c,
                             const BsdfAnswer* a) {
    const ScatterSurface_x1 s = scatter_surface_x1(c);
    const ScatterLight_x1 l = scatter_light_x1(c);
    const ScatterAnswer_x1 answer = scatter_answer_x1(a);
    const Scatter_x1 out = scatter_x1(&s, &l, &answer, params->light_sampling);
    return write_scatter(path, slot, &out, c->roulette_u);
}

/* The whole stage for one path: surface, light sample, the core at width 1,
 * scatter; returns the queue the path goes to next. */
WF_GPU_INLINE uint shade_path(PathState* path, const RenderParams* params, uint slot, const Scene* scene,
                       const FilmBuffers* film) {
    Arrival arrival;
    ShadeContext c;
    if (!shade_arrival(path, params, slot, scene, film, &arrival) ||
        !shade_surface(path, params, slot, scene, film, &arrival, &c))
        return WF_QUEUE_FINISHED;
    shade_light(params, scene, &c);
    shade_shadow_ray(path, params, slot, &c);
    const BsdfAnswer a = bsdf_core(&c.query);
    return shade_scatter(path, params, slot, &c, &a);
}

WF_FORCE_INLINE uint shade_step(const StageView* v, uint slot, StageTally* t) {
    (void)t;
    return shade_path(v->path, v->params, slot, v->scene, v->film);
}

#endif
