/**
 * @file acoustic_search.c
 * @brief The critical direction: the normal that minimises det Q(n), by a
 *        scan over [0, pi) refined by golden-section search (xefg.md 2.4:
 *        "180 samples of phi plus a local refine").
 */
#include <math.h>

#include "acoustic_tensor.h"

static const double PI = 3.14159265358979323846;

/** Golden-section search for a minimum of det Q(phi) in [@p a, @p b],
 *  which must hold one, down to a bracket of 1e-10 rad; the count of
 *  evaluations goes to *@p evals. */
static double golden_min(const double C[3][3], double a, double b, int *evals)
{
    const double g = 0.5 * (sqrt(5.0) - 1.0);  /* 0.618..., 1/golden ratio */
    double x1 = b - g * (b - a), x2 = a + g * (b - a);
    double f1 = acoustic_det(C, x1), f2 = acoustic_det(C, x2);
    *evals += 2;
    for (int it = 0; it < 200 && b - a > 1e-10; it++, ++*evals) {
        if (f1 <= f2) {               /* the minimum lies in [a, x2] */
            b = x2, x2 = x1, f2 = f1;
            x1 = b - g * (b - a);
            f1 = acoustic_det(C, x1);
        } else {                      /* in [x1, b] */
            a = x1, x1 = x2, f1 = f2;
            x2 = a + g * (b - a);
            f2 = acoustic_det(C, x2);
        }
    }
    return 0.5 * (a + b);
}

/// [acoustic_critical]
AcousticCritical acoustic_critical(const double C[3][3], int samples)
{
    if (samples < 8)
        samples = 8;
    double h = PI / samples;
    /* the scan: det Q(phi + pi) = det Q(phi), so [0, pi) holds every
     * normal; ties keep the first sample */
    int best = 0;
    double fbest = acoustic_det(C, 0.0);
    for (int k = 1; k < samples; k++) {
        double f = acoustic_det(C, k * h);
        if (f < fbest)
            best = k, fbest = f;
    }
    AcousticCritical r = {best * h, fbest, 0, samples};
    /* the least sample's neighbours are higher, so [phi_k - h, phi_k + h]
     * holds a minimum (it may reach below 0 or past pi: det Q is periodic) */
    double x = golden_min(C, r.phi - h, r.phi + h, &r.evaluations);
    double f = acoustic_det(C, x);
    r.evaluations++;
    if (f < r.det_min) {              /* keep the sample on a plateau */
        x = fmod(x, PI);
        r.phi = x < 0.0 ? x + PI : x >= PI ? x - PI : x;
        r.det_min = f;
    }
    r.unstable = r.det_min <= 0.0;
    return r;
}
/// [acoustic_critical]
