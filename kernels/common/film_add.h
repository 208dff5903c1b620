/* film_add.h — compensated addition into a film buffer (Kahan–Babuška /
 * Neumaier): the compensation holds what the last addition rounded away and is
 * fed into the next one, so it stays as small as one rounding error. Carrying it
 * separately without feeding it back fails for a constant signal: every
 * rounding error has the same sign, the compensation grows and rounds itself.
 * The film reads sum + compensation. Deterministic, since each pixel has one
 * writer adding its samples in order (see stages/generate.h). */
#ifndef WF_FILM_ADD_H
#define WF_FILM_ADD_H

#include "wavefront/compat.h"

WF_INLINE void film_add(__global float4* sum, __global float4* compensation, uint index, float4 x) {
    const float4 s = sum[index];
    const float4 y = x + compensation[index];
    const float4 t = s + y;
    const int4 sum_larger = isgreaterequal(fabs(s), fabs(y));
    compensation[index] = select((y - t) + s, (s - t) + y, sum_larger);
    sum[index] = t;
}

#endif
