/* finite.h — NaN and Inf tests by bit pattern. Compilers may fold isnan and
 * isinf away under fast-math; an exponent field of all ones cannot be folded. */
#ifndef WF_FINITE_H
#define WF_FINITE_H

#include "wavefront/compat.h"

WF_INLINE bool is_finite_bits(float x) { return (as_uint(x) & 0x7f800000u) != 0x7f800000u; }

WF_INLINE bool is_finite3(float3 v) {
    return is_finite_bits(v.x) && is_finite_bits(v.y) && is_finite_bits(v.z);
}

#endif
