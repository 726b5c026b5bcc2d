/**
 * @file growth_insert.c
 * @brief One growth event: the crack's line gains a point, and what the
 *        new segment touches is brought up to date (growth_add_parameters.c,
 *        growth_rows.c, growth_cohesive.c), the held places whose rows
 *        gained parameters, and the stable step.
 */
#include <math.h>
#include <string.h>

#include "cohesive.h"
#include "cracks.h"
#include "growth.h"

/** Is (px, py) inside a body with a margin all round (a tip), as
 *  xefg_build.c decides it? */
static int inside_a_body(const Scene *sc, double px, double py)
{
    double eps = 1e-9 * fmin(sc->dx, sc->dy);
    for (int b = 0; b < sc->nbodies; b++) {
        const Shape *s = &sc->bodies[b].shape;
        if (shape_contains(s, px - eps, py - eps) &&
            shape_contains(s, px + eps, py - eps) &&
            shape_contains(s, px - eps, py + eps) &&
            shape_contains(s, px + eps, py + eps))
            return 1;
    }
    return 0;
}

/// [growth_constraints]
/** The held places whose nodes' rows gained parameters: their rows of G
 *  again (the nodes' own rows, constraints.c) and G M^-1 G^T assembled and
 *  factored again, in the room kept at set-up. @return 0 or -1. */
static int constraints_update(Xefg *x, Growth *g, int c, char *err,
                              size_t errlen)
{
    const ShapeRows *A = &x->at_node;
    for (int k = 0; k < 2; k++) {
        Constraints *C = &x->fix[k];
        int changed = 0;
        for (int j = 0; j < C->n; j++) {
            int nd = C->node[j];
            g->len[j] = A->start[nd + 1] - A->start[nd];
            changed |= g->len[j] != C->rows.start[j + 1] - C->rows.start[j];
        }
        if (!changed)
            continue;
        if (growth_rows_expand(&C->rows, g->len, 0)) {
            snprintf(err, errlen, "growth of crack %d stopped: the rows of the "
                     "places held along %c reserved at set-up are full", c,
                     "xy"[k]);
            return -1;
        }
        for (int j = 0; j < C->n; j++)
            growth_copy_row(&C->rows, j, A, C->node[j]);
        double *w = g->diag;                    /* scratch, zero on entry */
        for (int q = 0; q < x->ndof; q++)
            w[q] = 0.0;
        if (xefg_constraints_factor(x, C, w)) {
            snprintf(err, errlen, "growth of crack %d stopped: the places held "
                     "along %c give dependent constraints with the new "
                     "parameters", c, "xy"[k]);
            return -1;
        }
    }
    return 0;
}
/// [growth_constraints]

/// [growth_stable_step]
/** The stable step again, by the power iteration in the room kept for it
 *  (about as many iterations as at set-up, each the work of a step); a
 *  lower step lowers the run's step for the rest of the run. Our first
 *  rule, to run it only when a new parameter is lighter relative to its
 *  node than any before, missed a fall of 10 % (scene_xefg_growth.c):
 *  the node's step and branch functions of the old and new tips are near
 *  each other, and their coupling, not the lumped mass, set it. */
static int stable_step(Sim *sim, Xefg *x, Growth *g, char *err, size_t errlen)
{
    g->power_runs++;
    if (xefg_power_iteration_in(x, sim, g->zs, g->kzs, g->gss)) {
        snprintf(err, errlen, "growth: the power iteration gave no finite "
                 "frequency (highest %g)", x->omega_max);
        return -1;
    }
    double dt = sim->scene.run.cfl * x->stable_step;
    if (dt < sim->dt) {                      /* the rest of the run, finer */
        sim->dt = dt;
        sim->nsteps = sim->step +
                      (long)ceil((sim->scene.run.time - sim->t) / dt - 1e-9);
    }
    return 0;
}
/// [growth_stable_step]

/// [growth_insert]
int growth_insert(Sim *sim, Xefg *x, Growth *g, int c, int end, double px,
                  double py, char *err, size_t errlen)
{
    CrackLine *l = &x->crack[c];
    Crack *ck = &cracks_of(sim)->crack[c];
    if (l->n >= g->point_cap[c]) {
        char at[SCENE_AT_LEN];
        snprintf(err, errlen, "growth of crack %d stopped: max_segments = %d "
                 "segments added (%s), all the room reserved at set-up: raise "
                 "max_segments", c,
                 g->set[c].max_segments,
                 scene_lines_at(sim->scene.lines, sim->scene.file,
                                g->set[c].line, at, SCENE_AT_LEN));
        return -1;
    }
    double a[2], dir[2], b[2] = {px, py};
    x->rows_version++;                       /* the gather is stale */
    crack_line_tip(l, end, a, dir);
    if (end == 1) {                          /* the line, one point longer */
        ck->x[ck->n] = px;
        ck->y[ck->n] = py;
    } else {
        memmove(ck->x + 1, ck->x, sizeof(double) * (size_t)ck->n);
        memmove(ck->y + 1, ck->y, sizeof(double) * (size_t)ck->n);
        ck->x[0] = px;
        ck->y[0] = py;
        for (int q = 0; q < x->ndof; q++)     /* their points moved up one */
            if (x->dof_crack[q] == c)
                x->dof_line[2 * q]++;
    }
    ck->n++;
    l->n = ck->n;
    crack_extent(ck);
    /* a segment that leaves the body ends the growth of that end: the
     * crack cuts through, and that end is a mouth */
    l->tip[end] = inside_a_body(&sim->scene, px, py);
    int seg = end == 1 ? l->n - 2 : 0;
    if (growth_add_parameters(x, g, c, a, b, err, errlen) < 0 ||
        growth_rows(sim, x, g, c, a, b, err, errlen) ||
        growth_cohesive(sim, x, g, c, seg, a, b, err, errlen) ||
        constraints_update(x, g, c, err, errlen) ||
        stable_step(sim, x, g, err, errlen))
        return -1;
    /* the bulk's stress acts on the new parameters at once: a(t) again
     * (with the new segment closed, its traction is zero) */
    xefg_accelerations(x, sim, sim->t);
    xefg_to_points(x, sim);
    return 0;
}
/// [growth_insert]
