/**
 * @file q4.c
 * @brief Plane-stress Q4 statics: element stiffness by 2 x 2 Gauss
 *        quadrature, banded assembly, LAPACKE_dpbsv.
 */
#include "q4.h"

#include <lapacke.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/** Entry K(r, c), r <= c, of a symmetric matrix in LAPACK's upper band
 *  storage @p ab (column major) with half bandwidth @p kd. */
#define KAB(ab, kd, r, c) \
    (ab)[(size_t)((kd) + (r) - (c)) + (size_t)(c) * (size_t)((kd) + 1)]

int q4_init(Q4Model *q, int nx, int ny, double x0, double y0, double dx,
            double dy, double t, double E, double nu)
{
    *q = (Q4Model){nx, ny, x0, y0, dx, dy, t, E, nu, NULL, NULL, NULL};
    size_t ndof = 2 * (size_t)(nx + 1) * (size_t)(ny + 1);
    q->f = calloc(ndof, sizeof(double));
    q->u = calloc(ndof, sizeof(double));
    q->fix = calloc(ndof, 1);
    return (q->f && q->u && q->fix) ? 0 : -1;
}

void q4_free(Q4Model *q)
{
    free(q->f);
    free(q->u);
    free(q->fix);
    q->f = q->u = NULL;
    q->fix = NULL;
}

/** Element of (x, y), its local coordinates in [0, 1]^2 and its 4 nodes
 *  numbered as the MPM cell corners (0: lower left, 1, 2: upper left, 3). */
static void locate(const Q4Model *q, double x, double y, double *xi,
                   double *eta, int node[4])
{
    double gx = (x - q->x0) / q->dx, gy = (y - q->y0) / q->dy;
    int i = (int)floor(gx), j = (int)floor(gy);
    i = i < 0 ? 0 : i >= q->nx ? q->nx - 1 : i;
    j = j < 0 ? 0 : j >= q->ny ? q->ny - 1 : j;
    *xi = gx - i;
    *eta = gy - j;
    node[0] = q4_node(q, i, j);
    node[1] = q4_node(q, i + 1, j);
    node[2] = q4_node(q, i, j + 1);
    node[3] = q4_node(q, i + 1, j + 1);
}

/** Bilinear shape functions and x, y derivatives at (xi, eta). */
static void shape(const Q4Model *q, double xi, double eta, double N[4],
                  double Nx[4], double Ny[4])
{
    double a = 1 - xi, b = 1 - eta;
    N[0] = a * b;
    N[1] = xi * b;
    N[2] = a * eta;
    N[3] = xi * eta;
    Nx[0] = -b / q->dx;
    Nx[1] = b / q->dx;
    Nx[2] = -eta / q->dx;
    Nx[3] = eta / q->dx;
    Ny[0] = -a / q->dy;
    Ny[1] = -xi / q->dy;
    Ny[2] = a / q->dy;
    Ny[3] = xi / q->dy;
}

void q4_point_force(Q4Model *q, double x, double y, double fx, double fy)
{
    double xi, eta, N[4], Nx[4], Ny[4];
    int node[4];
    locate(q, x, y, &xi, &eta, node);
    shape(q, xi, eta, N, Nx, Ny);
    for (int a = 0; a < 4; a++) {
        q->f[2 * node[a]] += N[a] * fx;
        q->f[2 * node[a] + 1] += N[a] * fy;
    }
}

