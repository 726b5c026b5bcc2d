/**
 * @file westergaard.h
 * @brief For the tests of Griffith's crack in stages 6 and 7: the exact
 *        Westergaard stress of an infinite plate with an inclined centre
 *        crack under a remote tension, and a growing text to write the
 *        scenes whose edges carry it.
 */
#ifndef MPM_TEST_WESTERGAARD_H
#define MPM_TEST_WESTERGAARD_H

#include <complex.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "testkit.h"

/**
 * The stress (xx, yy, xy) at (X, Y) of an infinite plate under the remote
 * tension @p sigma along y with the crack |x'| <= a, y' = 0 of a frame
 * turned by @p beta. In that frame the remote state is S = sigma cos^2
 * beta normal to the crack, T = sigma sin beta cos beta along it in shear
 * and P = sigma sin^2 beta parallel to it; Westergaard's functions
 * Z = z / sqrt(z^2 - a^2) (times S for mode I, T for mode II), with
 * Z' = -a^2 / (z^2 - a^2)^(3/2), give (Westergaard 1939; Anderson,
 * Fracture Mechanics, ch. 2)
 *   mode I:  s_xx = Re Z - y Im Z',     s_yy = Re Z + y Im Z', s_xy = -y Re Z'
 *   mode II: s_xx = 2 Im Z + y Re Z',   s_yy = -y Re Z',       s_xy = Re Z - y Im Z'
 * The mode I function also stretches the plate by S along the crack, which
 * P replaces. sqrt(z - a) sqrt(z + a) keeps the branch cut on the crack.
 */
static inline void griffith_stress(double sigma, double beta, double a,
                                   double X, double Y, double s[3])
{
    double c = cos(beta), n = sin(beta);
    double x = c * X + n * Y, y = -n * X + c * Y;          /* crack frame */
    double complex z = x + I * y;
    double complex w = csqrt(z - a) * csqrt(z + a);
    double complex Z = z / w, Zp = -a * a / (w * w * w);
    double S = sigma * c * c, T = sigma * n * c, P = sigma * n * n;
    double sxx = S * (creal(Z) - y * cimag(Zp) - 1.0) +
                 T * (2.0 * cimag(Z) + y * creal(Zp)) + P;
    double syy = S * (creal(Z) + y * cimag(Zp)) - T * y * creal(Zp);
    double sxy = -S * y * creal(Zp) + T * (creal(Z) - y * cimag(Zp));
    /* back to the plate's axes: R s R^T, R's columns (c, n), (-n, c) */
    s[0] = c * c * sxx - 2.0 * c * n * sxy + n * n * syy;
    s[1] = n * n * sxx + 2.0 * c * n * sxy + c * c * syy;
    s[2] = c * n * (sxx - syy) + (c * c - n * n) * sxy;
}

/** A growing text. */
typedef struct Text {
    char *s;        /**< the text, NUL-terminated */
    size_t len;     /**< its length */
    size_t cap;     /**< room in s */
} Text;

/** Append to @p t as printf does. */
static inline void text_add(Text *t, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
static inline void text_add(Text *t, const char *fmt, ...)
{
    for (;;) {
        va_list ap;
        va_start(ap, fmt);
        int n = vsnprintf(t->s + t->len, t->cap - t->len, fmt, ap);
        va_end(ap);
        assert_true(n >= 0);
        if ((size_t)n < t->cap - t->len) {
            t->len += (size_t)n;
            return;
        }
        t->cap = 2 * (t->cap + (size_t)n);
        t->s = realloc(t->s, t->cap);
        assert_non_null(t->s);
    }
}

#endif
