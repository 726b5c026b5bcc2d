/**
 * @file gimp_weight.c
 * @brief The 1D uGIMP weight of one node: the hat averaged over the
 *        point's domain (Bardenhagen & Kober 2004; exercise "GIMP weight"
 *        replaces this file).
 */
#include <math.h>

#include "gimp.h"

/// [gimp_weight]
double gimp_weight(double d, double l, double *G)
{
    double r = fabs(d), sg = d < 0 ? -1.0 : 1.0;
    if (r < l) {                        /* the node inside the domain */
        *G = -d / l;
        return 1.0 - (d * d + l * l) / (2.0 * l);
    }
    if (r <= 1.0 - l) {                 /* the domain on one side: linear */
        *G = -sg;
        return 1.0 - r;
    }
    if (r < 1.0 + l) {                  /* the domain over the hat's foot */
        double e = 1.0 + l - r;
        *G = -sg * e / (2.0 * l);
        return e * e / (4.0 * l);
    }
    *G = 0.0;
    return 0.0;
}
/// [gimp_weight]
