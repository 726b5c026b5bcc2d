/**
 * @file scene_crack_rules.c
 * @brief Crack contact's detection rules on the crack benchmarks: faces
 *        that open must never be found in contact, and a body cut through
 *        by a crack and closed in compression must carry the load as if
 *        it were whole, edge rows included.
 *
 * - **An opening crack** (tests/4-contact/scenes/inclined_crack.cfg with
 *   its load reversed: the internal 45-degree crack of the Coulomb test,
 *   the block pulled by 0.02 MPa ramped over 8 ms, damped to rest at
 *   16 ms): the crack opens, so with the opening rule (stage 4's default
 *   for cracks: contact when the faces approach and the opening, the two
 *   sides' mass-weighted displacements at the node along the normal, is
 *   closed) contact_nodes must be 0 at every step. The paper's volume
 *   rule (V_sep 0.9, V_contact 1.1) is printed: its grey zone takes faces a
 *   few micrometres apart that move toward each other for touching ones
 *   (contact in 846 of 1083 steps, up to 13 nodes, when written).
 * - **A bar cut through** (20 mm long, 4 mm and 2 mm high, a crack across
 *   it at x = 10.5, mid-cell, from below the bar to above it; rollers at
 *   x = 0, 0.04 and 0.02 N of compression at the other end ramped over 8 ms,
 *   damped to rest at 16 ms): the mean x of the loaded end's points within
 *   0.5 % of the uncracked bar's displacement (issue 25's bound), with the
 *   opening rule and with the volume rule. Measured when written: both
 *   +0.0001 % (4 mm) and +0.0037 % (2 mm). (Issue 25 reports the volume
 *   rule 1.9-3.8 % soft on a cut bar, from edge nodes whose relative
 *   volume is about 0.5; this scene, with the crack mid-cell and the load
 *   through the end's points, does not show it.) Without contact the
 *   halves pass through each other and the check fails.
 */
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crack_contact.h"

/** The most crack contact nodes over a run of the opening inclined crack
 *  with @p rule ("" for the default). */
static int opening_crack(const char *rule)
{
    const char *const over[] = {"loads.[0].force=[0.0, 0.4]", rule[0] ? rule : NULL,
                                NULL};
    Sim *sim = tk_load_file("tests/4-contact/scenes/inclined_crack.cfg", over);
    const ContactState *S = sim_state(sim, "crack contact");
    assert_non_null(S);
    int most = 0;
    long steps = 0;
    while (sim->step < sim->nsteps) {
        tk_steps(sim, 1);
        most = S->nodes > most ? S->nodes : most;
        steps += S->nodes > 0;
    }
    printf("  opening inclined crack, %s: contact in %ld of %ld steps, most nodes %d\n",
           rule[0] ? rule : "default (opening)", steps, sim->step, most);
    tk_free(sim);
    return most;
}

static void opening_crack_is_never_in_contact(void **state)
{
    (void)state;
    assert_int_equal(opening_crack(""), 0);
    opening_crack("cracks.[0].contact.V_sep=0.9");  /* the paper's rule: printed */
}

/** The bar's scene text, @p h mm high, with @p crack ("" for none). */
static void bar_text(char *out, size_t len, int h, const char *crack)
{
    snprintf(out, len,
        "grid = { origin = [-2.0, -2.0]; cells = [24, %d]; cell_size = [1.0, 1.0]; };\n"
        "run = { time = 16.0; cfl = 0.4; update = \"musl\"; damping = 2.0; snapshots = 0;\n"
        "        plane = \"stress\"; };\n"
        "materials = ( { name = \"soft\"; E = 1.0; nu = 0.3; rho = 1.5e-3; } );\n"
        "bodies = ( { name = \"bar\"; material = \"soft\"; points_per_cell = 2;\n"
        "             rectangle = { min = [0.0, 0.0]; max = [20.0, %d.0]; }; } );\n"
        "boundaries = ( { rectangle = { min = [0.0, -2.0]; max = [0.0, %d.0]; }; fix = \"x\"; },\n"
        "               { rectangle = { min = [0.0, 0.0]; max = [0.0, 0.0]; }; fix = \"y\"; } );\n"
        "loads = ( { rectangle = { min = [19.5, -1.0]; max = [21.0, %d.0]; };\n"
        "            force = [-0.0%d, 0.0]; ramp = 8.0; } );\n%s",
        h + 4, h, h + 2, h + 1, h, crack);
}

/** The loaded end's mean x displacement at the end of the run. */
static double end_displacement(const char *text)
{
    Sim *sim = tk_load(text);
    const Particles *P = &sim->pts;
    double x0 = 0;
    int n = 0;
    int *end = malloc(sizeof(int) * (size_t)P->n);
    assert_non_null(end);
    for (int p = 0; p < P->n; p++)
        if (P->x[p] > 19.5) {
            end[n++] = p;
            x0 += P->x[p];
        }
    tk_steps(sim, sim->nsteps);
    double x1 = 0;
    for (int k = 0; k < n; k++)
        x1 += P->x[end[k]];
    free(end);
    tk_free(sim);
    return (x1 - x0) / n;
}

static void bar_cut_through_carries_compression(void **state)
{
    (void)state;
    const char *rules[3] = {"contact = { law = \"frictionless\"; }; ",
                            "contact = { law = \"frictionless\"; V_sep = 0.9; V_contact = 1.1; }; ",
                            ""};
    const char *names[3] = {"opening rule", "volume rule", "no contact"};
    for (int h = 4; h >= 2; h -= 2) {
        char text[2048], crack[256];
        bar_text(text, sizeof text, h, "");
        double whole = end_displacement(text);
        printf("  bar %d mm high, uncracked: end displacement %.6e mm\n", h, whole);
        for (int k = 0; k < 3; k++) {
            snprintf(crack, sizeof crack, "cracks = ( { points = ( [10.5, -1.0], "
                     "[10.5, %d.0] ); %s} );\n", h + 1, rules[k]);
            bar_text(text, sizeof text, h, crack);
            double cut = end_displacement(text);
            printf("  bar %d mm high, cut through, %s: %.6e mm (%+.4f %% of the "
                   "uncracked)\n", h, names[k], cut, 100 * (cut / whole - 1));
            if (k < 2)
                assert_true(fabs(cut / whole - 1) <= 0.005);
            else
                assert_true(fabs(cut / whole - 1) > 0.005);  /* the check can fail */
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(opening_crack_is_never_in_contact),
        cmocka_unit_test(bar_cut_through_carries_compression),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
