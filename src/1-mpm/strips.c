/**
 * @file strips.c
 * @brief Binning the points by the strips of node rows their stencils
 *        reach: a stable counting sort over chunks of points, on threads.
 */
#include "strips.h"

#include <stdlib.h>
#include <string.h>

#include "sim.h"

int strips_init(Sim *sim)
{
    Strips *S = &sim->strips;
    const Grid *g = &sim->grid;
    int T = sim->threads, np = sim->pts.n;
    strips_free(S);
    if (T < 2)
        return 0;
    /* a stencil of 3 x 3 nodes comes from a domain at most a cell wide
       (shapes_check.c, cpdi_update.c): node rows j - 1 .. j + 2 */
    S->reach = sim->scene.run.stencil ? 1 : 0;
    S->first_node = malloc(sizeof(int) * ((size_t)T + 1));
    S->start = malloc(sizeof(int) * ((size_t)T + 1));
    S->list = malloc(sizeof(int) * (2 * (size_t)np + 1));
    S->code = malloc(sizeof(int) * ((size_t)np + 1));
    S->rows = malloc(sizeof(int) * (size_t)T * (size_t)g->ncy);
    S->count = malloc(sizeof(int) * (size_t)T * (size_t)T);
    S->strip_of_row = malloc(sizeof(int) * (size_t)g->nny);
    if (!S->first_node || !S->start || !S->list || !S->code || !S->rows ||
        !S->count || !S->strip_of_row) {
        strips_free(S);
        return -1;
    }
    S->cap = T;
    S->npoints = np;
    return 0;
}

/** The points of chunk @p c of @p T: [*lo, *hi). */
static void chunk(int np, int T, int c, int *lo, int *hi)
{
    *lo = (int)((long long)np * c / T);
    *hi = (int)((long long)np * (c + 1) / T);
}

/** Cut the node rows into at most Strips::cap strips of about equal
 *  points, each @p w rows or more, so that a point's rows meet at most
 *  two strips. @return how many, or 0 when fewer than two. */
static int cut_rows(Strips *S, const Grid *g, int np, int w)
{
    int T = S->cap, ns = g->nny / w < T ? g->nny / w : T, t = 0;
    long long seen = 0;
    if (ns < 2)
        return 0;
    int first = 0;
    S->first_node[0] = 0;
    for (int r = 0; r < g->nny; r++) {
        if (t + 1 < ns && r - first >= w && g->nny - r >= (ns - 1 - t) * w &&
            seen * ns >= (long long)np * (t + 1)) {
            S->first_node[++t] = r * g->nnx;
            first = r;
        }
        S->strip_of_row[r] = t;
        for (int c = 0; r < g->ncy && c < T; c++)
            seen += S->rows[(size_t)c * g->ncy + r];
    }
    S->first_node[t + 1] = g->nnodes;
    return t > 0 ? t + 1 : 0;           /* one strip: one thread */
}

/// [strips_bin]
void strips_bin(Sim *sim)
{
    Strips *S = &sim->strips;
    const Grid *g = &sim->grid;
    const int *cell = sim->pts.cell;
    int np = sim->pts.n, T = S->cap, nnx = g->nnx, ncy = g->ncy;
    S->n = 0;
    if (T < 2 || np > S->npoints)
        return;                         /* one thread */
#pragma omp parallel for num_threads(T) schedule(static, 1)
    for (int c = 0; c < T; c++) {       /* the points of each cell row */
        int lo, hi, *rows = &S->rows[(size_t)c * ncy];
        chunk(np, T, c, &lo, &hi);
        memset(rows, 0, sizeof(int) * (size_t)ncy);
        for (int p = lo; p < hi; p++)
            rows[S->code[p] = cell[p] / nnx]++;
    }
    int ns = cut_rows(S, g, np, 2 + 2 * S->reach);
    if (ns == 0)
        return;
#pragma omp parallel for num_threads(T) schedule(static, 1)
    for (int c = 0; c < T; c++) {       /* the strips each point reaches */
        int lo, hi, *count = &S->count[(size_t)c * T];
        chunk(np, T, c, &lo, &hi);
        memset(count, 0, sizeof(int) * (size_t)T);
        for (int p = lo; p < hi; p++) {
            int j = S->code[p], r0 = j - S->reach, r1 = j + 1 + S->reach;
            int t0 = S->strip_of_row[r0 < 0 ? 0 : r0];
            int t1 = S->strip_of_row[r1 > g->nny - 1 ? g->nny - 1 : r1];
            count[t0]++;
            count[t1] += t1 != t0;
            S->code[p] = 2 * t0 + (t1 != t0);
        }
    }
    int at = 0;                         /* strip by strip, chunk by chunk */
    for (int t = 0; t < ns; t++) {
        S->start[t] = at;
        for (int c = 0; c < T; c++) {
            int k = S->count[(size_t)c * T + t];
            S->count[(size_t)c * T + t] = at;
            at += k;
        }
    }
    S->start[ns] = at;
#pragma omp parallel for num_threads(T) schedule(static, 1)
    for (int c = 0; c < T; c++) {       /* each chunk's points, in order */
        int lo, hi, *count = &S->count[(size_t)c * T];
        chunk(np, T, c, &lo, &hi);
        for (int p = lo; p < hi; p++) {
            int t0 = S->code[p] >> 1;
            S->list[count[t0]++] = p;
            if (S->code[p] & 1)
                S->list[count[t0 + 1]++] = p;
        }
    }
    S->n = ns;
}
/// [strips_bin]

void strips_free(Strips *S)
{
    free(S->first_node);
    free(S->start);
    free(S->list);
    free(S->code);
    free(S->rows);
    free(S->count);
    free(S->strip_of_row);
    memset(S, 0, sizeof *S);
}
