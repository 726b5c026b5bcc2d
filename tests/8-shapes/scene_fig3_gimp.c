/**
 * @file scene_fig3_gimp.c
 * @brief The paper's Fig. 3 with uGIMP beside linear (chapter 8, "Contact
 *        with GIMP"): two cracked disks collide with frictionless crack
 *        contact, the study of tests/4-contact/scene_fig3.c
 *        (tests/support/fig3.h) run with run.shape = "gimp".
 *
 * Bounds fixed before the first GIMP run, the ones physics fixes and
 * linear meets (scene_fig3.c): no point crosses its own crack's line; the
 * crack along the impact axis opens in mode I (more than half a cell)
 * while the one across it stays closed (within a tenth of a cell when the
 * left one is widest); contact acts (some node in contact); total
 * momentum at its start value to 1e-12 of sum m |v| at every step; the
 * frictionless contact does no work (1e-12 of E0); the total energy
 * drift no worse than the 2.6 % that linear meets (the reference CRAMP
 * code's 2.6-3.3 %). Linear runs the same reduced scene and its numbers
 * are printed beside GIMP's (opening, drift, contact nodes).
 *
 * The run is scene_fig3's reduced one (the collision and the rebound,
 * 12 ms), with linear, uGIMP and CPDI (run.shape = "cpdi"), each held to
 * the same bounds (per particle-step they cost 1209, 3698 and 10136
 * instructions here; the three runs take about 11 s). FIG3_OUT=dir writes the full GIMP run's openings.csv and snapshots (as
 * scene_fig3 does for linear) for a GIMP panel of make fig3.
 */
#include "fig3.h"

/** Run the study with @p shape to scene_fig3's 12 ms, print it headed by
 *  @p shape and return it. */
static Fig3Run fig3_shape(const char *shape)
{
    char ov[64];
    snprintf(ov, sizeof ov, "run.shape=\"%s\"", shape);
    const char *const overrides[] = {"run.time=12.0", ov, NULL};
    Fig3Run r = run_fig3(1, NULL, overrides);
    fig3_print(shape, &r);
    return r;
}

/** The bounds of the file's header on run @p r; each failure printed. */
static int fig3_bounds(const char *shape, const Fig3Run *r)
{
    double h = 1.0;                          /* the scene's cell size (mm) */
    TkBounds c = {0, 0};
    tk_bound(&c, 4, r->crossings[0] == 0 && r->crossings[1] == 0,
             "%s: points crossed their crack (%ld, %ld)", shape, r->crossings[0],
             r->crossings[1]);
    tk_bound(&c, 4, r->open_max[0] > 0.5 * h, "%s: the left crack opened %.4f mm "
             "(bound > h/2)", shape, r->open_max[0]);
    tk_bound(&c, 4, fabs(r->right_open_at_left_max) < 0.1 * h, "%s: the right "
             "crack's opening %.4f mm (bound h/10)", shape, r->right_open_at_left_max);
    tk_bound(&c, 4, r->contact_nodes > 0, "%s: no contact", shape);
    tk_bound(&c, 4, r->dp < 1e-12, "%s: momentum %.2e (bound 1e-12)", shape, r->dp);
    tk_bound(&c, 4, fabs(r->work) < 1e-12, "%s: contact work %.2e of E0 (bound "
             "1e-12)", shape, r->work);
    tk_bound(&c, 4, r->drift < 0.026, "%s: energy drift %.3f %% (bound 2.6 %%)",
             shape, 100 * r->drift);
    return c.failed;
}

static void gimp_beside_linear(void **state)
{
    (void)state;
    Fig3Run lin = fig3_shape("linear"), gmp = fig3_shape("gimp");
    Fig3Run cp = fig3_shape("cpdi");
    printf("  left crack's widest opening (mm): linear %.4f, uGIMP %.4f, CPDI "
           "%.4f; energy drift: linear %.3f %%, uGIMP %.3f %%, CPDI %.3f %%; most "
           "contact nodes: linear %d, uGIMP %d, CPDI %d\n", lin.open_max[0],
           gmp.open_max[0], cp.open_max[0], 100 * lin.drift, 100 * gmp.drift,
           100 * cp.drift, lin.contact_nodes, gmp.contact_nodes, cp.contact_nodes);
    int failed = fig3_bounds("linear", &lin) + fig3_bounds("gimp", &gmp) +
                 fig3_bounds("cpdi", &cp);
    assert_int_equal(failed, 0);
}

int main(void)
{
    const char *out = getenv("FIG3_OUT");
    if (out) {
        static const char *const gimp[] = {"run.shape=\"gimp\"", NULL};
        Fig3Run r = run_fig3(1, out, gimp);
        fig3_print("full run, uGIMP, frictionless contact", &r);
        return 0;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(gimp_beside_linear),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
