/**
 * @file growth_rows.c
 * @brief What a new segment changes in the quadrature (xefg.md 2.6): the
 *        cells it cuts are split along it and get new Gauss points; every
 *        place within 2 d of it may lie in the support of a node that
 *        gained a parameter, or on the other side of the longer crack, so
 *        its row is made again; nothing farther is touched. Then the rows
 *        at the nodes, and the lumped masses of the new parameters
 *        (section 2.5, as xefg_build.c lumps them).
 */
#include <math.h>
#include <string.h>

#include "growth.h"

/** Does the segment from @p a to @p b meet the cell of node @p I? */
static int cuts_cell(const Xefg *x, int I, const double a[2], const double b[2])
{
    double x0 = x->X[I] - x->hx[I], x1 = x->X[I] + x->hx[I];
    double y0 = x->Y[I] - x->hy[I], y1 = x->Y[I] + x->hy[I];
    double tol = 1e-12 * (x1 - x0 + y1 - y0);
    if (fmax(a[0], b[0]) < x0 - tol || fmin(a[0], b[0]) > x1 + tol ||
        fmax(a[1], b[1]) < y0 - tol || fmin(a[1], b[1]) > y1 + tol)
        return 0;
    double dx = b[0] - a[0], dy = b[1] - a[1];
    double cx[4] = {x0, x1, x1, x0}, cy[4] = {y0, y0, y1, y1};
    int pos = 0, neg = 0;
    for (int k = 0; k < 4; k++) {
        double s = dx * (cy[k] - a[1]) - dy * (cx[k] - a[0]);
        pos += s > tol * hypot(dx, dy);
        neg += s < -tol * hypot(dx, dy);
    }
    return pos < 4 && neg < 4;
}

/** The full message. */
static int full(char *err, size_t errlen, int c, const char *what)
{
    snprintf(err, errlen, "growth of crack %d stopped: the %s reserved at "
             "set-up are full", c, what);
    return -1;
}

/** Append Gauss point (px, py) of weight @p w in the cell of node @p I
 *  with its row; its state is the caller's. @return its index or -1. */
static int append_point(Xefg *x, Growth *g, const Sim *sim, int I, double px,
                        double py, double w)
{
    ShapeRows *R = &x->gauss;
    if (x->ngauss + 1 > g->gauss_cap || R->n + 1 > R->ncap ||
        R->cap - R->len < ROW_ROOM)
        return -1;
    if (xefg_shape_row(x, &g->cl, sim->pts.body, sim->pts.body[I], px, py, 1,
                       R))
        return -1;
    int p = x->ngauss++;
    x->gx[p] = px;
    x->gy[p] = py;
    x->gw[p] = w;
    x->gnode[p] = I;
    return p;
}

/** grad u at Gauss point @p p (from its row): u_x,x u_x,y u_y,x u_y,y. */
static void grad_u(const Xefg *x, int p, double G[4])
{
    const ShapeRows *R = &x->gauss;
    G[0] = G[1] = G[2] = G[3] = 0.0;
    for (int e = R->start[p]; e < R->start[p + 1]; e++) {
        int q = R->dof[e];
        G[0] += x->u[2 * q] * R->Nx[e];
        G[1] += x->u[2 * q] * R->Ny[e];
        G[2] += x->u[2 * q + 1] * R->Nx[e];
        G[3] += x->u[2 * q + 1] * R->Ny[e];
    }
}

/** The state of new point @p p from the old point @p o of its cell: its
 *  stress and strain, then the law's response to the difference of the
 *  strain of the displacement field at the two (exact for linear
 *  elasticity: the stress of the field at p). */
static void carry_state(Xefg *x, const Sim *sim, int p, int o)
{
    double Gp[4], Go[4];
    grad_u(x, p, Gp);
    grad_u(x, o, Go);
    double dxx = Gp[0] - Go[0], dyy = Gp[3] - Go[3];
    double dxy = 0.5 * (Gp[1] + Gp[2] - Go[1] - Go[2]);
    memcpy(x->gs + 3 * p, x->gs + 3 * o, 3 * sizeof(double));
    x->ge[3 * p] = x->ge[3 * o] + dxx;
    x->ge[3 * p + 1] = x->ge[3 * o + 1] + dyy;
    x->ge[3 * p + 2] = x->ge[3 * o + 2] + dxy;
    const Material *m = &sim->scene.mat[sim->pts.mat[x->gnode[p]]];
    m->law->stress(m, dxx, dyy, dxy, x->gs + 3 * p);
}

/** The old point of cell @p I (mark 2) nearest to Gauss point @p p on its
 *  side of crack @p c (on no side: the nearest). */
