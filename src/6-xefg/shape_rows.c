/**
 * @file shape_rows.c
 * @brief The enriched shape functions of eq. 1 at a place: Phi_I for the
 *        standard parameter, Phi_I H for a step parameter and Phi_I B_k
 *        for a branch parameter, with gradients grad(Phi_I) E + Phi_I
 *        grad(E) (grad H = 0 off the crack).
 */
#include <stdlib.h>

#include "mls.h"
#include "xefg.h"

int xefg_grow(void **p, size_t size, int cap)
{
    void *q = realloc(*p, size * (size_t)cap);
    if (!q)
        return -1;
    *p = q;
    return 0;
}

int shape_rows_add(ShapeRows *R, int n, int grad)
{
    if (R->n == 0 && !R->start) {
        R->start = malloc(2 * sizeof(int));
        if (!R->start)
            return -1;
        R->start[0] = 0;
        R->ncap = 1;
    } else if (R->n + 1 > R->ncap) {     /* reserved rows: no allocation */
        if (xefg_grow((void **)&R->start, sizeof(int), R->n + 2))
            return -1;
        R->ncap = R->n + 1;
    }
    if (R->len + n > R->cap) {
        int cap = R->cap ? R->cap : 1024;
        while (cap < R->len + n)
            cap *= 2;
        if (xefg_grow((void **)&R->dof, sizeof(int), cap) ||
            xefg_grow((void **)&R->N, sizeof(double), cap) ||
            (grad && (xefg_grow((void **)&R->Nx, sizeof(double), cap) ||
                      xefg_grow((void **)&R->Ny, sizeof(double), cap))))
            return -1;
        R->cap = cap;
    }
    R->len += n;
    R->n++;
    R->start[R->n] = R->len;
    return 0;
}

void shape_rows_free(ShapeRows *R)
{
    free(R->start);
    free(R->dof);
    free(R->N);
    free(R->Nx);
    free(R->Ny);
    *R = (ShapeRows){0};
}

/// [xefg_enrichment]
void xefg_enrichment(const Xefg *x, int q, double px, double py, double *E,
                     double *Ex, double *Ey)
{
    CrackLine c = xefg_line_of(x, q);            /* the part it knows */
    int side = crack_line_side(&c, px, py, NULL);
    side = side ? side : 1;
    *Ex = *Ey = 0.0;
    if (x->dof_kind[q] == DOF_STEP) {
        *E = side;                                      /* eq. 3 */
        return;
    }
    double B[BRANCH_MAX], Bx[BRANCH_MAX], By[BRANCH_MAX];
    const double *tip = x->dof_frame + 4 * q, *dir = tip + 2; /* its tip */
    int nb = branch_functions(x->set.tip, x->set.m, tip, dir, side, px, py, B,
                              Bx, By);                  /* eq. 5 or 6 */
    int b = x->dof_kind[q] - DOF_BRANCH;
    *E = b < nb ? B[b] : 0.0;                           /* 0 on the tip */
    *Ex = b < nb ? Bx[b] : 0.0;
    *Ey = b < nb ? By[b] : 0.0;
}
/// [xefg_enrichment]

/** Most nodes whose supports hold one place. */
#define NEAR_MAX 512

/// [xefg_shape_row]
int xefg_shape_row(const Xefg *x, const CellList *cl, const int *body_of,
                   int body, double px, double py, int grad, ShapeRows *R)
{
    int near[NEAR_MAX], nn = 0;
    double X[NEAR_MAX], Y[NEAR_MAX], d[NEAR_MAX];
    double phi[NEAR_MAX], phx[NEAR_MAX], phy[NEAR_MAX];
    int all[NEAR_MAX];
    int m = cell_list_find(cl, x->X, x->Y, x->d, px, py, all, NEAR_MAX);
    if (m > NEAR_MAX)
        return -3;
    for (int k = 0; k < m; k++)          /* a body's own nodes only */
        if (body_of[all[k]] == body) {
            int J = all[k];
            near[nn] = J;
            X[nn] = x->X[J];
            Y[nn] = x->Y[J];
            d[nn] = x->d[J];
            nn++;
        }
    if (mls_shape(px, py, nn, X, Y, d, phi, grad ? phx : NULL,
                  grad ? phy : NULL))                       /* eq. 13-16 */
        return -1;
    int count = 0;
    for (int k = 0; k < nn; k++)
        count += x->node_dof[near[k] + 1] - x->node_dof[near[k]];
    if (shape_rows_add(R, count, grad))
        return -2;
    int e = R->start[R->n - 1];
    for (int k = 0; k < nn; k++) {
        int J = near[k];
        for (int q = x->node_dof[J]; q < x->node_dof[J + 1]; q++, e++) {
            double E = 1.0, Ex = 0.0, Ey = 0.0;         /* eq. 1: 1, H, B_k */
            if (x->dof_kind[q] != DOF_STANDARD)
                xefg_enrichment(x, q, px, py, &E, &Ex, &Ey);
            R->dof[e] = q;
            R->N[e] = phi[k] * E;
            if (grad) {
                R->Nx[e] = phx[k] * E + phi[k] * Ex;
                R->Ny[e] = phy[k] * E + phi[k] * Ey;
            }
        }
    }
    return 0;
}
/// [xefg_shape_row]