/// [q4_solve]
int q4_solve(Q4Model *q)
{
    int nn = (q->nx + 1) * (q->ny + 1), n = 2 * nn;
    int kd = 2 * (q->nx + 1) + 3;             /* half bandwidth of K */
    double *ab = calloc((size_t)(kd + 1) * (size_t)n, sizeof(double));
    if (!ab)
        return -1;
    double c = q->E / (1 - q->nu * q->nu);
    double D[3][3] = {{c, c * q->nu, 0}, {c * q->nu, c, 0},
                      {0, 0, c * (1 - q->nu) / 2}};
    static const double gp[2] = {0.5 - 0.5 / 1.7320508075688772,
                                 0.5 + 0.5 / 1.7320508075688772};
    double w = 0.25 * q->dx * q->dy * q->t;   /* Gauss weight x area x t */
    double Ke[8][8];
    memset(Ke, 0, sizeof Ke);
    for (int gi = 0; gi < 2; gi++)
        for (int gj = 0; gj < 2; gj++) {
            double N[4], Nx[4], Ny[4], B[3][8] = {{0}};
            shape(q, gp[gi], gp[gj], N, Nx, Ny);
            for (int a = 0; a < 4; a++) {
                B[0][2 * a] = Nx[a];
                B[1][2 * a + 1] = Ny[a];
                B[2][2 * a] = Ny[a];
                B[2][2 * a + 1] = Nx[a];
            }
            for (int r = 0; r < 8; r++)
                for (int s = 0; s < 8; s++) {
                    double k = 0;
                    for (int i = 0; i < 3; i++)
                        for (int j = 0; j < 3; j++)
                            k += B[i][r] * D[i][j] * B[j][s];
                    Ke[r][s] += w * k;
                }
        }
    for (int j = 0; j < q->ny; j++)
        for (int i = 0; i < q->nx; i++) {
            int node[4] = {q4_node(q, i, j), q4_node(q, i + 1, j),
                           q4_node(q, i, j + 1), q4_node(q, i + 1, j + 1)};
            for (int r = 0; r < 8; r++)
                for (int s = 0; s < 8; s++) {
                    int R = 2 * node[r / 2] + r % 2, S = 2 * node[s / 2] + s % 2;
                    if (R <= S)
                        KAB(ab, kd, R, S) += Ke[r][s];
                }
        }
    /* fixed dofs: zero row and column, unit diagonal, zero load */
    for (int d = 0; d < n; d++) {
        if (!q->fix[d])
            continue;
        for (int e = d - kd < 0 ? 0 : d - kd; e <= d; e++)
            KAB(ab, kd, e, d) = 0;
        for (int e = d; e <= d + kd && e < n; e++)
            KAB(ab, kd, d, e) = 0;
        KAB(ab, kd, d, d) = 1;
        q->f[d] = 0;
    }
    memcpy(q->u, q->f, sizeof(double) * (size_t)n);
    int info = (int)LAPACKE_dpbsv(LAPACK_COL_MAJOR, 'U', n, kd, 1, ab, kd + 1,
                                  q->u, n);
    free(ab);
    return info;
}
/// [q4_solve]

void q4_displacement(const Q4Model *q, double x, double y, double u[2])
{
    double xi, eta, N[4], Nx[4], Ny[4];
    int node[4];
    locate(q, x, y, &xi, &eta, node);
    shape(q, xi, eta, N, Nx, Ny);
    u[0] = u[1] = 0;
    for (int a = 0; a < 4; a++) {
        u[0] += N[a] * q->u[2 * node[a]];
        u[1] += N[a] * q->u[2 * node[a] + 1];
    }
}

void q4_stress(const Q4Model *q, double x, double y, double s[3])
{
    double xi, eta, N[4], Nx[4], Ny[4], exx = 0, eyy = 0, gxy = 0;
    int node[4];
    locate(q, x, y, &xi, &eta, node);
    shape(q, xi, eta, N, Nx, Ny);
    for (int a = 0; a < 4; a++) {
        double ux = q->u[2 * node[a]], uy = q->u[2 * node[a] + 1];
        exx += Nx[a] * ux;
        eyy += Ny[a] * uy;
        gxy += Ny[a] * ux + Nx[a] * uy;
    }
    double c = q->E / (1 - q->nu * q->nu);
    s[0] = c * (exx + q->nu * eyy);
    s[1] = c * (q->nu * exx + eyy);
    s[2] = c * (1 - q->nu) / 2 * gxy;
}
