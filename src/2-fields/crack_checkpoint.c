/**
 * @file crack_checkpoint.c
 * @brief The cracks in a checkpoint: their points move with the body
 *        (Task 7), so a restart takes them from the checkpoint.
 */
#include "checkpoint.h"
#include "cracks.h"

int cracks_checkpoint(Sim *sim, void *state, FILE *f, int save)
{
    Cracks *C = state;
    int n = C->ncracks;
    if (checkpoint_io(f, &n, sizeof n, save) || n != C->ncracks)
        return -1;
    for (int k = 0; k < C->ncracks; k++) {
        Crack *c = &C->crack[k];
        int np = c->n;
        if (checkpoint_io(f, &np, sizeof np, save) || np != c->n ||
            checkpoint_io(f, c->x, (size_t)np * sizeof(double), save) ||
            checkpoint_io(f, c->y, (size_t)np * sizeof(double), save))
            return -1;
        crack_extent(c);
    }
    /* the search's cells follow the restored points */
    return save || !C->search->update ? 0 : C->search->update(C, &sim->grid);
}
