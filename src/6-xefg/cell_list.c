/**
 * @file cell_list.c
 * @brief Neighbour search by a cell list: nodes binned on square cells of
 *        the largest support radius, so that a support that holds a point
 *        lies in the point's cell or one next to it.
 */
#include <limits.h>
#include <math.h>
#include <stdlib.h>

#include "cell_list.h"

/* The cell coordinate floor((v - o) / size) in double; rounding is
 * monotone, so v <= u gives cell(v) <= cell(u), which the query relies on. */
static double cell_coord(double v, double o, double size)
{
    return floor((v - o) / size);
}

int cell_list_build(CellList *c, int n, const double *X, const double *Y,
                    double size)
{
    c->start = c->item = NULL;
    c->nx = c->ny = 0;
    c->size = size;
    c->ox = c->oy = 0.0;
    if (n < 0 || !(size > 0.0) || !isfinite(size))
        return -1;

    double xmin = 0.0, ymin = 0.0, xmax = 0.0, ymax = 0.0;
    for (int k = 0; k < n; k++) {
        if (!isfinite(X[k]) || !isfinite(Y[k]))
            return -1;
        if (k == 0 || X[k] < xmin) xmin = X[k];
        if (k == 0 || X[k] > xmax) xmax = X[k];
        if (k == 0 || Y[k] < ymin) ymin = Y[k];
        if (k == 0 || Y[k] > ymax) ymax = Y[k];
    }
    c->ox = xmin;
    c->oy = ymin;
    /* the last node's cell must be a valid index */
    double fx = cell_coord(xmax, xmin, size) + 1.0;
    double fy = cell_coord(ymax, ymin, size) + 1.0;
    if (!(fx < INT_MAX && fy < INT_MAX && fx * fy < INT_MAX))
        return -1;
    c->nx = (int)fx;
    c->ny = (int)fy;
    int ncell = c->nx * c->ny;

    c->start = calloc((size_t)ncell + 1, sizeof *c->start);
    c->item = malloc((size_t)(n > 0 ? n : 1) * sizeof *c->item);
    int *cell = malloc((size_t)(n > 0 ? n : 1) * sizeof *cell);
    if (!c->start || !c->item || !cell) {
        free(cell);
        cell_list_free(c);
        return -1;
    }

    /* counting sort: count per cell, prefix sums, then place the nodes in
     * increasing order, so that each cell lists its nodes increasing */
    for (int k = 0; k < n; k++) {
        int i = (int)cell_coord(X[k], c->ox, size);
        int j = (int)cell_coord(Y[k], c->oy, size);
        cell[k] = i + c->nx * j;
        c->start[cell[k] + 1]++;
    }
    for (int q = 0; q < ncell; q++)
        c->start[q + 1] += c->start[q];
    for (int k = 0; k < n; k++)
        c->item[c->start[cell[k]]++] = k;
    /* placing advanced start[q] to the end of cell q: shift back */
    for (int q = ncell; q > 0; q--)
        c->start[q] = c->start[q - 1];
    c->start[0] = 0;
    free(cell);
    return 0;
}

/* The range of cells [lo, hi] along one axis that can hold a node within
 * distance size of v, clipped to [0, ncell - 1]; 0 when it is empty. */
static int cell_range(double v, double o, double size, int ncell, int *lo, int *hi)
{
    double a = cell_coord(v - size, o, size);
    double b = cell_coord(v + size, o, size);
    if (!(a <= ncell - 1 && b >= 0.0))  /* also false for NaN */
        return 0;
    *lo = a > 0.0 ? (int)a : 0;
    *hi = b < ncell - 1 ? (int)b : ncell - 1;
    return 1;
}

int cell_list_find(const CellList *c, const double *X, const double *Y,
                   const double *d, double x, double y, int *out, int cap)
{
    int ilo, ihi, jlo, jhi;
    if (!c->start || !cell_range(x, c->ox, c->size, c->nx, &ilo, &ihi)
        || !cell_range(y, c->oy, c->size, c->ny, &jlo, &jhi))
        return 0;
    /* X_k within size of x lies in cells [cell(x - size), cell(x + size)]:
     * the 3x3 cells around x, or one more where rounding puts x on an edge */
    int count = 0;
    for (int j = jlo; j <= jhi; j++)
        for (int i = ilo; i <= ihi; i++) {
            int q = i + c->nx * j;
            for (int m = c->start[q]; m < c->start[q + 1]; m++) {
                int k = c->item[m];
                double rx = x - X[k], ry = y - Y[k];
                if (!(rx * rx + ry * ry < d[k] * d[k]))
                    continue;
                /* insert k into the sorted out[0 .. min(count, cap)), which
                 * keeps the cap smallest indices when there are more */
                int len = count < cap ? count : cap;
                int p = len;
                while (p > 0 && out[p - 1] > k)
                    p--;
                if (p < cap) {
                    for (int t = (len < cap ? len : cap - 1); t > p; t--)
                        out[t] = out[t - 1];
                    out[p] = k;
                }
                count++;
            }
        }
    return count;
}

void cell_list_free(CellList *c)
{
    free(c->start);
    free(c->item);
    c->start = c->item = NULL;
    c->nx = c->ny = 0;
}
