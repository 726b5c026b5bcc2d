/**
 * @file cohesive_points.c
 * @brief Set-up of the cohesive cracks: the default penalty, the Gauss
 *        points along each segment inside a body, and at each the jump
 *        of the enriched shape functions across the crack (xefg.md 2.1:
 *        [[H]] = 2, [[r^m sin(theta/2)]] = 2 r^m), so that the opening is
 *        [[u]] = sum_q Phi_I [[E_q]] u_q; the standard parameters do not
 *        jump (their Phi_I is continuous).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "branch.h"
#include "cohesive.h"
#include "quadrature.h"

/** The first body holding (px, py) (edges included), or -1. */
static int body_at(const Scene *sc, double px, double py)
{
    for (int b = 0; b < sc->nbodies; b++)
        if (shape_contains(&sc->bodies[b].shape, px, py))
            return b;
    return -1;
}

/** The jump [[E_q]] = E_q(side +1) - E_q(side -1) of enriched parameter
 *  @p q at (px, py) on its crack. */
static double enrichment_jump(const Xefg *x, int q, double px, double py)
{
    CrackLine line = xefg_line_of(x, q);         /* the part it knows */
    double dist;
    crack_line_side(&line, px, py, &dist);
    if (dist > 1e-9 * x->hx[x->dof_node[q]])
        return 0.0;          /* on a later segment: its function is smooth */
    if (x->dof_kind[q] == DOF_STEP)
        return 2.0;                                   /* H = +-1, eq. 3 */
    double Bp[BRANCH_MAX], Bm[BRANCH_MAX];
    const double *tip = x->dof_frame + 4 * q, *dir = tip + 2; /* its tip */
    int np = branch_functions(x->set.tip, x->set.m, tip, dir, 1, px, py, Bp,
                              NULL, NULL);
    int nm = branch_functions(x->set.tip, x->set.m, tip, dir, -1, px, py, Bm,
                              NULL, NULL);
    int b = x->dof_kind[q] - DOF_BRANCH;
    return b < np && b < nm ? Bp[b] - Bm[b] : 0.0;    /* eq. 5-6 */
}

/** Room for @p n more points. */
static int grow_points(Cohesive *c, int n, int *cap)
{
    if (c->npt + n <= *cap)
        return 0;
    *cap = 2 * (c->npt + n);
    double **d[] = {&c->px, &c->py, &c->w, &c->tx, &c->ty};
    for (size_t k = 0; k < sizeof d / sizeof d[0]; k++)
        if (xefg_grow((void **)d[k], sizeof(double), *cap))
            return -1;
    return xefg_grow((void **)&c->crack, sizeof(int), *cap);
}

int cohesive_jump_row(const Xefg *x, const ShapeRows *R, int k, double px,
                      double py, int *dof, double *N)
{
    int j = 0;
    double phi = 0.0;
    for (int e = R->start[R->n - 1]; e < R->start[R->n]; e++) {
        int q = R->dof[e];
        if (x->dof_kind[q] == DOF_STANDARD) {
            phi = R->N[e];              /* Phi_I: the node's entries follow */
            continue;
        }
        if (x->dof_crack[q] != k)
            continue;
        if (dof) {
            dof[j] = q;
            N[j] = phi * enrichment_jump(x, q, px, py);
        }
        j++;
    }
    return j;
}

/** Add the point (px, py) of crack @p k, body @p b, weight @p w and its
 *  jump row (from the row @p R made at the point). @return 0 or -1. */
static int add_point(Cohesive *c, const Xefg *x, const ShapeRows *R, int k,
                     double px, double py, double w, const double t[2],
                     int *cap)
{
    int n = cohesive_jump_row(x, R, k, px, py, NULL, NULL);
    if (grow_points(c, 1, cap) || shape_rows_add(&c->jump, n, 0))
        return -1;
    int j = c->jump.start[c->jump.n - 1];
    cohesive_jump_row(x, R, k, px, py, c->jump.dof + j, c->jump.N + j);
    int p = c->npt++;
    c->crack[p] = k;
    c->px[p] = px;
    c->py[p] = py;
    c->w[p] = w;
    c->tx[p] = t[0];
    c->ty[p] = t[1];
    return 0;
}

/** The part [s0, s1] (arc length) of the segment from @p a along @p t
 *  where (a + s t) lies in a body, found by a walk of steps @p step and
 *  bisection; 0 when it has none from @p from on. */
static int inside_part(const Scene *sc, const double a[2], const double t[2],
                       double len, double from, double step,
                       double *s0, double *s1)
{
    int n = (int)ceil((len - from) / step);
    double prev = from;
    int in = body_at(sc, a[0] + from * t[0], a[1] + from * t[1]) >= 0;
    if (in)
        *s0 = from;
    for (int i = 1; i <= n; i++) {
        double s = fmin(from + i * step, len);
        int now = body_at(sc, a[0] + s * t[0], a[1] + s * t[1]) >= 0;
        if (now != in) {
            double lo = prev, hi = s;              /* the boundary between */
            for (int it = 0; it < 60; it++) {
                double mid = 0.5 * (lo + hi);
                int m = body_at(sc, a[0] + mid * t[0], a[1] + mid * t[1]) >= 0;
                if (m == in)
                    lo = mid;
                else
                    hi = mid;
            }
            if (!in) {
                *s0 = hi;
                in = 1;
            } else {
                *s1 = lo;
                return 1;
            }
        }
        prev = s;
    }
    if (in)
        *s1 = len;
    return in;
}

