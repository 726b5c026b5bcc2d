/**
 * @file xefg_step.c
 * @brief One explicit central-difference step of M_L a = f_ext - f_int
 *        (eq. 31; xefg.md 2.5): the method "xefg". It is written as two
 *        half kicks around the drift (velocity Verlet), which is the same
 *        central difference with velocities at whole steps as well, so that
 *        the energy of history.csv is taken at one instant.
 */
#include <math.h>

#include "cohesive.h"
#include "growth.h"
#include "step.h"
#include "xefg.h"
#include "xefg_gather.h"

/** External forces at time @p t: the scene's point loads through the
 *  loaded nodes' rows, and gravity through int rho psi dV. */
static void external_force(const Xefg *x, const Sim *sim, double t, double *f)
{
    const Scene *sc = &sim->scene;
    const ShapeRows *R = &x->at_node;
    double gs = gravity_scale(&sc->run, t);
    double gx = sc->run.gx * gs, gy = sc->run.gy * gs;
    if (gx != 0.0 || gy != 0.0)
        for (int q = 0; q < x->ndof; q++) {
            f[2 * q] += x->load[q] * gx;
            f[2 * q + 1] += x->load[q] * gy;
        }
    for (int l = 0; l < sc->nloads; l++) {
        const Load *L = &sc->loads[l];
        double fx, fy;
        load_point_force(L, t, &fx, &fy);
        for (int j = 0; j < L->count; j++) {
            int I = L->points[j];
            for (int e = R->start[I]; e < R->start[I + 1]; e++) {
                f[2 * R->dof[e]] += R->N[e] * fx;
                f[2 * R->dof[e] + 1] += R->N[e] * fy;
            }
        }
    }
}

/** The first parameter (lowest index) whose velocity is not finite, or
 *  else the first Gauss point whose stress is not (on the threads when
 *  the sums are: the lowest index, whichever thread met it).
 *  @return 0 or -1. */
static int check_finite(const Xefg *x, Sim *sim)
{
    int qbad = x->ndof, gbad = x->ngauss;
#pragma omp parallel if (x->gather) num_threads(sim->threads)
    {                                               /* one region, two loops */
#pragma omp for schedule(static) reduction(min : qbad)
        for (int q = 0; q < x->ndof; q++)
            if (!isfinite(x->v[2 * q]) || !isfinite(x->v[2 * q + 1]))
                qbad = q < qbad ? q : qbad;
#pragma omp for schedule(static) reduction(min : gbad)
        for (int g = 0; g < x->ngauss; g++)
            for (int k = 0; k < 3; k++)
                if (!isfinite(x->gs[3 * g + k]))
                    gbad = g < gbad ? g : gbad;
    }
    if (qbad < x->ndof) {
        const double *v = x->v + 2 * qbad;
        return step_fail(sim, x->dof_node[qbad], "velocity",
                         isfinite(v[0]) ? v[1] : v[0]);
    }
    for (int k = 0; gbad < x->ngauss && k < 3; k++)
        if (!isfinite(x->gs[3 * gbad + k]))
            return step_fail(sim, x->gnode[gbad], "stress", x->gs[3 * gbad + k]);
    return 0;
}

/** a = M^-1 (f_ext(t) - f_int), the parameters' accelerations before
 *  damping, from the Gauss points' stresses now. */
void xefg_accelerations(Xefg *x, const Sim *sim, double t)
{
    xefg_internal_force(x, x->gs, x->a);
    if (x->coh)
        cohesive_force(x->coh, x->u, x->a, 1);
    xefg_accelerations_from(x, sim, t);
}

void xefg_accelerations_from(Xefg *x, const Sim *sim, double t)
{
    double *a = x->a;
    for (int k = 0; k < 2 * x->ndof; k++)
        a[k] = -a[k];
    external_force(x, sim, t, a);
    for (int q = 0; q < x->ndof; q++) {
        a[2 * q] /= x->mass[q];
        a[2 * q + 1] /= x->mass[q];
    }
}

/** The points, moved with the parameters, must stay on the grid that the
 *  outputs (and MPM) use. @return 0 or -1 with the first that left. */
