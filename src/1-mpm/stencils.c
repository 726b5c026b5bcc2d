/**
 * @file stencils.c
 * @brief The stencils of a step, computed once at Task 0 (stencils.h).
 */
#include "stencils.h"

#include <stdlib.h>
#include <string.h>

#include "stencil.h"

int stencils_init(Sim *sim)
{
    Stencils *T = &sim->stencils;
    size_t np = (size_t)sim->pts.n;
    stencils_free(T);
    if (sim->scene.run.method->step != sim_step || np == 0)
        return 0;                   /* a method with a step of its own */
    if (sim->scene.run.stencil)     /* another row of run.shape */
        T->wide = calloc(np, sizeof *T->wide);
    else
        T->linear = calloc(np, sizeof *T->linear);
    if (!T->wide && !T->linear)
        return -1;
    T->npoints = sim->pts.n;
    return 0;
}

/// [stencils_fill]
void stencils_fill(Sim *sim)
{
    Stencils *T = &sim->stencils;
    const Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    StencilFn wide = sim->scene.run.stencil;
    if (T->npoints != P->n || T->npoints == 0)
        return;                         /* set-up: not allocated yet */
    /* a point writes only its own stencil: any number of threads */
    if (T->wide) {                      /* another row of run.shape */
#pragma omp parallel for num_threads(sim->threads)
        for (int p = 0; p < P->n; p++)
            wide(sim, p, &T->wide[p]);
        return;
    }
#pragma omp parallel for num_threads(sim->threads)
    for (int p = 0; p < P->n; p++) {    /* the paper's four nodes */
        Stencil4 *r = &T->linear[p];
        shape_linear(P->xi[p], P->eta[p], g->idx, g->idy, r->S, r->Gx, r->Gy);
        shape_cell_nodes(g, P->cell[p], r->slot);
    }
}
/// [stencils_fill]

/// [stencils_fields]
void stencils_fields(Sim *sim)
{
    const FieldTable *F = &sim->fields;
    Stencils *T = &sim->stencils;
    if (T->npoints == 0)
        return;
    for (int r = 0; r < F->nrows; r++) {   /* the points with keyed pairs */
        int p = F->row_point[r];
        const int *slot = &F->row_slot[F->width * r];
        if (T->wide)
            memcpy(T->wide[p].slot, slot, sizeof(int) * (size_t)T->wide[p].n);
        else
            memcpy(T->linear[p].slot, slot, sizeof(int) * STENCIL_NODES);
    }
}
/// [stencils_fields]

void stencils_free(Stencils *T)
{
    free(T->linear);
    free(T->wide);
    memset(T, 0, sizeof *T);
}
