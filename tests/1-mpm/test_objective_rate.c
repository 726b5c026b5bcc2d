/**
 * @file test_objective_rate.c
 * @brief A body's initial velocity field and stress, and the objective
 *        stress rate (run.stress_rate = "jaumann") against the paper's
 *        unrotated update.
 *
 * Initial conditions.  A point at x gets v = v0 + L (x - c), with an
 * angular velocity w adding [0 -w; w 0] to L, exactly (one multiply-add
 * per term: 1e-15 relative); a body's initial stress s0 gets the strain
 * e0 = C^-1 s0 of its law, so that C e0 gives s0 back to round-off.
 *
 * Rigid rotation.  Every node gets the velocity w x (x_i - c) of a rigid
 * spin, and the stress update is called n times with points held: a
 * rotation of w n dt.  Bilinear shape functions reproduce a linear field,
 * so the velocity gradient is the spin W exactly (up to round-off) and its
 * symmetric part, the strain increment, vanishes.  The unrotated update
 * then leaves the stress as it was; an objective rate must rotate it with
 * the body: s = R s0 R^T, R the rotation by theta = w n dt.  Our rotation
 * (I - W dt/2)^-1 (I + W dt/2) turns by 2 atan(w dt / 2) = w dt - (w dt)^3
 * / 12 + ..., so after n steps the angle is short by theta (w dt)^2 / 12; a
 * component of the turned stress changes with the angle at most at 2 r per
 * radian (r: the radius of Mohr's circle), so each is off by at most 2 r
 * theta (w dt)^2 / 12: we allow twice it, plus 1e-13 |s0| a step of
 * round-off.  At 90 degrees a symmetric tensor turned either way is the
 * same, so a state with shear turned by 60 degrees checks the sense.
 */
#include <stdio.h>
#include <stdlib.h>

#include "step.h"
#include "testkit.h"

#define W 0.75      /* angular velocity (rad/ms) */
#define CX 3.0      /* centre of the spin */
#define CY 2.5
#define QUARTER 1.5707963267948966  /* pi / 2 */

/** A block 4 x 3 mm holding stress (sx, sy, sxy), spinning at W about
 *  (CX, CY) on top of a translation, with the given stress rate. */
static Sim *spinning_block(const char *rate, double sx, double sy, double sxy)
{
    char text[2048];
    snprintf(text, sizeof text,
        "grid = { origin = [-2.0, -2.0]; cells = [10, 9]; cell_size = [1.0, 1.0]; };\n"
        "run = { time = 1.0; cfl = 0.5; stress_rate = \"%s\"; snapshots = 0; };\n"
        "materials = ( { name = \"m\"; E = 1000.0; nu = 0.3; rho = 1.0e-3; } );\n"
        "bodies = ( { name = \"block\"; material = \"m\"; velocity = [0.25, -0.5];\n"
        "  angular_velocity = %#.17g; center = [%#.17g, %#.17g];\n"
        "  stress = [%#.17g, %#.17g, %#.17g]; points_per_cell = 2;\n"
        "  rectangle = { min = [1.0, 1.0]; max = [5.0, 4.0]; }; } );\n",
        rate, W, CX, CY, sx, sy, sxy);
    return tk_load(text);
}

/** Velocities are the rigid field; strains carry the stress (C e0 = s0). */
static void initial_velocity_and_stress(void **state)
{
    (void)state;
    Sim *sim = spinning_block("unrotated", 3.0, -1.0, 2.0);
    const Particles *P = &sim->pts;
    const Material *m = &sim->scene.mat[0];
    assert_int_equal(P->n, 48);
    for (int p = 0; p < P->n; p++) {
        assert_close(P->vx[p], 0.25 - W * (P->y[p] - CY), 1e-15);
        assert_close(P->vy[p], -0.5 + W * (P->x[p] - CX), 1e-15);
        assert_close(P->sxx[p], 3.0, 0.0);
        double s[3] = {0, 0, 0};
        elastic_stress_increment(m, P->exx[p], P->eyy[p], P->exy[p], s);
        assert_close(s[0], 3.0, 1e-14);
        assert_close(s[1], -1.0, 1e-14);
        assert_close(s[2], 2.0, 1e-14);
    }
    tk_free(sim);
}

/** Hold the points, give every node the rigid spin's velocity and update
 *  the stress @p n times over @p dt; return the largest departure of any
 *  point's stress from s0 rotated by W n dt. */
