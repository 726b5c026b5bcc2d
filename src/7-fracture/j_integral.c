/**
 * @file j_integral.c
 * @brief The dynamic J-integral at a CRAMP crack tip as a domain integral
 *        over the material points (chapter 7; Guo and Nairn, CMES 6 (2004)
 *        295-308, whose contour form this is the equivalent of).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cracks.h"
#include "j_integral.h"
#include "stencil.h"

int j_integral_fit(JState *S, int slots)
{
    if (slots <= S->cap)
        return 0;
    int cap = S->cap > 0 ? S->cap : slots;
    while (cap < slots)
        cap = cap > (1 << 29) ? slots : 2 * cap;
    double *a[3] = {S->mux, S->muy, S->m};
    for (int k = 0; k < 3; k++) {
        double *n = realloc(a[k], sizeof(double) * (size_t)cap);
        if (!n)
            return -1;
        a[k] = n;
        if (k == 0)
            S->mux = n;
        else if (k == 1)
            S->muy = n;
        else
            S->m = n;
    }
    S->cap = cap;
    return 0;
}

void j_integral_tips(const Sim *sim, JState *S)
{
    const Cracks *C = cracks_of(sim);
    for (int t = 0; t < S->ntips; t++) {
        JTip *T = &S->tip[t];
        const Crack *c = &C->crack[T->crack];
        int i = T->end ? c->n - 1 : 0, b = T->end ? c->n - 2 : 1;
        double ex = c->x[i] - c->x[b], ey = c->y[i] - c->y[b];
        double len = sqrt(ex * ex + ey * ey);
        T->x = c->x[i];
        T->y = c->y[i];
        T->ex = ex / len;                /* ahead of the tip: x1 */
        T->ey = ey / len;
    }
}

/** The widest contour of tip @p T, in cells. */
static int widest(const JState *S, const JTip *T)
{
    const JSettings *j = &S->set[T->crack];
    int w = 0;
    for (int m = 0; m < j->ncontours; m++)
        w = j->contour[m] > w ? j->contour[m] : w;
    return w;
}

/** Is (x, y) within @p cells cells (in x and in y) of tip @p T? */
static int within(const Grid *g, const JTip *T, double x, double y, double cells)
{
    return fabs(x - T->x) < cells * g->dx && fabs(y - T->y) < cells * g->dy;
}

/// [j_nodal_displacement]
/** Pass 1: the displacement of each field slot near a tip, extrapolated
 *  from the points as the momentum is (eq. 26): u_i = sum m_p S_ip u_p /
 *  sum m_p S_ip, each pair in its own field (Task 1's slots), so that the
 *  two faces of the crack keep their own displacements. The points within
 *  two cells beyond the widest domain reach every node a domain point
 *  reads. */
static void nodal_displacement(const Sim *sim, JState *S)
{
    const Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    memset(S->mux, 0, sizeof(double) * (size_t)g->nslots);
    memset(S->muy, 0, sizeof(double) * (size_t)g->nslots);
    memset(S->m, 0, sizeof(double) * (size_t)g->nslots);
    for (int p = 0; p < P->n; p++) {
        int near = 0;
        for (int t = 0; t < S->ntips && !near; t++)
            near = within(g, &S->tip[t], P->x[p], P->y[p],
                          widest(S, &S->tip[t]) + 2.0);
        if (!near)
            continue;
        Stencil st;
        stencil_of_point(sim, p, &st);
        double ux = P->x[p] - S->X[p], uy = P->y[p] - S->Y[p];
        for (int a = 0; a < STENCIL_NODES; a++) {
            int s = st.slot[a];
            double w = P->m[p] * st.S[a];
            S->m[s] += w;
            S->mux[s] += w * ux;
            S->muy[s] += w * uy;
        }
    }
}
/// [j_nodal_displacement]