static int nearest_old(const Xefg *x, const Growth *g, int ng0, int I, int c,
                       int p)
{
    const CrackLine *l = &x->crack[c];
    int side = crack_line_side(l, x->gx[p], x->gy[p], NULL), best = -1, any = -1;
    double db = INFINITY, da = INFINITY;
    side = side ? side : 1;
    for (int o = 0; o < ng0; o++) {
        if (g->mark[o] != 2 || x->gnode[o] != I)
            continue;
        double d = hypot(x->gx[o] - x->gx[p], x->gy[o] - x->gy[p]);
        if (d < da)
            da = d, any = o;
        int s = crack_line_side(l, x->gx[o], x->gy[o], NULL);
        if ((s ? s : 1) == side && d < db)
            db = d, best = o;
    }
    return best >= 0 ? best : any;
}

/** Drop the old points marked 2 or 3 (their replacements are appended);
 *  @return the index of the first appended point after it. */
static int compact(Xefg *x, Growth *g, int ng0)
{
    ShapeRows *R = &x->gauss;
    int w = 0, ew = 0, first = 0;
    for (int p = 0; p < x->ngauss; p++) {
        int s0 = R->start[p], s1 = R->start[p + 1];
        if (p < ng0 && g->mark[p] >= 2)
            continue;
        if (p == ng0)
            first = w;
        x->gx[w] = x->gx[p];
        x->gy[w] = x->gy[p];
        x->gw[w] = x->gw[p];
        x->gnode[w] = x->gnode[p];
        memmove(x->gs + 3 * w, x->gs + 3 * p, 3 * sizeof(double));
        memmove(x->ge + 3 * w, x->ge + 3 * p, 3 * sizeof(double));
        int n = s1 - s0;
        memmove(R->dof + ew, R->dof + s0, sizeof(int) * (size_t)n);
        memmove(R->N + ew, R->N + s0, sizeof(double) * (size_t)n);
        memmove(R->Nx + ew, R->Nx + s0, sizeof(double) * (size_t)n);
        memmove(R->Ny + ew, R->Ny + s0, sizeof(double) * (size_t)n);
        R->start[w] = ew;
        ew += n;
        w++;
    }
    if (ng0 == x->ngauss)
        first = w;
    R->start[w] = ew;
    R->n = x->ngauss = w;
    R->len = ew;
    return first;
}

/// [growth_gauss]
/** The Gauss points: the cells the segment cuts split anew, the rows of
 *  the points within @p reach of it made again. @return the index of the
 *  first point made again (they are last), or -1. */
static int gauss_points(Sim *sim, Xefg *x, Growth *g, int c, const double a[2],
                        const double b[2], double reach, char *err,
                        size_t errlen)
{
    int ng0 = x->ngauss, *cut = g->shift;    /* per node: its cell is cut */
    for (int I = 0; I < x->nnode; I++)
        cut[I] = cuts_cell(x, I, a, b);
    for (int p = 0; p < ng0; p++)
        g->mark[p] = cut[x->gnode[p]] ? 2
                     : growth_segment_distance(a, b, x->gx[p], x->gy[p]) < reach;
    for (int p = 0; p < ng0; p++) {           /* rows made again */
        if (g->mark[p] != 1)
            continue;
        int q = append_point(x, g, sim, x->gnode[p], x->gx[p], x->gy[p],
                             x->gw[p]);
        if (q < 0)
            return full(err, errlen, c, "Gauss points");
        memcpy(x->gs + 3 * q, x->gs + 3 * p, 3 * sizeof(double));
        memcpy(x->ge + 3 * q, x->ge + 3 * p, 3 * sizeof(double));
        g->mark[p] = 3;
    }
    int n = x->set.gauss;
    for (int I = 0; I < x->nnode; I++) {      /* cells split anew */
        if (!cut[I])
            continue;
        const Body *B = &sim->scene.bodies[sim->pts.body[I]];
        int m = quad_cell_in(g->qw, x->crack, x->ncrack, x->X[I] - x->hx[I],
                          x->Y[I] - x->hy[I], x->X[I] + x->hx[I],
                          x->Y[I] + x->hy[I], n, g->quad, g->quad_cap);
        if (m < 0 || m > g->quad_cap)
            return full(err, errlen, c, m == -2 ? "cuts of a cell's quadrature"
                                                : "quadrature points of a cell");
        x->cell_w[I] = 0.0;
        for (int k = 0; k < m; k++) {
            int p = append_point(x, g, sim, I, g->quad[k].x, g->quad[k].y,
                                 g->quad[k].w * B->thickness);
            if (p < 0)
                return full(err, errlen, c, "Gauss points");
            int o = nearest_old(x, g, ng0, I, c, p);
            if (o < 0)
                return full(err, errlen, c, "Gauss points (a cell without "
                            "points)");
            carry_state(x, sim, p, o);
            x->cell_w[I] += x->gw[p];
        }
    }
    return compact(x, g, ng0);
}
/// [growth_gauss]

