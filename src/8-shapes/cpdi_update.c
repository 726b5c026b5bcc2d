/**
 * @file cpdi_update.c
 * @brief The deformation gradient that carries each CPDI domain: F = I at
 *        set-up, F <- (I + dt L) F at Task 7 from the same nodal
 *        velocities and gradients as the step's strain, and a stop naming
 *        the step and the point when a domain inverts, grows wider than a
 *        cell, or leaves the grid.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "checkpoint.h"
#include "cpdi.h"
#include "gimp.h"
#include "step.h"

/** Why the domain of point @p p (half sides @p r1, @p r2 at its current
 *  position) cannot be used, or NULL; *@p value: det F (the
 *  area over the initial one) when inverted, the width in cells when too
 *  wide, the position when off the grid. */
static const char *domain_fault(const Sim *sim, int p, const double r1[2],
                                const double r2[2], double *value)
{
    const Grid *g = &sim->grid;
    double area = r1[0] * r2[1] - r1[1] * r2[0];
    double ex = fabs(r1[0]) + fabs(r2[0]), ey = fabs(r1[1]) + fabs(r2[1]);
    double x = sim->pts.x[p], y = sim->pts.y[p];
    double xmax = g->ox + g->ncx * g->dx, ymax = g->oy + g->ncy * g->dy;
    double l = gimp_half(sim, p);
    if (!(area > 0.0)) {
        *value = area / (l * g->dx * l * g->dy);   /* det F */
        return "CPDI domain (inverted: det F)";
    }
    if (!(2.0 * ex < g->dx && 2.0 * ey < g->dy)) {
        *value = fmax(2.0 * ex * g->idx, 2.0 * ey * g->idy);
        return "CPDI domain (wider than a cell: cells)";
    }
    if (!(x - ex >= g->ox && x + ex <= xmax)) {
        *value = x;
        return "CPDI domain x (left the grid)";
    }
    if (!(y - ey >= g->oy && y + ey <= ymax)) {
        *value = y;
        return "CPDI domain y (left the grid)";
    }
    return NULL;
}

/// [cpdi_update]
/** Task 7: F <- (I + dt L) F, L = sum_i v_i (x) G_ip over the domain the
 *  step used; then the checks. */
static int cpdi_update(Sim *sim, void *state, Seam seam)
{
    Cpdi *C = state;
    const Grid *g = &sim->grid;
    int rc = 0;
    (void)seam;
    for (int p = 0; p < sim->pts.n; p++) {
        StencilRow st = stencil_row(stencil_stored_wide(sim, p)); /* Task 0's */
        double L[4];                             /* xx, xy, yx, yy */
        row_velocity_gradient(g, &st, st.n, L);
        double *F = &C->F[4 * p], dt = sim->dt, f[4];
        f[0] = F[0] + dt * (L[0] * F[0] + L[1] * F[2]);
        f[1] = F[1] + dt * (L[0] * F[1] + L[1] * F[3]);
        f[2] = F[2] + dt * (L[2] * F[0] + L[3] * F[2]);
        f[3] = F[3] + dt * (L[2] * F[1] + L[3] * F[3]);
        for (int k = 0; k < 4; k++)
            F[k] = f[k];
        double r1[2], r2[2], value;
        cpdi_vectors(sim, C, p, r1, r2);
        const char *why = domain_fault(sim, p, r1, r2, &value);
        if (why)
            rc = step_fail(sim, p, why, value);
    }
    return rc;
}
/// [cpdi_update]

/** Save or restore the deformation gradients. */
static int cpdi_checkpoint(Sim *sim, void *state, FILE *f, int save)
{
    Cpdi *C = state;
    (void)sim;
    return checkpoint_io(f, C->F, sizeof(double) * 4 * (size_t)C->n, save);
}

static void cpdi_release(void *state)
{
    Cpdi *C = state;
    free(C->F);
    free(C);
}

int cpdi_prepare(Sim *sim, char *err, size_t errlen)
{
    const char *file = sim->scene.file;
    int n = sim->pts.n;
    Cpdi *C = calloc(1, sizeof *C);
    if (C)
        C->F = calloc(4 * (size_t)(n > 0 ? n : 1), sizeof(double));
    if (!C || !C->F || sim_attach(sim, CPDI_STATE, C, cpdi_release)) {
        if (C)
            free(C->F);
        free(C);
        snprintf(err, errlen, "%s: out of memory (CPDI domains)", file);
        return -1;
    }
    C->n = n;
    for (int p = 0; p < n; p++) {
        C->F[4 * p] = C->F[4 * p + 3] = 1.0;
        double r1[2], r2[2], value;
        cpdi_vectors(sim, C, p, r1, r2);
        const char *why = domain_fault(sim, p, r1, r2, &value);
        if (why) {
            snprintf(err, errlen, "%s: run.shape = \"cpdi\": point %d at (%g, %g): "
                     "%s; add a cell of margin", file, p, sim->pts.x[p],
                     sim->pts.y[p], why);
            return -1;
        }
    }
    if (hooks_on_step(&sim->hooks, SEAM_TASK7, cpdi_update, C) ||
        hooks_on_checkpoint(&sim->hooks, cpdi_checkpoint, C)) {
        snprintf(err, errlen, "%s: too many step hooks", file);
        return -1;
    }
    return 0;
}
