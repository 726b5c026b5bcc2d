/**
 * @file hoop_angle.c
 * @brief Where a crack kinks: the direction of the largest hoop stress at
 *        the tip (Erdogan and Sih, J. Basic Eng. 85 (1963) 519-527); stage
 *        6 grows cohesive cracks by it, stage 7 CRAMP cracks.
 */
#include <math.h>

#include "hoop_angle.h"

/// [hoop_angle]
double hoop_angle(double KI, double KII)
{
    if (KII == 0.0)
        return 0.0;                     /* pure mode I: straight ahead */
    /* theta = 2 atan[(K_I - s) / (4 K_II)], s = sqrt(K_I^2 + 8 K_II^2);
       times (K_I + s) / (K_I + s), the same without the cancellation of
       K_I - s when K_II is small: */
    double s = sqrt(KI * KI + 8.0 * KII * KII);
    return 2.0 * atan(-2.0 * KII / (KI + s));
}
/// [hoop_angle]
