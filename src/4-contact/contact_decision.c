/**
 * @file contact_decision.c
 * @brief The per-node contact decision: storage and checkpoint.
 */
#include <stdlib.h>

#include "checkpoint.h"
#include "contact_decision.h"

int contact_decision_alloc(ContactDecision *d, int nnodes)
{
    d->nnodes = nnodes;
    d->pairs = calloc((size_t)nnodes, sizeof(unsigned));
    d->step = malloc((size_t)nnodes * sizeof(long));
    if (!d->pairs || !d->step)
        return -1;
    for (int n = 0; n < nnodes; n++)
        d->step[n] = -1;
    return 0;
}

void contact_decision_free(ContactDecision *d)
{
    free(d->pairs);
    free(d->step);
    d->pairs = NULL;
    d->step = NULL;
}

int contact_decision_checkpoint(ContactDecision *d, FILE *f, int save)
{
    size_t n = (size_t)d->nnodes;
    return checkpoint_io(f, d->pairs, n * sizeof(unsigned), save) ||
           checkpoint_io(f, d->step, n * sizeof(long), save) ? -1 : 0;
}
