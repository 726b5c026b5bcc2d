/**
 * @file scene_fig3.c
 * @brief The paper's Fig. 3 (section 3.2): two disks with central cracks
 *        collide and bounce apart, with frictionless crack contact.
 *
 * A reduced run of figures/fig3/cracked_disks.cfg (the collision and the
 * rebound, 12 ms; the figure's grid and CFL) checks, every step and by the
 * cracks' own geometry (crack_watch.h), that no point crosses its own
 * crack's line; that the crack along the impact axis opens (mode I) while
 * the faces of the crack across it touch; that total momentum stays at its
 * start value to round-off; that contact does no work (frictionless); and
 * it prints the total energy drift, which must stay below the 2.6 % that
 * the reference CRAMP code gains on this scene. The same run with contact
 * switched off lets the right crack's faces cross: the watch can fail.
 *
 * FIG3_OUT=dir runs the full scene instead and writes what `make fig3`
 * draws: openings.csv (time, both openings, contact nodes, energy) and
 * four snapshots snap_K.csv (x, y, sigma_xx, sigma_yy) with cracks_K.csv,
 * at 0, 7, 12 and 18 ms (the paper's frames A-D) or at the four times
 * FIG3_TIMES="t0 t1 t2 t3" gives.
 */
#include "fig3.h"

static const char *const reduced[] = {"run.time=12.0", NULL};

static void collision_with_contact(void **state)
{
    (void)state;
    Fig3Run r = run_fig3(1, NULL, reduced);
    fig3_print("frictionless contact", &r);
    double h = 1.0;                          /* the scene's cell size (mm) */
    assert_int_equal(r.crossings[0], 0);     /* no point crosses its crack */
    assert_int_equal(r.crossings[1], 0);
    assert_true(r.open_max[0] > 0.5 * h);    /* mode I: the left crack opens */
    /* the right crack is closed then: its faces' points no further apart
       than at the start, give or take a tenth of a cell */
    assert_true(fabs(r.right_open_at_left_max) < 0.1 * h);
    assert_true(r.contact_nodes > 0);
    assert_true(r.dp < 1e-12);               /* momentum: round-off */
    assert_true(fabs(r.work) < 1e-12);       /* frictionless: no work */
    assert_true(r.drift < 0.026);            /* the reference code: 2.6-3.3 % */
}

static void collision_without_contact(void **state)
{
    (void)state;
    Fig3Run r = run_fig3(0, NULL, reduced);
    fig3_print("contact off", &r);
    assert_true(r.crossings[1] > 0);         /* the watch sees faces cross */
    assert_int_equal(r.contact_nodes, 0);
}

int main(void)
{
    const char *out = getenv("FIG3_OUT");
    if (out) {
        Fig3Run r = run_fig3(1, out, NULL);
        fig3_print("full run, frictionless contact", &r);
        return 0;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(collision_with_contact),
        cmocka_unit_test(collision_without_contact),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
