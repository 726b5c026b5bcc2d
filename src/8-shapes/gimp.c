/**
 * @file gimp.c
 * @brief The uGIMP stencil of a point (Bardenhagen & Kober 2004, the
 *        undeformed particle domain): the nodes its domain reaches and
 *        the products of the 1D weights of gimp_weight.c.
 */
#include "gimp.h"

/** The first node column (row) a domain [u - l, u + l] of cell @p i
 *  reaches, and how many (2 or 3). */
static int reach(int i, double u, double l, int *count)
{
    int left = u - l < 0.0, right = u + l > 1.0;
    *count = 2 + (left || right);
    return left ? i - 1 : i;
}

/// [gimp_stencil_cell]
void gimp_stencil_cell(const Grid *g, int cell, double xi, double eta,
                       double lx, double ly, Stencil *st)
{
    int i = cell % g->nnx, j = cell / g->nnx, ni, nj;
    int i0 = reach(i, xi, lx, &ni), j0 = reach(j, eta, ly, &nj);
    double Sx[3], Gx[3], Sy[3], Gy[3];
    for (int a = 0; a < ni; a++)
        Sx[a] = gimp_weight(i + xi - (i0 + a), lx, &Gx[a]);
    for (int b = 0; b < nj; b++)
        Sy[b] = gimp_weight(j + eta - (j0 + b), ly, &Gy[b]);
    st->n = 0;
    for (int b = 0; b < nj; b++) {
        int row = j0 + b;
        if (row < 0 || row > g->ncy)
            continue;
        for (int a = 0; a < ni; a++) {
            int col = i0 + a, k = st->n;
            if (col < 0 || col > g->ncx)
                continue;
            st->slot[k] = row * g->nnx + col;
            st->S[k] = Sx[a] * Sy[b];         /* S_ip = S_x S_y */
            st->Gx[k] = Gx[a] * Sy[b] * g->idx;
            st->Gy[k] = Sx[a] * Gy[b] * g->idy;
            st->n++;
        }
    }
}
/// [gimp_stencil_cell]

void gimp_stencil(const struct Sim *sim, int p, Stencil *st)
{
    double l = gimp_half(sim, p);
    gimp_stencil_cell(&sim->grid, sim->pts.cell[p], sim->pts.xi[p],
                      sim->pts.eta[p], l, l, st);
}

const ShapeFunctions shape_gimp = {"gimp", STENCIL_MAX, gimp_stencil};
