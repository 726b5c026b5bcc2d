/**
 * @file stage7.c
 * @brief Stage 7 adds fracture parameters: the J-integral, and K_I and
 *        K_II by the interaction integral, at the tips of a crack that
 *        asks for them (cracks.[k].j_integral). A scene without the key
 *        subscribes nothing and runs as on stage 6.
 */
#include "stage7.h"

#include "j_integral.h"

/// [stage7_install]
void stage7_install(Hooks *h)
{
    hooks_add_key(h, "cracks", "j_integral", j_integral_read, j_integral_keys);
}
/// [stage7_install]