static int check_in_grid(Sim *sim)
{
    const Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    double xmax = g->ox + g->ncx * g->dx, ymax = g->oy + g->ncy * g->dy;
    for (int p = 0; p < P->n; p++) {
        if (!(P->x[p] >= g->ox && P->x[p] < xmax))
            return step_fail(sim, p, "position x (left the grid)", P->x[p]);
        if (!(P->y[p] >= g->oy && P->y[p] < ymax))
            return step_fail(sim, p, "position y (left the grid)", P->y[p]);
    }
    return 0;
}

/** A half kick of a velocity component @p v: v + dt/2 (a - kappa v). */
static inline double kicked(double v, double a, double dt, double kappa)
{
    return v + 0.5 * dt * (a - kappa * v);
}

/** The energy the damping -kappa M v takes out of a component of mass
 *  @p m in a half kick from @p v to @p v1: its kinetic energy changes by
 *  its mean velocity times the impulse, and the damping's share of that
 *  impulse is -kappa v dt / 2 (the split is exact: the change is linear in
 *  the force). */
static inline double damping_term(double m, double v, double v1, double dt,
                                  double kappa)
{
    return m * 0.5 * (v + v1) * kappa * v * 0.5 * dt;
}

/** The half kick v += dt/2 (a - kappa M v) of every parameter, and the
 *  energy the damping takes in it (kappa != 0), summed in the order of
 *  the components: the same bits on any number of threads. On threads
 *  (a gather) each component's term goes to scratch in the kick's loop
 *  and is summed after it; on one, a pass before the kick sums them. */
static double kick(Xefg *x, const Sim *sim, double dt, double kappa)
{
    double *v = x->v, *t = x->gather ? x->gather->ws : NULL, w = 0.0;
    const double *a = x->a;
    int n2 = 2 * x->ndof;
    if (!t) {                                       /* one thread */
        for (int k = 0; kappa != 0.0 && k < n2; k++)
            w += damping_term(x->mass[k / 2], v[k], kicked(v[k], a[k], dt, kappa),
                              dt, kappa);
        for (int k = 0; k < n2; k++)
            v[k] = kicked(v[k], a[k], dt, kappa);
        return w;
    }
#pragma omp parallel for num_threads(sim->threads) schedule(static)
    for (int k = 0; k < n2; k++) {
        double v1 = kicked(v[k], a[k], dt, kappa);
        t[k] = damping_term(x->mass[k / 2], v[k], v1, dt, kappa);
        v[k] = v1;
    }
    for (int k = 0; kappa != 0.0 && k < n2; k++)
        w += t[k];
    return w;
}

/// [xefg_step]
int xefg_step(Sim *sim)
{
    Xefg *x = xefg_of(sim);
    double dt = sim->dt, kappa = sim->scene.run.damping;
    double *v = x->v, *a = x->a, *du = x->f;    /* each k its own: threads */
    int n2 = 2 * x->ndof;
    x->w_damped += kick(x, sim, dt, kappa);         /* v(t + dt/2) */
    xefg_constraints_apply(x, sim->t + 0.5 * dt);   /* held velocities */
#pragma omp parallel for if (x->gather) num_threads(sim->threads) schedule(static)
    for (int k = 0; k < n2; k++) {                  /* u(t + dt) */
        du[k] = dt * v[k];
        x->u[k] += du[k];
    }
    xefg_update_and_force(x, sim, du, a);           /* sigma, f_int */
    xefg_accelerations_from(x, sim, sim->t + dt);   /* a(t + dt) */
    x->w_damped += kick(x, sim, dt, kappa);         /* v(t + dt) */
    xefg_constraints_apply(x, sim->t + dt);
    if (check_finite(x, sim))
        return -1;
    xefg_to_points(x, sim);
    if (check_in_grid(sim))
        return -1;
    sim->t += dt;
    sim->step++;
    if (x->grow && growth_after_step(sim, x, x->grow))  /* tips that grow */
        return -1;
    xefg_gather_refresh(x);                         /* rows that changed */
    return 0;
}
/// [xefg_step]