int growth_rows_expand(ShapeRows *R, const int *len, int grad)
{
    long total = 0;
    for (int r = 0; r < R->n; r++) {
        if (len[r] < R->start[r + 1] - R->start[r])
            return -1;
        total += len[r];
    }
    if (total > R->cap)
        return -1;
    int end = (int)total, old_end = R->start[R->n];
    for (int r = R->n - 1; r >= 0; r--) {
        int old_beg = R->start[r], n = old_end - old_beg, beg = end - len[r];
        memmove(R->dof + beg, R->dof + old_beg, sizeof(int) * (size_t)n);
        memmove(R->N + beg, R->N + old_beg, sizeof(double) * (size_t)n);
        if (grad) {
            memmove(R->Nx + beg, R->Nx + old_beg, sizeof(double) * (size_t)n);
            memmove(R->Ny + beg, R->Ny + old_beg, sizeof(double) * (size_t)n);
        }
        R->start[r + 1] = end;
        end = beg;
        old_end = old_beg;
    }
    R->start[0] = 0;
    R->len = (int)total;
    return 0;
}

void growth_copy_row(ShapeRows *R, int r, const ShapeRows *S, int k)
{
    int n = S->start[k + 1] - S->start[k];
    memcpy(R->dof + R->start[r], S->dof + S->start[k], sizeof(int) * (size_t)n);
    memcpy(R->N + R->start[r], S->N + S->start[k], sizeof(double) * (size_t)n);
}

/** The rows at the nodes within @p reach of the segment, made again. */
static int node_rows(Sim *sim, Xefg *x, Growth *g, int c, const double a[2],
                     const double b[2], double reach, char *err, size_t errlen)
{
    ShapeRows *S = &g->rows, *R = &x->at_node;
    S->n = S->len = 0;
    for (int J = 0; J < x->nnode; J++) {
        g->mark[J] = -1;
        g->len[J] = R->start[J + 1] - R->start[J];
        if (growth_segment_distance(a, b, x->X[J], x->Y[J]) >= reach)
            continue;
        if (S->n + 1 > S->ncap || S->cap - S->len < ROW_ROOM ||
            xefg_shape_row(x, &g->cl, sim->pts.body, sim->pts.body[J], x->X[J],
                           x->Y[J], 0, S))
            return full(err, errlen, c, "rows of the nodes");
        g->mark[J] = S->n - 1;
        g->len[J] = S->start[S->n] - S->start[S->n - 1];
    }
    if (growth_rows_expand(R, g->len, 0))
        return full(err, errlen, c, "rows of the nodes");
    for (int J = 0; J < x->nnode; J++)
        if (g->mark[J] >= 0)
            growth_copy_row(R, J, S, g->mark[J]);
    return 0;
}

/// [growth_lumping]
/** The lumped masses of the new parameters, m_I <E^2> as at set-up
 *  (xefg_build.c), and their gravity integrals, from the points made
 *  again from @p first on (every point of a new parameter's support is
 *  one of them). @return 0, or -1 with a message. */
static int new_masses(const Sim *sim, Xefg *x, Growth *g, int c, int first,
                      char *err, size_t errlen)
{
    const ShapeRows *R = &x->gauss;
    for (int q = 0; q < x->ndof; q++)
        g->diag[q] = 0.0;
    for (int p = first; p < x->ngauss; p++) {
        const Body *B = &sim->scene.bodies[sim->pts.body[x->gnode[p]]];
        double rw = sim->scene.mat[B->material].rho * x->gw[p];
        for (int e = R->start[p]; e < R->start[p + 1]; e++) {
            int q = R->dof[e], I = x->dof_node[q];
            if (!g->add[I])
                continue;
            if (q == x->node_dof[I])
                g->diag[q] += rw;                    /* int_supp rho */
            else if (q >= x->node_dof[I + 1] - g->add[I]) {
                double E, Ex, Ey;
                xefg_enrichment(x, q, x->gx[p], x->gy[p], &E, &Ex, &Ey);
                g->diag[q] += rw * E * E;            /* int_supp rho E^2 */
                x->load[q] += rw * R->N[e];
            }
        }
    }
    for (int I = 0; I < x->nnode; I++) {
        int s0 = x->node_dof[I];
        for (int q = x->node_dof[I + 1] - g->add[I]; q < x->node_dof[I + 1]; q++) {
            x->mass[q] = x->mass[s0] * g->diag[q] / g->diag[s0];
            if (!(x->mass[q] > 0.0 && isfinite(x->mass[q]))) {
                snprintf(err, errlen, "growth of crack %d stopped: the node at "
                         "(%g, %g) gained a parameter of lumped mass %g", c,
                         x->X[I], x->Y[I], x->mass[q]);
                return -1;
            }
        }
    }
    return 0;
}
/// [growth_lumping]

int growth_rows(Sim *sim, Xefg *x, Growth *g, int c, const double a[2],
                const double b[2], char *err, size_t errlen)
{
    double dmax = 0.0;
    for (int I = 0; I < x->nnode; I++)
        dmax = fmax(dmax, x->d[I]);
    double reach = 2.0 * dmax * (1.0 + 1e-9);
    int first = gauss_points(sim, x, g, c, a, b, reach, err, errlen);
    if (first < 0 || node_rows(sim, x, g, c, a, b, reach, err, errlen))
        return -1;
    return new_masses(sim, x, g, c, first, err, errlen);
}
