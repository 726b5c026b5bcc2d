/**
 * @file stage8.c
 * @brief Stage 8 adds a row to the table of shape functions: uGIMP
 *        (Bardenhagen & Kober 2004).
 */
#include "stage8.h"

#include "gimp.h"
#include "gimp_check.h"

/// [stage8_install]
void stage8_install(Hooks *h)
{
    hooks_add_choice(h, "run.shape", "gimp", &shape_gimp);
    hooks_on_prepare(h, gimp_prepare, NULL);     /* checks gimp scenes only */
}
/// [stage8_install]
