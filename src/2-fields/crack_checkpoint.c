/**
 * @file crack_checkpoint.c
 * @brief The cracks in a checkpoint: their points move with the body
 *        (Task 7), so a restart takes them from the checkpoint. A later
 *        stage may have added points (chapter 7's growth): a crack is
 *        restored with as many as it had, never fewer than the scene's.
 */
#include "checkpoint.h"
#include "cracks.h"

/** Points a restored crack may have: a guard against a damaged file. */
#define RESTORED_POINTS_MAX 100000000

int cracks_checkpoint(Sim *sim, void *state, FILE *f, int save)
{
    Cracks *C = state;
    int n = C->ncracks;
    if (checkpoint_io(f, &n, sizeof n, save) || n != C->ncracks)
        return -1;
    for (int k = 0; k < C->ncracks; k++) {
        Crack *c = &C->crack[k];
        int np = c->n;
        if (checkpoint_io(f, &np, sizeof np, save) || np < c->n ||
            np > RESTORED_POINTS_MAX)
            return -1;
        if (np > c->n) {                 /* it grew: a later stage that
                                            reserves room does so again */
            if (crack_reserve_points(c, np))
                return -1;
            c->n = np;
        }
        if (checkpoint_io(f, c->x, (size_t)np * sizeof(double), save) ||
            checkpoint_io(f, c->y, (size_t)np * sizeof(double), save))
            return -1;
        crack_extent(c);
    }
    /* the search's cells follow the restored points */
    return save || !C->search->update ? 0 : C->search->update(C, &sim->grid);
}
