/**
 * @file cpdi.c
 * @brief CPDI1 weights and gradients of a parallelogram domain
 *        (Sadeghirad, Brannon & Burghardt 2011, eq. 31 and 33 in their
 *        numbering; derived here from the divergence theorem).
 */
#include "cpdi.h"

#include <math.h>

#include "gimp.h"

/** The hat of a node at distance @p t cells. */
static double hat(double t)
{
    t = fabs(t);
    return t < 1.0 ? 1.0 - t : 0.0;
}

/** The first node and the count (at most 3) along one direction for
 *  corner coordinates @p c (in cells) on a grid of @p cells cells. */
static int node_range(const double c[4], int cells, int *count)
{
    double lo = fmin(fmin(c[0], c[1]), fmin(c[2], c[3]));
    double hi = fmax(fmax(c[0], c[1]), fmax(c[2], c[3]));
    int first = (int)floor(lo), last = (int)floor(hi) + 1;
    if (first < 0)
        first = 0;
    if (last > cells)
        last = cells;
    if (last - first > 2)
        last = first + 2;
    *count = last - first + 1;
    return first;
}

/// [cpdi_stencil_domain]
void cpdi_stencil_domain(const Grid *g, double x, double y, const double r1[2],
                         const double r2[2], Stencil *st)
{
    /* corners 1..4 counter-clockwise: -r1-r2, +r1-r2, +r1+r2, -r1+r2 */
    static const double s1[4] = {-1, 1, 1, -1}, s2[4] = {-1, -1, 1, 1};
    double cx[4], cy[4];
    for (int k = 0; k < 4; k++) {
        cx[k] = (x + s1[k] * r1[0] + s2[k] * r2[0] - g->ox) * g->idx;
        cy[k] = (y + s1[k] * r1[1] + s2[k] * r2[1] - g->oy) * g->idy;
    }
    double V = 4.0 * (r1[0] * r2[1] - r1[1] * r2[0]);   /* area */
    /* the closed integral of N n ds, N linear along each side */
    double a[2] = {(r1[1] - r2[1]) / V, (r2[0] - r1[0]) / V};   /* N1 - N3 */
    double b[2] = {(r1[1] + r2[1]) / V, -(r1[0] + r2[0]) / V};  /* N2 - N4 */
    int ni, nj, i0 = node_range(cx, g->ncx, &ni), j0 = node_range(cy, g->ncy, &nj);
    st->n = 0;
    for (int jb = 0; jb < nj; jb++)
        for (int ia = 0; ia < ni; ia++) {
            int col = i0 + ia, row = j0 + jb, k = st->n;
            double N[4];
            for (int c = 0; c < 4; c++)
                N[c] = hat(cx[c] - col) * hat(cy[c] - row);
            st->slot[k] = row * g->nnx + col;
            st->S[k] = 0.25 * (N[0] + N[1] + N[2] + N[3]);
            st->Gx[k] = (N[0] - N[2]) * a[0] + (N[1] - N[3]) * b[0];
            st->Gy[k] = (N[0] - N[2]) * a[1] + (N[1] - N[3]) * b[1];
            st->n++;
        }
}
/// [cpdi_stencil_domain]

void cpdi_vectors(const struct Sim *sim, const Cpdi *C, int p, double r1[2],
                  double r2[2])
{
    double l = gimp_half(sim, p), hx = l * sim->grid.dx, hy = l * sim->grid.dy;
    const double *F = &C->F[4 * p];
    r1[0] = F[0] * hx;                  /* F (hx, 0) */
    r1[1] = F[2] * hx;
    r2[0] = F[1] * hy;                  /* F (0, hy) */
    r2[1] = F[3] * hy;
}

void cpdi_stencil(const struct Sim *sim, int p, Stencil *st)
{
    const Cpdi *C = sim_state(sim, CPDI_STATE);
    const Grid *g = &sim->grid;
    int cell = sim->pts.cell[p];
    double x = g->ox + (cell % g->nnx + sim->pts.xi[p]) * g->dx;
    double y = g->oy + (cell / g->nnx + sim->pts.eta[p]) * g->dy;
    double r1[2], r2[2];
    cpdi_vectors(sim, C, p, r1, r2);
    cpdi_stencil_domain(g, x, y, r1, r2, st);
}

const ShapeFunctions shape_cpdi = {"cpdi", STENCIL_MAX, cpdi_stencil};
