/**
 * @file locate.c
 * @brief Task 0: find every point's cell and stencil before the step
 *        begins.
 */
#include "shape.h"
#include "step.h"

/// [locate_points]
void locate_points(Sim *sim)
{
    Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    /* a point writes only its own arrays: any number of threads */
#pragma omp parallel for num_threads(sim->threads)
    for (int p = 0; p < P->n; p++)
        P->cell[p] = shape_locate(g, P->x[p], P->y[p], &P->xi[p], &P->eta[p]);
    stencils_fill(sim); /* every point's stencil, once for the step */
    strips_bin(sim);    /* the points of each thread's nodes (strips.h) */
}
/// [locate_points]
