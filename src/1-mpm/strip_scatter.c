/**
 * @file strip_scatter.c
 * @brief The loop of a scatter on threads by strips (strip_scatter.h).
 */
#include "strip_scatter.h"

#include "sim.h"

/// [strip_scatter]
void strip_scatter(Sim *sim, StripPointFn fn, void *ctx)
{
    const Strips *S = &sim->strips;
#pragma omp parallel for num_threads(sim->threads) schedule(static, 1)
    for (int t = 0; t < S->n; t++) {
        Owned own = {S->first_node[t], S->first_node[t + 1]};
        for (int k = S->start[t]; k < S->start[t + 1]; k++) {
            int p = S->list[k];         /* increasing within the strip */
            fn(sim, ctx, p, S->row_strips[S->code[p]] & 1 ? &own : NULL);
        }
    }
}
/// [strip_scatter]
