/**
 * @file grid.c
 * @brief Allocation and clearing of the background grid.
 */
#include "grid.h"

#include <stdlib.h>
#include <string.h>

int grid_init(Grid *g, double ox, double oy, double dx, double dy,
              int ncx, int ncy, int extra_slots)
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
    g->capacity = g->nnodes + extra_slots;
    size_t n = (size_t)g->capacity;
    double **arrays[] = {&g->m, &g->px, &g->py, &g->fx, &g->fy,
                         &g->vx, &g->vy, &g->ax, &g->ay};
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; k++) {
        *arrays[k] = calloc(n, sizeof(double));
        if (!*arrays[k])
            return -1;
    }
    g->slot_node = calloc((size_t)extra_slots + 1, sizeof(int));
    g->fixed = calloc((size_t)g->nnodes, 1);
    return (g->slot_node && g->fixed) ? 0 : -1;
}

void grid_free(Grid *g)
{
    free(g->m);
    free(g->px);
    free(g->py);
    free(g->fx);
    free(g->fy);
    free(g->vx);
    free(g->vy);
    free(g->ax);
    free(g->ay);
    free(g->slot_node);
    free(g->fixed);
    memset(g, 0, sizeof *g);
}

void grid_clear(Grid *g)
{
    size_t bytes = (size_t)g->nslots * sizeof(double);
    memset(g->m, 0, bytes);
    memset(g->px, 0, bytes);
    memset(g->py, 0, bytes);
    memset(g->fx, 0, bytes);
    memset(g->fy, 0, bytes);
}

double grid_bytes(const Grid *g)
{
    return (double)g->capacity * (9.0 * sizeof(double))
         + (double)(g->capacity - g->nnodes + 1) * sizeof(int)
         + (double)g->nnodes;
}
