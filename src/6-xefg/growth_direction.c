/**
 * @file growth_direction.c
 * @brief Where a tip grows under direction = "hoop" (our choice, the
 *        paper's criterion is beyond our transcript): K_I and K_II by the
 *        interaction integral at the tip, and the angle of largest hoop
 *        stress (Erdogan and Sih 1963) from them, as chapter 7b's CRAMP
 *        cracks turn.
 */
#include <math.h>

#include "growth.h"
#include "hoop_angle.h"
#include "interaction_integral.h"

/// [growth_hoop_direction]
int growth_hoop_direction(const Sim *sim, const Growth *g, int c, int end,
                          const double ahead[2], double K[2], double dir[2])
{
    if (xefg_stress_intensity(sim, c, end, g->k_radius, K))
        return -1;
    /* faces cannot pass through each other: K_I < 0 counts as 0, and the
     * kink is then K_II's alone, |theta| <= 70.53 degrees (chapter 7b) */
    double theta = hoop_angle(K[0] > 0.0 ? K[0] : 0.0, K[1]);
    /* theta turns from ahead (the tip frame's x1) towards its left
     * normal (x2), the frame of xefg_stress_intensity() */
    double c_t = cos(theta), s_t = sin(theta);
    dir[0] = c_t * ahead[0] - s_t * ahead[1];
    dir[1] = s_t * ahead[0] + c_t * ahead[1];
    return 0;
}
/// [growth_hoop_direction]