void j_point_gradients(const Sim *sim, const JState *S, int p, JPoint *jp)
{
    const Grid *g = &sim->grid;
    Stencil st;
    stencil_of_point(sim, p, &st);
    memset(jp, 0, sizeof *jp);
    for (int a = 0; a < STENCIL_NODES; a++) {
        int s = st.slot[a];
        if (!(S->m[s] > 0.0))
            continue;
        double ux = S->mux[s] / S->m[s], uy = S->muy[s] / S->m[s];
        double G[2] = {st.Gx[a], st.Gy[a]};
        for (int k = 0; k < 2; k++) {
            jp->D[0][k] += ux * G[k];
            jp->D[1][k] += uy * G[k];
            jp->L[0][k] += g->vx[s] * G[k];
            jp->L[1][k] += g->vy[s] * G[k];
        }
        jp->a[0] += st.S[a] * g->ax[s];
        jp->a[1] += st.S[a] * g->ay[s];
    }
}

double j_strain_energy(const Particles *P, int p)
{
    return 0.5 * (P->sxx[p] * P->exx[p] + P->syy[p] * P->eyy[p] +
                  2.0 * P->sxy[p] * P->exy[p]);   /* linear elastic */
}

/// [j_weight]
/* The weight: 1 within c - 1 cells, 0 from c cells on, linear across the
 * ring between in the "square distance" max(|x - x_t| / c dx, |y - y_t| /
 * c dy). */
double j_weight(const Grid *g, const JTip *T, int c, double x, double y,
                     double dq[2])
{
    double sx = fabs(x - T->x) / (c * g->dx), sy = fabs(y - T->y) / (c * g->dy);
    double s = fmax(sx, sy), q = c * (1.0 - s);
    dq[0] = dq[1] = 0.0;
    if (q <= 0.0)
        return 0.0;
    if (q >= 1.0)
        return 1.0;
    if (sx >= sy)                        /* q = c (1 - s): dq = -c ds */
        dq[0] = -copysign(1.0 / g->dx, x - T->x);
    else
        dq[1] = -copysign(1.0 / g->dy, y - T->y);
    return q;
}
/// [j_weight]

/** The material of the body that tip @p T lies in (the first such body;
 *  material 0 if none). */
static int tip_material(const Sim *sim, const JTip *T)
{
    const Scene *sc = &sim->scene;
    for (int b = 0; b < sc->nbodies; b++)
        if (shape_contains(&sc->bodies[b].shape, T->x, T->y))
            return sc->bodies[b].material;
    return 0;
}

