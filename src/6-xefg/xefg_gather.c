/**
 * @file xefg_gather.c
 * @brief XEFG's sums on threads: each parameter's internal force and each
 *        node's cell average gathered in ascending Gauss point, the order
 *        of the one-thread scatter, so the bits do not depend on the number
 *        of threads (appendix "Running in parallel").
 */
#include <stdlib.h>
#include <string.h>

#include "growth.h"
#include "xefg_gather.h"

/** The entries of rows @p R by parameter (a counting sort): for each of
 *  @p nkeys parameters its entries, in ascending row (Gauss point), each
 *  entry's gradient copied (@p grad: Nx, Ny) with its row (@p point), so
 *  that a parameter's sum reads them in a stream rather than one cache
 *  line per entry from rows laid out by Gauss point. */
static void turn_rows(const ShapeRows *R, int nkeys, int *start, double *grad,
                      int *point)
{
    memset(start, 0, sizeof(int) * (size_t)(nkeys + 1));
    for (int k = 0; k < R->start[R->n]; k++)
        start[R->dof[k] + 1]++;
    for (int q = 0; q < nkeys; q++)
        start[q + 1] += start[q];
    for (int g = 0; g < R->n; g++)          /* ascending g: the scatter's order */
        for (int k = R->start[g]; k < R->start[g + 1]; k++) {
            int e = start[R->dof[k]]++;
            grad[2 * e] = R->Nx[k];
            grad[2 * e + 1] = R->Ny[k];
            point[e] = g;
        }
    for (int q = nkeys; q > 0; q--)         /* start[q] had moved to start[q + 1] */
        start[q] = start[q - 1];
    start[0] = 0;
}

/** Node I's Gauss points, ascending. */
static void turn_cells(const Xefg *x, int *start, int *point)
{
    memset(start, 0, sizeof(int) * (size_t)(x->nnode + 1));
    for (int g = 0; g < x->ngauss; g++)
        start[x->gnode[g] + 1]++;
    for (int I = 0; I < x->nnode; I++)
        start[I + 1] += start[I];
    for (int g = 0; g < x->ngauss; g++)
        point[start[x->gnode[g]]++] = g;
    for (int I = x->nnode; I > 0; I--)
        start[I] = start[I - 1];
    start[0] = 0;
}

void xefg_gather_refresh(Xefg *x)
{
    XefgGather *G = x->gather;
    if (!G || G->version == x->rows_version)
        return;
    turn_rows(&x->gauss, x->ndof, G->col_start, G->col_grad, G->col_point);
    turn_cells(x, G->cell_start, G->cell_point);
    G->version = x->rows_version;
}

int xefg_gather_build(Xefg *x, const Sim *sim)
{
    if (sim->threads <= 1 || x->gather)
        return 0;
    const Growth *g = x->grow;               /* the room a crack may grow in */
    size_t ndof = (size_t)(g ? g->dof_cap : x->ndof);
    size_t ngauss = (size_t)(g ? g->gauss_cap : x->ngauss);
    size_t nent = (size_t)x->gauss.cap;
    XefgGather *G = calloc(1, sizeof *G);
    if (!G)
        return -1;
    x->gather = G;
    G->col_start = malloc(sizeof(int) * (ndof + 1));
    G->col_grad = malloc(2 * sizeof(double) * nent);
    G->col_point = malloc(sizeof(int) * nent);
    G->cell_start = malloc(sizeof(int) * ((size_t)x->nnode + 1));
    G->cell_point = malloc(sizeof(int) * ngauss);
    size_t nws = 3 * ngauss > 2 * ndof ? 3 * ngauss : 2 * ndof;
    G->ws = malloc(sizeof(double) * nws);
    if (!G->col_start || !G->col_grad || !G->col_point || !G->cell_start ||
        !G->cell_point || !G->ws)
        return -1;                           /* freed with x */
    G->version = x->rows_version - 1;
    xefg_gather_refresh(x);
    return 0;
}

int xefg_gather_current(const Xefg *x)
{
    return x->gather && x->gather->version == x->rows_version;
}

/// [xefg_gather_force]
void xefg_gather_force(const Xefg *x, double *f)
{
    const XefgGather *G = x->gather;
#pragma omp for schedule(static)
    for (int q = 0; q < x->ndof; q++) {     /* each parameter its own sum */
        double fx = 0.0, fy = 0.0;
        for (int e = G->col_start[q]; e < G->col_start[q + 1]; e++) {
            const double *s = G->ws + 3 * G->col_point[e], *b = G->col_grad + 2 * e;
            fx += s[0] * b[0] + s[2] * b[1];
            fy += s[2] * b[0] + s[1] * b[1];
        }
        f[2 * q] = fx;
        f[2 * q + 1] = fy;
    }
}
/// [xefg_gather_force]

void xefg_gather_cell(const Xefg *x, int I, Particles *P)
{
    const XefgGather *G = x->gather;
    double s[3] = {0.0, 0.0, 0.0}, e[3] = {0.0, 0.0, 0.0};
    for (int j = G->cell_start[I]; j < G->cell_start[I + 1]; j++) {
        int g = G->cell_point[j];
        double w = x->gw[g] / x->cell_w[I];
        for (int c = 0; c < 3; c++) {
            s[c] += w * x->gs[3 * g + c];
            e[c] += w * x->ge[3 * g + c];
        }
    }
    P->sxx[I] = s[0];
    P->syy[I] = s[1];
    P->sxy[I] = s[2];
    P->exx[I] = e[0];
    P->eyy[I] = e[1];
    P->exy[I] = e[2];
}

void xefg_gather_free(XefgGather *G)
{
    if (!G)
        return;
    free(G->col_start);
    free(G->col_grad);
    free(G->col_point);
    free(G->cell_start);
    free(G->cell_point);
    free(G->ws);
    free(G);
}
