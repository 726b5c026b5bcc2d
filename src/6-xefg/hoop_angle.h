/**
 * @file hoop_angle.h
 * @brief Where a crack kinks: the direction of the largest hoop stress at
 *        a tip (Erdogan and Sih, J. Basic Eng. 85 (1963) 519-527). Stage
 *        6's growing cohesive cracks and stage 7's J growth both turn by
 *        it (chapters 6b and 7b).
 */
#ifndef MPM_HOOP_ANGLE_H
#define MPM_HOOP_ANGLE_H

/**
 * @brief The kink angle of maximum hoop stress (Erdogan and Sih 1963),
 *        the root of K_I sin(theta) + K_II (3 cos(theta) - 1) = 0 that
 *        makes sigma_thetatheta largest:
 *        theta_c = 2 atan[(K_I - sqrt(K_I^2 + 8 K_II^2)) / (4 K_II)].
 *        In the tip's frame (x1 ahead, x2 its left normal),
 *        theta > 0 turns towards x2: pure mode II (K_II > 0) gives
 *        -70.53 degrees, K_II < 0 gives +70.53; K_II = 0 gives 0.
 * @return theta_c in radians.
 */
double hoop_angle(double KI, double KII);

#endif