/// [j_integral_evaluate]
int j_integral_evaluate(const Sim *sim, JState *S)
{
    const Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    const Scene *sc = &sim->scene;
    if (j_integral_fit(S, g->nslots))
        return -1;
    const Cracks *C = cracks_of(sim);
    j_integral_tips(sim, S);
    for (int t = 0; t < S->ntips; t++)
        j_tip_kink(g, &C->crack[S->tip[t].crack], &S->tip[t],
                   widest(S, &S->tip[t]));
    nodal_displacement(sim, S);
    double kappa = sc->run.damping;
    int strain = sc->run.plane == PLANE_STRAIN;
    for (int t = 0; t < S->ntips; t++) {
        memset(S->tip[t].J, 0, sizeof S->tip[t].J);
        memset(S->tip[t].KI, 0, sizeof S->tip[t].KI);   /* M^(I) until the end */
        memset(S->tip[t].KII, 0, sizeof S->tip[t].KII);
        memset(S->tip[t].Jface, 0, sizeof S->tip[t].Jface);
        memset(S->tip[t].KIface, 0, sizeof S->tip[t].KIface);
        memset(S->tip[t].KIIface, 0, sizeof S->tip[t].KIIface);
    }
    for (int p = 0; p < P->n; p++) {
        int gradients = 0;
        JPoint jp;
        double thick = sc->bodies[P->body[p]].thickness;
        double A = P->vol[p] / thick, mA = P->m[p] / thick; /* per thickness */
        double s[2][2] = {{P->sxx[p], P->sxy[p]}, {P->sxy[p], P->syy[p]}};
        double W = j_strain_energy(P, p);
        double v[2] = {P->vx[p], P->vy[p]};
        double T2 = 0.5 * (v[0] * v[0] + v[1] * v[1]);    /* T / rho */
        for (int t = 0; t < S->ntips; t++) {
            JTip *T = &S->tip[t];
            const JSettings *j = &S->set[T->crack];
            if (!within(g, T, P->x[p], P->y[p], widest(S, T)))
                continue;
            if (!gradients) {
                j_point_gradients(sim, S, p, &jp);
                gradients = 1;
            }
            double e[2] = {T->ex, T->ey};
            double d[2], ve = 0.0;       /* d_i = u_i,1 in the tip's frame */
            for (int i = 0; i < 2; i++) {
                d[i] = jp.D[i][0] * e[0] + jp.D[i][1] * e[1];
                ve += v[i] * (jp.L[i][0] * e[0] + jp.L[i][1] * e[1]);
            }
            /* inertia: sigma_ij,j = rho (a_i + kappa v_i), the damping of
               eq. 4 being a body force; rho v_i v_i,1 = T,1 */
            double inertia = (jp.a[0] + kappa * v[0]) * d[0] +
                             (jp.a[1] + kappa * v[1]) * d[1] - ve;
            /* the auxiliary states (mode I, II) and what of them does not
               depend on the contour: u^m_i,1, sigma_ij eps^m_ij and the
               inertia (a_i + kappa v_i) u^m_i,1 */
            double sa[2][2][2], dua[2][2][2], da[2][2], W12[2], ina[2];
            k_auxiliary(T, &C->crack[T->crack], &sc->mat[P->mat[p]], strain,
                        P->x[p], P->y[p], sa, dua);
            for (int k = 0; k < 2; k++) {
                W12[k] = ina[k] = 0.0;
                for (int i = 0; i < 2; i++) {
                    da[k][i] = dua[k][i][0] * e[0] + dua[k][i][1] * e[1];
                    ina[k] += (jp.a[i] + kappa * v[i]) * da[k][i];
                    for (int l = 0; l < 2; l++)  /* eps^m = sym(du^m) */
                        W12[k] += s[i][l] * 0.5 * (dua[k][i][l] + dua[k][l][i]);
                }
            }
            for (int m = 0; m < j->ncontours; m++) {
                double dq[2];
                double q = j_weight(g, T, j->contour[m], P->x[p], P->y[p], dq);
                if (q == 0.0)
                    continue;
                double sdq = 0.0;        /* sigma_ij u_i,1 q_,j */
                for (int i = 0; i < 2; i++)
                    sdq += d[i] * (s[i][0] * dq[0] + s[i][1] * dq[1]);
                double edq = e[0] * dq[0] + e[1] * dq[1];  /* delta_1j q_,j */
                T->J[m] += A * (sdq - W * edq) - mA * T2 * edq + mA * inertia * q;
                double M[2];             /* the interaction integrals */
                for (int k = 0; k < 2; k++) {
                    double sum = -W12[k] * edq;
                    for (int i = 0; i < 2; i++)
                        sum += da[k][i] * (s[i][0] * dq[0] + s[i][1] * dq[1]) +
                             d[i] * (sa[k][i][0] * dq[0] + sa[k][i][1] * dq[1]);
                    M[k] = A * sum + mA * ina[k] * q;
                }
                T->KI[m] += M[0];
                T->KII[m] += M[1];
            }
        }
    }
    /* the faces behind a kink: their terms (j_faces.c) */
    for (int t = 0; t < S->ntips; t++)
        if (S->tip[t].kink)
            j_face_terms(sim, S, &S->tip[t]);
    /* K_m = E' M^(m) / 2 (Irwin: M^(m) = 2 K_m / E'), E' of the material
       at the tip (the body the tip lies in; one material about it) */
    for (int t = 0; t < S->ntips; t++) {
        JTip *T = &S->tip[t];
        const Material *mt = &sc->mat[tip_material(sim, T)];
        double Ep = strain ? mt->E / (1.0 - mt->nu * mt->nu) : mt->E;
        for (int m = 0; m < S->set[T->crack].ncontours; m++) {
            T->KI[m] *= 0.5 * Ep;
            T->KII[m] *= 0.5 * Ep;
            T->KIface[m] *= 0.5 * Ep;
            T->KIIface[m] *= 0.5 * Ep;
        }
    }
    return 0;
}
/// [j_integral_evaluate]
