/**
 * @file grid_update.c
 * @brief Grid tasks: boundary conditions, nodal velocities and the
 *        momentum update (Tasks 2-4, eq. 4, 29 and 34).
 */
#include <string.h>

#include "step.h"

/// [grid_velocities]
void grid_velocities(Sim *sim)
{
    Grid *g = &sim->grid;
    /* a slot writes only its own values: any number of threads */
#pragma omp parallel for num_threads(sim->threads)
    for (int s = 0; s < g->nslots; s++) {
        unsigned fix = g->fixed[grid_slot_node(g, s)];
        if (fix & GRID_FIX_X)
            g->px[s] = 0.0;
        if (fix & GRID_FIX_Y)
            g->py[s] = 0.0;
        double m = g->m[s];
        g->vx[s] = m > 0.0 ? g->px[s] / m : 0.0;
        g->vy[s] = m > 0.0 ? g->py[s] / m : 0.0;
    }
}
/// [grid_velocities]

/// [grid_momentum_update]
void grid_momentum_update(Sim *sim)
{
    Grid *g = &sim->grid;
    const RunSettings *run = &sim->scene.run;
    double dt = sim->dt, kappa = run->damping;
    double gs = gravity_scale(run, sim->t + 0.5 * dt);  /* mid-step */
    double gx = run->gx * gs, gy = run->gy * gs;
#pragma omp parallel for num_threads(sim->threads)
    for (int s = 0; s < g->nslots; s++) {
        double m = g->m[s];
        if (m <= 0.0) {
            g->vx[s] = g->vy[s] = g->ax[s] = g->ay[s] = 0.0;
            continue;
        }
        unsigned fix = g->fixed[grid_slot_node(g, s)];
        /* eq. 4: internal + external (body force m_i b) - damping */
        double fx = g->fx[s] + m * gx - kappa * g->px[s];
        double fy = g->fy[s] + m * gy - kappa * g->py[s];
        if (fix & GRID_FIX_X)
            fx = 0.0;
        if (fix & GRID_FIX_Y)
            fy = 0.0;
        g->fx[s] = fx;
        g->fy[s] = fy;
        g->px[s] += dt * fx;                            /* eq. 29 */
        g->py[s] += dt * fy;
        g->vx[s] = g->px[s] / m;
        g->vy[s] = g->py[s] / m;
        g->ax[s] = fx / m;
        g->ay[s] = fy / m;
    }
}
/// [grid_momentum_update]

/** After contact at slot @p s: fixed directions, v = p / m, and at Task 4
 *  the force f += (p_new - p_old)/dt and a = f / m. */
static void contact_rederive(Grid *g, int s, int task4, double idt)
{
    unsigned fix = g->fixed[grid_slot_node(g, s)];
    double m = g->m[s];
    if (task4) {                                  /* f = (p_new - p_old)/dt */
        g->fx[s] += (g->px[s] - g->qx[s]) * idt;
        g->fy[s] += (g->py[s] - g->qy[s]) * idt;
    }
    if (fix & GRID_FIX_X)
        g->px[s] = g->fx[s] = 0.0;
    if (fix & GRID_FIX_Y)
        g->py[s] = g->fy[s] = 0.0;
    g->vx[s] = m > 0.0 ? g->px[s] / m : 0.0;
    g->vy[s] = m > 0.0 ? g->py[s] / m : 0.0;
    if (task4) {
        g->ax[s] = m > 0.0 ? g->fx[s] / m : 0.0;
        g->ay[s] = m > 0.0 ? g->fy[s] / m : 0.0;
    }
}

/** Hold every field of @p node at velocity @p v along the directions of
 *  @p fix; at Task 4 (@p task4) with the force that took it from @p v0. */
static void hold_node(Grid *g, const FieldTable *F, int node, unsigned fix,
                      const double v0[2], const double v[2], int task4, double dt)
{
    for (int s = node; s >= 0; s = field_next(F, g, s)) {
        double m = g->m[s];
        if (fix & GRID_FIX_X) {
            g->px[s] = m * v[0];
            g->vx[s] = v[0];
            if (task4) {                              /* f = m dv / dt */
                g->ax[s] = (v[0] - v0[0]) / dt;
                g->fx[s] = m * g->ax[s];
            }
        }
        if (fix & GRID_FIX_Y) {
            g->py[s] = m * v[1];
            g->vy[s] = v[1];
            if (task4) {
                g->ay[s] = (v[1] - v0[1]) / dt;
                g->fy[s] = m * g->ay[s];
            }
        }
    }
}

/// [grid_prescribe]
void grid_prescribe(Sim *sim, Seam seam)
{
    const Scene *sc = &sim->scene;
    if (sim->nmoving == 0 && sc->nheld == 0)
        return;
    Grid *g = &sim->grid;
    const FieldTable *F = &sim->fields;
    int task4 = seam == SEAM_TASK4_CONTACT;
    int start = seam == SEAM_TASK2_HELD || seam == SEAM_TASK2_CONTACT;
    double t0 = sim->t, t = start ? t0 : t0 + sim->dt;
    for (int k = 0; k < sim->nmoving; k++) {          /* moving boundaries */
        const Hold *h = &sc->bc[sim->moving_bc[k]].hold;
        double v0[2], v[2];
        hold_velocity(h, t0, v0);
        hold_velocity(h, t, v);
        hold_node(g, F, sim->moving[k], h->fix, v0, v, task4, sim->dt);
    }
    for (int k = 0; k < sc->nheld; k++) {             /* the nodes of held points */
        const HeldPoints *H = &sc->held[k];
        double v0[2], v[2];
        hold_velocity(&H->hold, t0, v0);
        hold_velocity(&H->hold, t, v);
        for (int j = 0; j < H->count; j++) {   /* every node it reaches */
            Stencil st;
            stencil_of_point(sim, H->points[j], &st);
            for (int a = 0; a < st.n; a++)
                hold_node(g, F, grid_slot_node(g, st.slot[a]), H->hold.fix, v0,
                          v, task4, sim->dt);
        }
    }
}
/// [grid_prescribe]

/// [grid_contact]
int grid_contact(Sim *sim, Seam seam)
{
    if (sim->hooks.seam[seam].n == 0)
        return 0;                                 /* no contact: nothing */
    Grid *g = &sim->grid;
    const FieldTable *F = &sim->fields;
    int task4 = seam == SEAM_TASK4_CONTACT;
    double idt = 1.0 / sim->dt;
    if (!F->first) {                              /* one field: any slot */
        size_t bytes = (size_t)g->nslots * sizeof(double);
        if (task4) {                              /* p before contact */
            memcpy(g->qx, g->px, bytes);
            memcpy(g->qy, g->py, bytes);
        }
        int rc = hooks_run_step(sim, seam);
        for (int s = 0; s < g->nslots && !rc; s++)
            contact_rederive(g, s, task4, idt);
        return rc;
    }
    /* with a field table, contact changes the fields of the nodes that
       have several (the touched nodes); the rest need nothing derived */
    for (int k = 0; k < F->ntouched && task4; k++)
        for (int s = F->touched[k]; s >= 0; s = field_next(F, g, s)) {
            g->qx[s] = g->px[s];
            g->qy[s] = g->py[s];
        }
    int rc = hooks_run_step(sim, seam);
    for (int k = 0; k < F->ntouched && !rc; k++)
        for (int s = F->touched[k]; s >= 0; s = field_next(F, g, s))
            contact_rederive(g, s, task4, idt);
    return rc;
}
/// [grid_contact]
