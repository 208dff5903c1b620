/* float_error.h — the constant that bounds the rounding error of chained float
 * operations, for the error bounds of geometry/ray_offset.h and
 * geometry/triangle_intersect.h; shared by the kernels and the host.
 *
 * Each correctly rounded operation multiplies its exact result by (1 + e) with
 * |e| <= u = 2^-24. A chain of n of them stays within a factor (1 + theta) with
 * |theta| <= gamma_n = n u / (1 - n u) (Higham, Accuracy and Stability of
 * Numerical Algorithms, lemma 3.1), and gamma_n (1 + gamma_m) <= gamma_(n+m). */
#ifndef WF_FLOAT_ERROR_H
#define WF_FLOAT_ERROR_H

#include "wavefront/compat.h"

WF_DEVICE_BEGIN

WF_INLINE float rounding_gamma(int n) {
    const float nu = (float)n * 0x1p-24f;
    return nu / (1.0f - nu);
}

WF_DEVICE_END

#endif /* WF_FLOAT_ERROR_H */
