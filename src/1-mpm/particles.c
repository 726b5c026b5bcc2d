/**
 * @file particles.c
 * @brief Allocation of the material-point arrays.
 */
#include "particles.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

/** Addresses of every double array of @p P, for loops over all of them. */
#define DOUBLE_ARRAYS(P) \
    { &(P)->x, &(P)->y, &(P)->vx, &(P)->vy, &(P)->m, &(P)->vol, &(P)->sxx, \
      &(P)->syy, &(P)->sxy, &(P)->exx, &(P)->eyy, &(P)->exy, &(P)->xi, &(P)->eta }
/** Addresses of every int array of @p P. */
#define INT_ARRAYS(P) { &(P)->mat, &(P)->body, &(P)->cell }

int particles_init(Particles *P, int cap)
{
    memset(P, 0, sizeof *P);
    return particles_reserve(P, cap > 0 ? cap : 16);
}

int particles_reserve(Particles *P, int cap)
{
    if (cap <= P->cap)
        return 0;
    double **d[] = DOUBLE_ARRAYS(P);
    int **k[] = INT_ARRAYS(P);
    for (size_t a = 0; a < sizeof d / sizeof d[0]; a++) {
        double *q = realloc(*d[a], (size_t)cap * sizeof(double));
        if (!q)
            return -1;
        memset(q + P->cap, 0, (size_t)(cap - P->cap) * sizeof(double));
        *d[a] = q;
    }
    for (size_t a = 0; a < sizeof k / sizeof k[0]; a++) {
        int *q = realloc(*k[a], (size_t)cap * sizeof(int));
        if (!q)
            return -1;
        memset(q + P->cap, 0, (size_t)(cap - P->cap) * sizeof(int));
        *k[a] = q;
    }
    P->cap = cap;
    return 0;
}

int particles_add(Particles *P, double x, double y, double m, double vol,
                  int mat, int body)
{
    if (P->n == P->cap) {                 /* double, up to INT_MAX points */
        size_t cap = 2 * (size_t)(P->cap > 0 ? P->cap : 8);
        if (P->n == INT_MAX ||
            particles_reserve(P, cap > INT_MAX ? INT_MAX : (int)cap) != 0)
            return -1;
    }
    int p = P->n++;
    P->x[p] = x;
    P->y[p] = y;
    P->m[p] = m;
    P->vol[p] = vol;
    P->mat[p] = mat;
    P->body[p] = body;
    return p;
}

void particles_free(Particles *P)
{
    double **d[] = DOUBLE_ARRAYS(P);
    int **k[] = INT_ARRAYS(P);
    for (size_t a = 0; a < sizeof d / sizeof d[0]; a++)
        free(*d[a]);
    for (size_t a = 0; a < sizeof k / sizeof k[0]; a++)
        free(*k[a]);
    memset(P, 0, sizeof *P);
}

double particles_bytes_per_point(void)
{
    return 14.0 * sizeof(double) + 3.0 * sizeof(int);
}
