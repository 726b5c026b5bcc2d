/**
 * @file stage5.c
 * @brief Stage 5 adds USAVG, the paper's averaged stress update: half an
 *        update at Task 2 (as USF) and half after re-extrapolation at
 *        Task 6 (as MUSL), section 2.3.
 */
#include "stage5.h"

#include "energy_balance.h"
#include "usavg_scheme.h"

/// [stage5_install]
void stage5_install(Hooks *h)
{
    UpdateScheme u = usavg_scheme();             /* Nairn 2003, Task 6 */
    hooks_add_scheme(h, u.name, u.before, u.after, u.reextrapolate);
    energy_balance_install(h);                   /* in = stored + lost */
}
/// [stage5_install]
