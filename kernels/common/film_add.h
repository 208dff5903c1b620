/* film_add.h — compensated addition into a film buffer (Neumaier's variant of
 * Kahan summation): sum + compensation carries the running total to about
 * twice float precision, so a million samples per pixel lose nothing to the
 * float accumulator. Deterministic, since each pixel has one writer adding its
 * samples in order (see stages/generate.cl). */
#ifndef WF_FILM_ADD_H
#define WF_FILM_ADD_H

inline void film_add(__global float4* sum, __global float4* compensation, uint index, float4 x) {
    const float4 s = sum[index];
    const float4 t = s + x;
    const int4 sum_larger = isgreaterequal(fabs(s), fabs(x));
    compensation[index] += select((x - t) + s, (s - t) + x, sum_larger);
    sum[index] = t;
}

#endif