/// [cohesive_points]
int cohesive_segment_points(Cohesive *c, const Xefg *x, const Sim *sim,
                            const CellList *cl, int k, int g, double h,
                            ShapeRows *R, int *cap, char *err, size_t errlen)
{
    const Scene *sc = &sim->scene;
    const CrackLine *l = &x->crack[k];
    int n = x->set.gauss;
    double xi[GAUSS_MAX], gw[GAUSS_MAX];
    gauss_legendre(n, xi, gw);
    double a[2] = {l->x[g], l->y[g]};
    double len = hypot(l->x[g + 1] - a[0], l->y[g + 1] - a[1]);
    double t[2] = {(l->x[g + 1] - a[0]) / len, (l->y[g + 1] - a[1]) / len};
    double s0 = 0.0, s1 = 0.0;
    while (s1 < len &&
           inside_part(sc, a, t, len, s1, 0.125 * h, &s0, &s1)) {
        int pieces = (int)ceil((s1 - s0) / h);
        double ds = (s1 - s0) / pieces;
        for (int p = 0; p < pieces; p++)
            for (int i = 0; i < n; i++) {
                double s = s0 + ds * (p + 0.5 * (1.0 + xi[i]));
                double px = a[0] + s * t[0], py = a[1] + s * t[1];
                int b = body_at(sc, px, py);
                R->n = R->len = 0;
                int rc = b < 0 ? -1 : xefg_shape_row(x, cl, sim->pts.body,
                                                     b, px, py, 0, R);
                if (rc == -2 || (rc == 0 &&
                    add_point(c, x, R, k, px, py, 0.5 * ds * gw[i] *
                              sc->bodies[b].thickness, t, cap))) {
                    snprintf(err, errlen, "%s: out of memory for the "
                             "cohesive points", sc->file);
                    return -1;
                }
                if (rc) {
                    char at[SCENE_AT_LEN];
                    snprintf(err, errlen, "%s: cohesive: the point (%g, %g) "
                             "of crack %d has no shape functions (%s); "
                             "raise xefg.support",
                             scene_lines_at(sc->lines, sc->file,
                                            c->set[k].line, at, SCENE_AT_LEN),
                             px, py, k, b < 0 ? "in no body" :
                             "too few nodes' supports hold it");
                    return -1;
                }
            }
        s1 += 1e-12 * len;                   /* on past this part */
    }
    return 0;
}

/** The points of crack @p k: each part of a segment inside a body cut in
 *  pieces no longer than @p h, each piece with the Gauss rule of @p n
 *  points; none on its first notch_segments segments (a traction-free
 *  notch, the Petersson beam of chapter 6b). */
static int crack_points(Cohesive *c, const Xefg *x, const Sim *sim,
                        const CellList *cl, int k, double h, ShapeRows *R,
                        int *cap, char *err, size_t errlen)
{
    for (int g = c->set[k].notch; g + 1 < x->crack[k].n; g++)
        if (cohesive_segment_points(c, x, sim, cl, k, g, h, R, cap, err, errlen))
            return -1;
    return 0;
}
/// [cohesive_points]

/** The default penalty K = 10 E' / h (E' = the stiffest body's c11,
 *  h = the point spacing), and its check against f_t^2 / (2 G_f). */
static int penalties(Cohesive *c, const Sim *sim, double h, char *err,
                     size_t errlen)
{
    const Scene *sc = &sim->scene;
    double E = 0.0;
    for (int b = 0; b < sc->nbodies; b++)
        E = fmax(E, sc->mat[sc->bodies[b].material].c11);
    for (int k = 0; k < c->ncrack; k++) {
        CohesiveLaw *L = &c->set[k].law;
        if (!c->set[k].on || L->K > 0.0)
            continue;
        L->K = 10.0 * E / h;
        if (!(L->K > L->f_t * L->f_t / (2.0 * L->G_f))) {
            char at[SCENE_AT_LEN];
            snprintf(err, errlen, "%s: cohesive: the default penalty 10 E / h = "
                     "%g is not above f_t^2 / (2 G_f) = %g: give penalty",
                     scene_lines_at(sc->lines, sc->file, c->set[k].line, at,
                                    SCENE_AT_LEN), L->K,
                     L->f_t * L->f_t / (2.0 * L->G_f));
            return -1;
        }
    }
    return 0;
}

int cohesive_build(Cohesive *c, const Xefg *x, const Sim *sim,
                   const CellList *cl, char *err, size_t errlen)
{
    double h = INFINITY;
    for (int I = 0; I < x->nnode; I++)
        h = fmin(h, 2.0 * fmin(x->hx[I], x->hy[I]));
    if (penalties(c, sim, h, err, errlen))
        return -1;
    ShapeRows R = {0};
    int cap = 0;
    for (int k = 0; k < c->ncrack && k < x->ncrack; k++)
        if (c->set[k].on && crack_points(c, x, sim, cl, k, h, &R, &cap, err, errlen)) {
            shape_rows_free(&R);
            return -1;
        }
    shape_rows_free(&R);
    size_t n = (size_t)(c->npt > 0 ? c->npt : 1);
    double **d[] = {&c->dmax, &c->dn, &c->ds, &c->tn, &c->ts, &c->stored};
    for (size_t k = 0; k < sizeof d / sizeof d[0]; k++)
        if (!(*d[k] = calloc(n, sizeof(double)))) {
            snprintf(err, errlen, "%s: out of memory for the cohesive points",
                     sim->scene.file);
            return -1;
        }
    return 0;
}

void cohesive_free(Cohesive *c)
{
    void *a[] = {c->set, c->crack, c->px, c->py, c->w, c->tx, c->ty, c->dmax,
                 c->dn, c->ds, c->tn, c->ts, c->stored};
    for (size_t k = 0; k < sizeof a / sizeof a[0]; k++)
        free(a[k]);
    shape_rows_free(&c->jump);
    *c = (Cohesive){0};
}
