/* counters.h — the statistics the kernels count, in the counter buffer after
 * the queue lengths (wavefront/stage_graph.h), so that one read returns both.
 *   X(COUNTER, "name", what-it-counts) */
#ifndef WAVEFRONT_COUNTERS_H
#define WAVEFRONT_COUNTERS_H

#include "wavefront/stage_graph.h"

#define WF_COUNTERS(X)                                                                            \
    X(CLOSEST_RAYS, "closest_rays", "closest-hit rays traced")                                     \
    X(SHADOW_RAYS, "shadow_rays", "shadow rays traced")                                            \
    X(NONFINITE, "nonfinite", "samples dropped for a NaN or Inf component")                        \
    X(LANE_PATHS, "lane_paths", "paths whose BSDF core ran in the group schedule's lanes")          \
    X(LANE_SLOTS, "lane_slots", "lanes those runs took, filled or not: lane_paths / lane_slots is their fill") \
    X(BUSY_SLOTS, "busy_slots", "slots that started a sample, in a launch that takes paths from camera to film")

/* Finished paths by bounce count, in power-of-two buckets: 0, 1, 2–3, 4–7, ...,
 * the last open-ended; after the counters above. */
#define WF_PATH_LENGTH_BUCKETS 16

#define WF_COUNTER_ENUM(counter, name, what) WF_COUNTER_##counter,
enum CounterId {
    WF_COUNTER_BEFORE_FIRST = WF_QUEUE_COUNT - 1, /* the counters follow the queues' */
    WF_COUNTERS(WF_COUNTER_ENUM)
    WF_COUNTER_PATH_LENGTHS,
    WF_COUNTER_COUNT = WF_COUNTER_PATH_LENGTHS + WF_PATH_LENGTH_BUCKETS
};
#undef WF_COUNTER_ENUM

#endif /* WAVEFRONT_COUNTERS_H */
