/**
 * @file apic.c
 * @brief APIC's two transfers (Jiang et al. 2015, 2017): point to grid
 *        with the point's affine velocity, grid to point keeping it.
 *
 * The affine part is stored as B_p = sum_i S_ip v_i (x_i - x_p)^T, taken
 * at Task 5, and turned into C_p = B_p D_p^-1 at the next scatter with the
 * D_p of the point's new position: the 2017 paper's choice, under which
 * the angular momentum sum m_p (x_p x v_p) + m_p (B_yx - B_xy) is carried
 * exactly from step to step (a symmetric stress exerts no torque on the
 * grid). Positions x_i - x_p are those of Task 0, from the stencil's cell.
 */
#include "apic.h"

#include "step.h"
#include "strip_scatter.h"

/** x_i - x_p along x and y for node @p node of a point at Task 0's
 *  position (cell @p cell, local @p xi, @p eta). */
static inline void offset(const Grid *g, int cell, double xi, double eta,
                          int node, double d[2])
{
    d[0] = (node % g->nnx - cell % g->nnx - xi) * g->dx;
    d[1] = (node / g->nnx - cell / g->nnx - eta) * g->dy;
}

void apic_inertia(const Grid *g, const Particles *P, int p, const Stencil *st,
                  double D[3])
{
    D[0] = D[1] = D[2] = 0.0;
    for (int a = 0; a < st->n; a++) {
        double d[2];
        offset(g, P->cell[p], P->xi[p], P->eta[p], grid_slot_node(g, st->slot[a]), d);
        D[0] += st->S[a] * d[0] * d[0];
        D[1] += st->S[a] * d[0] * d[1];
        D[2] += st->S[a] * d[1] * d[1];
    }
}

/** The (pseudo-)inverse of the symmetric D = (xx, xy, yy). Only linear
 *  functions make it singular: a point on a grid line, whose nodes all lie
 *  on that line; the rank-one inverse D / tr(D)^2 drops the direction no
 *  node reaches. */
static void inverse(const double D[3], double I[3])
{
    double det = D[0] * D[2] - D[1] * D[1], tr = D[0] + D[2];
    if (det > 1e-12 * tr * tr) {
        I[0] = D[2] / det;
        I[1] = -D[1] / det;
        I[2] = D[0] / det;
    } else {
        double s = tr > 0.0 ? 1.0 / (tr * tr) : 0.0;
        I[0] = D[0] * s;
        I[1] = D[1] * s;
        I[2] = D[2] * s;
    }
}

/// [apic_scatter]
/** The nodes of @p own (NULL: all) get m_p S_ip C_p (x_i - x_p), with
 *  @p mc = m_p C_p (xx, xy, yx, yy). Inlined twice, so that the one-thread
 *  loop makes no test. */
static inline __attribute__((always_inline)) void
add_affine(const Particles *P, int p, const Stencil *st, Grid *g,
           const double mc[4], const Owned *own)
{
    int cell = P->cell[p];
    double xi = P->xi[p], eta = P->eta[p];
    double cxx = mc[0], cxy = mc[1], cyx = mc[2], cyy = mc[3];
    for (int a = 0; a < st->n; a++) {
        int s = st->slot[a];
        double d[2];
        if (!owns(g, own, s))
            continue;                           /* another thread's node */
        offset(g, cell, xi, eta, grid_slot_node(g, s), d);
        g->px[s] += st->S[a] * (cxx * d[0] + cxy * d[1]);
        g->py[s] += st->S[a] * (cyx * d[0] + cyy * d[1]);
    }
}

void apic_scatter(const Sim *sim, int p, const Stencil *st, Grid *g,
                  const Owned *own)
{
    const Particles *P = &sim->pts;
    const Apic *A = (const Apic *)sim->scene.run.transfer;
    const double *B = &A->B[4 * p];
    double D[3], I[3];
    apic_inertia(g, P, p, st, D);
    inverse(D, I);
    double m = P->m[p];                         /* m_p C_p = m_p B_p D_p^-1 */
    double mc[4] = {m * (B[0] * I[0] + B[1] * I[1]), m * (B[0] * I[1] + B[1] * I[2]),
                    m * (B[2] * I[0] + B[3] * I[1]), m * (B[2] * I[1] + B[3] * I[2])};
    if (own)                                    /* a thread's strip */
        add_affine(P, p, st, g, mc, own);
    else
        add_affine(P, p, st, g, mc, NULL);
}
/// [apic_scatter]

/// [apic_gather]
void apic_gather(Sim *sim, int p, const Stencil *st)
{
    Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    Apic *A = (Apic *)sim->scene.run.transfer;
    double vx = 0, vy = 0, B[4] = {0, 0, 0, 0};
    for (int a = 0; a < st->n; a++) {
        int s = st->slot[a];
        double d[2], ux = st->S[a] * g->vx[s], uy = st->S[a] * g->vy[s];
        offset(g, P->cell[p], P->xi[p], P->eta[p], grid_slot_node(g, s), d);
        vx += ux;
        vy += uy;
        B[0] += ux * d[0];
        B[1] += ux * d[1];
        B[2] += uy * d[0];
        B[3] += uy * d[1];
    }
    P->vx[p] = vx;                  /* PIC's velocity, not eq. 30's v + dt a */
    P->vy[p] = vy;
    for (int k = 0; k < 4; k++)
        A->B[4 * p + k] = B[k];
}
/// [apic_gather]

void apic_set_gradient(Sim *sim, int p, const double L[4])
{
    Apic *A = (Apic *)sim->scene.run.transfer;
    Stencil st;
    double D[3];
    stencil_of_point(sim, p, &st);
    apic_inertia(&sim->grid, &sim->pts, p, &st, D);
    double *B = &A->B[4 * p];
    B[0] = L[0] * D[0] + L[1] * D[1];
    B[1] = L[0] * D[1] + L[1] * D[2];
    B[2] = L[2] * D[0] + L[3] * D[1];
    B[3] = L[2] * D[1] + L[3] * D[2];
}

double apic_angular_momentum(const Sim *sim)
{
    const Particles *P = &sim->pts;
    const Apic *A = (const Apic *)sim->scene.run.transfer;
    double l = 0.0;
    for (int p = 0; p < P->n; p++)
        l += P->m[p] * (P->x[p] * P->vy[p] - P->y[p] * P->vx[p] +
                        A->B[4 * p + 2] - A->B[4 * p + 1]);
    return l;
}
