/**
 * @file grid.c
 * @brief Allocation, growth and clearing of the background grid.
 */
#include "grid.h"

#include <stdlib.h>
#include <string.h>

/** Addresses of every per-slot double array of @p g, optional ones too. */
#define SLOT_ARRAYS(g) \
    { &(g)->m, &(g)->px, &(g)->py, &(g)->fx, &(g)->fy, &(g)->vx, &(g)->vy, \
      &(g)->ax, &(g)->ay, &(g)->qx, &(g)->qy }
/** How many of SLOT_ARRAYS every grid has (the rest are optional). */
#define SLOT_ARRAYS_ALWAYS 9

int grid_init(Grid *g, double ox, double oy, double dx, double dy,
              int ncx, int ncy)
{
    memset(g, 0, sizeof *g);
    g->ox = ox;
    g->oy = oy;
    g->dx = dx;
    g->dy = dy;
    g->idx = 1.0 / dx;
    g->idy = 1.0 / dy;
    g->ncx = ncx;
    g->ncy = ncy;
    g->nnx = ncx + 1;
    g->nny = ncy + 1;
    g->nnodes = g->nnx * g->nny;
    g->nslots = g->nnodes;
    g->fixed = calloc((size_t)g->nnodes, 1);
    if (!g->fixed)
        return -1;
    return grid_reserve(g, g->nnodes);
}

int grid_reserve(Grid *g, int capacity)
{
    if (capacity <= g->capacity)
        return 0;
    double **arrays[] = SLOT_ARRAYS(g);
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; k++) {
        if (k >= SLOT_ARRAYS_ALWAYS && !*arrays[k])
            continue;                          /* optional, not asked for */
        double *a = realloc(*arrays[k], (size_t)capacity * sizeof(double));
        if (!a)
            return -1;
        memset(a + g->capacity, 0, (size_t)(capacity - g->capacity) * sizeof(double));
        *arrays[k] = a;
    }
    int *sn = realloc(g->slot_node, (size_t)(capacity - g->nnodes + 1) * sizeof(int));
    if (!sn)
        return -1;
    g->slot_node = sn;
    g->capacity = capacity;
    return 0;
}

int grid_want(Grid *g, double **which)
{
    if (*which)
        return 0;
    *which = calloc((size_t)g->capacity, sizeof(double));
    return *which ? 0 : -1;
}

void grid_free(Grid *g)
{
    double **arrays[] = SLOT_ARRAYS(g);
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; k++)
        free(*arrays[k]);
    free(g->slot_node);
    free(g->fixed);
    memset(g, 0, sizeof *g);
}

/** Zero block @p b of @p nb (blocks of @p block slots) of each array. */
static void zero_block(const Grid *g, double *const *arrays, int narrays, int block,
                       int nb, int b)
{
    size_t lo = (size_t)b * block;
    size_t len = (size_t)(b == nb - 1 ? g->nslots - (int)lo : block) * sizeof(double);
    for (int k = 0; k < narrays; k++)
        memset(arrays[k] + lo, 0, len);
}

/// [grid_zero]
void grid_zero(const Grid *g, double *const *arrays, int narrays, int threads)
{
    const int block = 4096;             /* slots: 32 kB of each array */
    int nb = (g->nslots + block - 1) / block;
    if (nb <= 1 || threads == 1) {
        /* no region: one of a size other than the step's makes libgomp
           free the team it keeps and allocate another */
        for (int b = 0; b < nb; b++)
            zero_block(g, arrays, narrays, block, nb, b);
        return;
    }
    /* blocks in a fixed order per thread; zeros, so no bits depend on it */
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int b = 0; b < nb; b++)
        zero_block(g, arrays, narrays, block, nb, b);
}
/// [grid_zero]

void grid_clear(Grid *g, int threads)
{
    double *const arrays[] = { g->m, g->px, g->py, g->fx, g->fy };
    grid_zero(g, arrays, 5, threads);
}

double grid_bytes(const Grid *g)
{
    double arrays = 9.0 + (g->qx != NULL) + (g->qy != NULL);
    return (double)g->capacity * arrays * sizeof(double)
         + (double)(g->capacity - g->nnodes + 1) * sizeof(int)
         + (double)g->nnodes;
}