static double spin_error(Sim *sim, int n, double dt, const double s0[3],
                         double *strain_energy_change)
{
    Grid *g = &sim->grid;
    Particles *P = &sim->pts;
    double u0 = 0.0, u1 = 0.0;
    for (int p = 0; p < P->n; p++)
        u0 += material_energy_density(P->sxx[p], P->syy[p], P->sxy[p],
                                      P->exx[p], P->eyy[p], P->exy[p]);
    grid_clear(g, 1);
    locate_points(sim);
    for (int s = 0; s < g->nslots; s++) {
        int node = grid_slot_node(g, s);
        g->vx[s] = -W * (grid_node_y(g, node) - CY);
        g->vy[s] = W * (grid_node_x(g, node) - CX);
    }
    for (int k = 0; k < n; k++)
        assert_int_equal(update_stress(sim, dt), 0);
    double th = W * n * dt, c = cos(th), sn = sin(th), worst = 0.0;
    double want[3] = {
        c * c * s0[0] - 2.0 * c * sn * s0[2] + sn * sn * s0[1],
        sn * sn * s0[0] + 2.0 * c * sn * s0[2] + c * c * s0[1],
        c * sn * (s0[0] - s0[1]) + (c * c - sn * sn) * s0[2]};
    for (int p = 0; p < P->n; p++) {
        worst = fmax(worst, fabs(P->sxx[p] - want[0]));
        worst = fmax(worst, fabs(P->syy[p] - want[1]));
        worst = fmax(worst, fabs(P->sxy[p] - want[2]));
        u1 += material_energy_density(P->sxx[p], P->syy[p], P->sxy[p],
                                      P->exx[p], P->eyy[p], P->exy[p]);
    }
    *strain_energy_change = fabs(u1 - u0) / u0;
    return worst;
}

/** The bound of the file's comment for stress @p s0 turned by @p th in
 *  steps of w dt = @p wdt, over @p n steps. */
static double rotation_bound(const double s0[3], double th, double wdt, int n)
{
    double r = sqrt(0.25 * (s0[0] - s0[1]) * (s0[0] - s0[1]) + s0[2] * s0[2]);
    double mag = fmax(fabs(s0[0]), fmax(fabs(s0[1]), fabs(s0[2])));
    return 2.0 * 2.0 * r * th * wdt * wdt / 12.0 + 1e-13 * mag * n;
}

/** A pre-stressed block turned by 90 degrees: with the objective rate its
 *  stress turns with it (xx becomes yy); with the paper's update it stays. */
static void rotated_prestressed_block(void **state)
{
    (void)state;
    const double s0[3] = {3.0, 0.0, 0.0}, mag = 3.0;
    const int n = 1000;
    const double dt = QUARTER / (W * n);          /* 90 degrees in n steps */
    double du;
    Sim *sim = spinning_block("jaumann", s0[0], s0[1], s0[2]);
    double err = spin_error(sim, n, dt, s0, &du);
    double bound = rotation_bound(s0, QUARTER, W * dt, n);
    printf("  jaumann: stress after 90 degrees off R s0 R^T by %.3g MPa "
           "(bound %.3g); syy %.15g of sxx0 %.15g; strain energy changed %.2g\n",
           err, bound, sim->pts.syy[0], s0[0], du);
    assert_true(err <= bound);
    assert_true(du <= 1e-12);                           /* an invariant */
    tk_free(sim);

    sim = spinning_block("unrotated", s0[0], s0[1], s0[2]);
    err = spin_error(sim, n, dt, s0, &du);
    double stays = 0.0;
    for (int p = 0; p < sim->pts.n; p++)
        stays = fmax(stays, fabs(sim->pts.sxx[p] - s0[0]) + fabs(sim->pts.syy[p]) +
                            fabs(sim->pts.sxy[p]));
    printf("  unrotated: off R s0 R^T by %.3g MPa; off s0 by %.3g MPa\n", err, stays);
    assert_true(stays <= 1e-13 * mag * n);              /* the paper's: unchanged */
    assert_true(err >= 0.99 * mag);                     /* xx and yy each off by s0 */
    tk_free(sim);
}

/** Turned by 60 degrees, a state with shear: the sense of the rotation
 *  shows (a symmetric tensor turned by +90 and -90 degrees is the same). */
static void sense_of_rotation(void **state)
{
    (void)state;
    const double s0[3] = {3.0, -1.0, 2.0};
    const int n = 1000;
    const double th = QUARTER * 2.0 / 3.0, dt = th / (W * n);
    double du;
    Sim *sim = spinning_block("jaumann", s0[0], s0[1], s0[2]);
    double err = spin_error(sim, n, dt, s0, &du);
    double bound = rotation_bound(s0, th, W * dt, n);
    printf("  jaumann, 60 degrees: off R s0 R^T by %.3g MPa (bound %.3g)\n", err, bound);
    assert_true(err <= bound);
    assert_true(du <= 1e-12);
    tk_free(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(initial_velocity_and_stress),
        cmocka_unit_test(rotated_prestressed_block),
        cmocka_unit_test(sense_of_rotation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
