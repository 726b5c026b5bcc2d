/**
 * @file strips.c
 * @brief Binning the points by the strips of node rows their stencils
 *        reach: a stable counting sort over chunks of points, on threads.
 */
#include "strips.h"

#include <stdlib.h>
#include <string.h>

#include "sim.h"

/** Ints between two chunks' counters: a cache line or more, so that
 *  threads counting at once do not share one. */
static int stride_of(int T)
{
    return (T + 15) / 16 * 16;
}

int strips_init(Sim *sim)
{
    Strips *S = &sim->strips;
    const Grid *g = &sim->grid;
    int T = sim->threads, np = sim->pts.n;
    strips_free(S);
    if (T < 2 || sim->scene.run.method->step != sim_step)
        return 0;                   /* one thread, or a method of its own */
    /* a stencil of 3 x 3 nodes comes from a domain at most a cell wide
       (shapes_check.c, cpdi_update.c): node rows j - 1 .. j + 2 */
    S->reach = sim->scene.run.stencil ? 1 : 0;
    S->first_node = malloc(sizeof(int) * ((size_t)T + 1));
    S->start = malloc(sizeof(int) * ((size_t)T + 1));
    S->list = malloc(sizeof(int) * (2 * (size_t)np + 1));
    S->code = malloc(sizeof(int) * ((size_t)np + 1));
    S->rows = malloc(sizeof(int) * (size_t)T * (size_t)g->ncy);
    S->count = malloc(sizeof(int) * (size_t)T * (size_t)stride_of(T));
    S->row_strips = malloc(sizeof(int) * (size_t)g->ncy);
    if (!S->first_node || !S->start || !S->list || !S->code || !S->rows ||
        !S->count || !S->row_strips) {
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
 *  points, each 2 + 2 reach rows or more, so that a point's rows meet at
 *  most two strips; give each cell row its strips (Strips::row_strips).
 *  @return how many, or 0 when fewer than two. */
static int cut_rows(Strips *S, const Grid *g, int np)
{
    int T = S->cap, w = 2 + 2 * S->reach, t = 0, first = 0;
    int ns = g->nny / w < T ? g->nny / w : T;
    long long seen = 0;
    if (ns < 2)
        return 0;
    S->first_node[0] = 0;
    for (int r = 0; r < g->nny; r++) {
        if (t + 1 < ns && r - first >= w && g->nny - r >= (ns - 1 - t) * w &&
            seen * ns >= (long long)np * (t + 1)) {
            S->first_node[++t] = r * g->nnx;
            first = r;
        }
        for (int c = 0; r < g->ncy && c < T; c++)
            seen += S->rows[(size_t)c * g->ncy + r];
    }
    S->first_node[t + 1] = g->nnodes;
    int t0 = 0, t1 = 0, last = t;
    for (int j = 0; j < g->ncy; j++) {  /* node rows j - reach .. j + 1 + reach */
        int r0 = j - S->reach, r1 = j + 1 + S->reach;
        while (t0 < last && S->first_node[t0 + 1] <= r0 * g->nnx)
            t0++;
        while (t1 < last && S->first_node[t1 + 1] <= r1 * g->nnx)
            t1++;
        S->row_strips[j] = 2 * t0 + (t1 != t0);
    }
    return t > 0 ? t + 1 : 0;           /* one strip: one thread */
}

/** Where each chunk's points go in the lists: strip by strip, chunk by
 *  chunk, counted from the cell rows' points. */
static void offsets(Strips *S, const Grid *g, int ns)
{
    int T = S->cap, at = 0, stride = stride_of(T);
    for (int c = 0; c < T; c++) {
        int *count = &S->count[(size_t)c * stride];
        const int *rows = &S->rows[(size_t)c * g->ncy];
        for (int t = 0; t < ns; t++)
            count[t] = 0;
        for (int j = 0; j < g->ncy; j++) {
            int rs = S->row_strips[j];
            count[rs >> 1] += rows[j];
            if (rs & 1)                 /* they reach the next strip too */
                count[(rs >> 1) + 1] += rows[j];
        }
    }
    for (int t = 0; t < ns; t++) {
        S->start[t] = at;
        for (int c = 0; c < T; c++) {
            int k = S->count[(size_t)c * stride + t];
            S->count[(size_t)c * stride + t] = at;
            at += k;
        }
    }
    S->start[ns] = at;
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
    for (int c = 0; c < T; c++) {       /* each chunk's points per cell row */
        int lo, hi, *rows = &S->rows[(size_t)c * ncy];
        chunk(np, T, c, &lo, &hi);
        memset(rows, 0, sizeof(int) * (size_t)ncy);
        for (int p = lo; p < hi; p++)
            rows[S->code[p] = cell[p] / nnx]++;
    }
    int ns = cut_rows(S, g, np);
    if (ns == 0)
        return;
    offsets(S, g, ns);
#pragma omp parallel for num_threads(T) schedule(static, 1)
    for (int c = 0; c < T; c++) {       /* each chunk's points, in order */
        int lo, hi, *count = &S->count[(size_t)c * stride_of(T)];
        chunk(np, T, c, &lo, &hi);
        for (int p = lo; p < hi; p++) {
            int rs = S->row_strips[S->code[p]], t0 = rs >> 1;
            S->list[count[t0]++] = p;
            if (rs & 1)                 /* it reaches the next strip too */
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
    free(S->row_strips);
    memset(S, 0, sizeof *S);
}
