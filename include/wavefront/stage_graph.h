/* stage_graph.h — the wavefront's queues and stages, declared once: from these
 * lists come the queue ids, the host's stage enum and names, the report's and
 * the statistics' columns, the kernels' local queues in the group schedule,
 * and the fullest-first schedule's choice.
 *
 * The queues are index buffers of path slots, one region of pool_size entries
 * per queue in one buffer, each with a counter in the counter buffer
 * (wavefront/counters.h). A slot is in one queue at a time, and each queue
 * has one consumer, which takes it whole before the host zeroes its counter
 * (host/integrator/wavefront_integrator.cpp); so the stages may run in any
 * order, and one extension queue serves both generate and roulette. The
 * order lets the refill schedule clear the counters of each phase with one
 * fill: [EXTEND, REGENERATE] once shade has consumed them, the rest at the end
 * of every iteration, after it has read them.
 *   X(QUEUE, "name", what-it-holds) */
#ifndef WAVEFRONT_STAGE_GRAPH_H
#define WAVEFRONT_STAGE_GRAPH_H

#define WF_QUEUES(X)                                                                       \
    X(EXTEND, "extend", "paths whose ray needs a closest hit, then shading")                \
    X(REGENERATE, "regenerate", "free slots, to receive the next camera sample")            \
    X(SHADOW, "shadow", "paths with a pending shadow ray, before roulette or accumulation") \
    X(CONTINUE, "continue", "shaded paths with a new ray, before roulette")                 \
    X(FINISHED, "finished", "ended paths, to accumulate")

#define WF_QUEUE_ENUM(queue, name, what) WF_QUEUE_##queue,
enum QueueId { WF_QUEUES(WF_QUEUE_ENUM) WF_QUEUE_COUNT };
#undef WF_QUEUE_ENUM

/* The stages along a path, in its order, each a kernel of wavefront.cl that
 * takes the slots of one queue and returns each to the queue that comes next;
 * intersect and shade both take the extension queue, one after the other.
 * The megakernel walks a path through them in this order (stages/stage_step.h).
 *   X(STAGE, kernel_name, QUEUE it consumes) */
#define WF_STAGES(X)                          \
    X(GENERATE, generate, REGENERATE)         \
    X(INTERSECT, intersect, EXTEND)           \
    X(SHADE, shade, EXTEND)                   \
    X(INTERSECT_SHADOW, intersect_shadow, SHADOW) \
    X(ROULETTE, roulette, CONTINUE)           \
    X(ACCUMULATE, accumulate, FINISHED)

/* --sort-materials: the keys of the counting sort of the extension queue by
 * material (kernels/stages/sort_by_material.h); materials beyond share keys. */
#define WF_SORT_KEYS 256

#endif /* WAVEFRONT_STAGE_GRAPH_H */
