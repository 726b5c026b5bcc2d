/**
 * @file stage5.c
 * @brief Stage 5 adds USAVG, the paper's averaged stress update: half an
 *        update at Task 2 (as USF) and half after re-extrapolation at
 *        Task 6 (as MUSL), section 2.3.
 */
#include "stage5.h"

#include "energy_balance.h"

/// [stage5_install]
void stage5_install(Hooks *h)
{
    /* name, dt share at Task 2, dt share at Task 6, re-extrapolate */
    hooks_add_scheme(h, "usavg", 0.5, 0.5, 1);   /* Nairn 2003, Task 6 */
    energy_balance_install(h);                   /* in = stored + lost */
}
/// [stage5_install]
