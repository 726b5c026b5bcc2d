/**
 * @file stage7.c
 * @brief Stage 7 adds fracture parameters: the J-integral, and K_I and
 *        K_II by the interaction integral, at the tips of a crack that
 *        asks for them (cracks.[k].j_integral), and growth of the tips
 *        whose J reaches G_c (cracks.[k].growth). A scene without the
 *        keys subscribes nothing and runs as on stage 6.
 */
#include "stage7.h"

#include "crack_growth.h"
#include "j_integral.h"

/// [stage7_install]
void stage7_install(Hooks *h)
{
    hooks_add_key(h, "cracks", "j_integral", j_integral_read, j_integral_keys);
    hooks_add_key(h, "cracks", "growth", crack_growth_read, crack_growth_keys);
}
/// [stage7_install]
