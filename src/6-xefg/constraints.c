/**
 * @file constraints.c
 * @brief Essential boundary conditions on MLS by Lagrange multipliers on
 *        the velocities (xefg.md 2.6, pitfall 8: the shape functions have
 *        no Kronecker delta, so holding a parameter does not hold the
 *        material). Each held place c asks v(X_c) = sum_q psi_q(X_c) v_q
 *        = vbar_c; with G the rows psi(X_c), the velocities closest to
 *        the free ones in the kinetic-energy norm are
 *        v - M^-1 G^T (G M^-1 G^T)^-1 (G v - vbar).
 *        G M^-1 G^T is factored once (LAPACKE, Cholesky).
 */
#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "grid.h"
#include "xefg.h"

/** Most places held in one direction (the dense factor is n x n). */
#define HELD_MAX 4000

/** Hold node @p nd in direction @p k by @p h, unless it is held already. */
static int add_place(Constraints *c, int nd, const Hold *h, int *cap)
{
    for (int j = 0; j < c->n; j++)
        if (c->node[j] == nd) {
            c->hold[j] = h;               /* the later entry wins */
            return 0;
        }
    if (c->n == *cap) {
        *cap = *cap ? 2 * *cap : 64;
        int *a = realloc(c->node, sizeof(int) * (size_t)*cap);
        if (a)
            c->node = a;
        const Hold **b = realloc(c->hold, sizeof(Hold *) * (size_t)*cap);
        if (b)
            c->hold = b;
        if (!a || !b)
            return -1;
    }
    c->node[c->n] = nd;
    c->hold[c->n++] = h;
    return 0;
}

/** The places of direction @p k: nodes inside a boundary's box that holds
 *  k, and the held points (point_velocities) that hold k. */
static int collect(Xefg *x, const Sim *sim, int k)
{
    const Scene *sc = &sim->scene;
    unsigned bit = k == 0 ? GRID_FIX_X : GRID_FIX_Y;
    Constraints *c = &x->fix[k];
    int cap = 0;
    for (int b = 0; b < sc->nbc; b++) {
        const Boundary *B = &sc->bc[b];
        if (!(B->hold.fix & bit))
            continue;
        for (int nd = 0; nd < x->nnode; nd++)
            if (shape_contains(&B->region, x->X[nd], x->Y[nd]) &&
                add_place(c, nd, &B->hold, &cap))
                return -1;
    }
    for (int h = 0; h < sc->nheld; h++) {
        const HeldPoints *H = &sc->held[h];
        if (!(H->hold.fix & bit))
            continue;
        for (int j = 0; j < H->count; j++)
            if (add_place(c, H->points[j], &H->hold, &cap))
                return -1;
    }
    return 0;
}

int xefg_constraints_factor(const Xefg *x, Constraints *c, double *w)
{
    size_t n = (size_t)c->n;
    const ShapeRows *G = &c->rows;
    for (int a = 0; a < c->n; a++) {         /* w: M^-1 G^T, a row at a time */
        for (int e = G->start[a]; e < G->start[a + 1]; e++)
            w[G->dof[e]] = G->N[e] / x->mass[G->dof[e]];
        for (int b = 0; b < c->n; b++) {
            double s = 0.0;
            for (int e = G->start[b]; e < G->start[b + 1]; e++)
                s += w[G->dof[e]] * G->N[e];
            c->S[(size_t)b * n + (size_t)a] = s;     /* column-major */
        }
        for (int e = G->start[a]; e < G->start[a + 1]; e++)
            w[G->dof[e]] = 0.0;
    }
    /* the lower factor, column-major, as xefg_constraints_apply() solves
       with it: the _work calls allocate nothing (LAPACKE_dpotrs with
       LAPACK_ROW_MAJOR allocated a transposed copy at every step) */
    return LAPACKE_dpotrf_work(LAPACK_COL_MAJOR, 'L', c->n, c->S, c->n) ? -1 : 0;
}

/** Room for S and r of direction @p k, then S and its factor. @return 0,
 *  -1 (not positive definite) or -2 (out of memory). */
static int factor(Xefg *x, Constraints *c)
{
    size_t n = (size_t)c->n;
    double *w = calloc((size_t)x->ndof, sizeof(double));
    c->S = malloc(sizeof(double) * n * n);
    c->r = malloc(sizeof(double) * n);
    if (!w || !c->S || !c->r) {
        free(w);
        return -2;
    }
    int rc = xefg_constraints_factor(x, c, w);
    free(w);
    return rc;
}

int xefg_constraints_build(Xefg *x, const Sim *sim, const CellList *cl,
                           const int *body_of, char *err, size_t errlen)
{
    (void)cl, (void)body_of;
    for (int k = 0; k < 2; k++) {
        Constraints *c = &x->fix[k];
        if (collect(x, sim, k))
            goto oom;
        if (c->n == 0)
            continue;
        if (c->n > HELD_MAX) {
            snprintf(err, errlen, "%s: %d nodes are held along %c, more than "
                     "the %d the XEFG method's dense constraint solve takes",
                     sim->scene.file, c->n, "xy"[k], HELD_MAX);
            return -1;
        }
        for (int j = 0; j < c->n; j++) {       /* G: the nodes' own rows */
            const ShapeRows *A = &x->at_node;
            int nd = c->node[j], len = A->start[nd + 1] - A->start[nd];
            if (shape_rows_add(&c->rows, len, 0))
                goto oom;
            memcpy(c->rows.dof + c->rows.start[j], A->dof + A->start[nd],
                   sizeof(int) * (size_t)len);
            memcpy(c->rows.N + c->rows.start[j], A->N + A->start[nd],
                   sizeof(double) * (size_t)len);
        }
        int rc = factor(x, c);
        if (rc == -2)
            goto oom;
        if (rc) {
            snprintf(err, errlen, "%s: the %d places held along %c give "
                     "dependent constraints (G M^-1 G^T is singular): hold "
                     "fewer points, or points farther apart", sim->scene.file,
                     c->n, "xy"[k]);
            return -1;
        }
    }
    return 0;
oom:
    snprintf(err, errlen, "%s: out of memory for the held places",
             sim->scene.file);
    return -1;
}

/// [xefg_constraints_apply]
void xefg_constraints_apply(Xefg *x, double t)
{
    for (int k = 0; k < 2; k++) {
        Constraints *c = &x->fix[k];
        if (c->n == 0)
            continue;
        const ShapeRows *G = &c->rows;
        for (int a = 0; a < c->n; a++) {          /* r = G v - vbar */
            double v[2], s = 0.0;
            hold_velocity(c->hold[a], t, v);
            for (int e = G->start[a]; e < G->start[a + 1]; e++)
                s += G->N[e] * x->v[2 * G->dof[e] + k];
            c->r[a] = s - v[k];
        }
        LAPACKE_dpotrs_work(LAPACK_COL_MAJOR, 'L', c->n, 1, c->S, c->n, c->r, c->n);
        if (x->coh)          /* the work of the held places (a cohesive */
            for (int a = 0; a < c->n; a++) {  /* crack's energy balance): */
                double v[2];                  /* impulse -lambda times the */
                hold_velocity(c->hold[a], t, v);    /* held velocity */
                x->w_held -= c->r[a] * v[k];
            }
        for (int a = 0; a < c->n; a++)            /* v -= M^-1 G^T lambda */
            for (int e = G->start[a]; e < G->start[a + 1]; e++) {
                int q = G->dof[e];
                x->v[2 * q + k] -= G->N[e] * c->r[a] / x->mass[q];
            }
    }
}
/// [xefg_constraints_apply]
