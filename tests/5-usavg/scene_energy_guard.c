/**
 * @file scene_energy_guard.c
 * @brief The energy guard where gravity works (energy_guard.h): stage 5's
 *        account counts the energy put in through SEAM_ENERGY_IN, and the
 *        guard compares the run's energy with it, not with the start's.
 *
 * - The beam impact of Fig. 6 (figures/fig6/beam_supports.cfg) with USL at
 *   CFL 0.1 to 1.5 ms, as on the stability map, under gravity of
 *   10 mm/ms^2: the falling impactor gains more than its start's energy
 *   from gravity (its energy passes twice the start legitimately), and
 *   then USL blows up (eq. 20). Stepping the scene itself, the first step
 *   whose kinetic + strain energy passes twice the account's energy in
 *   (the start's and gravity's work) comes after the first that passes
 *   twice the start; the program (a history row every step) stops at the
 *   former with status 3 and a message naming the energy put in and the
 *   ratio.
 * - The block sliding on its incline (tests/4-contact/scenes/slide.cfg,
 *   chapter 4b, MUSL), whose account closes within 1.5 %, runs to the end
 *   with the guard on.
 */
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "energy_balance.h"

#define BEAM "figures/fig6/beam_supports.cfg"
#define OVER "run.update=usl run.cfl=0.1 run.time=1.5 run.gravity=[0.0,-10.0] " \
             "run.snapshots=0"

/** First steps after which the energy passes twice the energy in
 *  (@return) and twice the start (@p at_start); @p ratio: E / in there. */
static long doubling(long *at_start, double *ratio)
{
    const char *const over[] = {"run.update=usl", "run.cfl=0.1", "run.time=1.5",
                                "run.gravity=[0.0,-10.0]", "run.snapshots=0", NULL};
    Sim *sim = tk_load_file(BEAM, over);
    const EnergyBalance *B = sim_state(sim, "energy balance");
    assert_non_null(B);
    long at = -1;
    *at_start = -1;
    while (sim->step < sim->nsteps && at < 0 && sim_advance(sim) == 0) {
        EnergyTerms e = energy_balance_terms(sim, B);
        if (*at_start < 0 && e.stored > 2.0 * B->e0)
            *at_start = sim->step;
        if (e.stored > 2.0 * e.in) {
            at = sim->step;
            *ratio = e.stored / e.in;
        }
    }
    tk_free(sim);
    return at;
}

static void guard_counts_gravity(void **state)
{
    (void)state;
    long at_start;
    double ratio = 0;
    long at = doubling(&at_start, &ratio);
    print_message("usl under gravity: energy passes twice the start after step "
                  "%ld, twice the energy put in after step %ld (E/in = %g)\n",
                  at_start, at, ratio);
    assert_true(at_start >= 1 && at > at_start);

    char out[4096], expect[64];
    assert_int_equal(tk_run_mpm(BEAM " -q -o build/test-energy-guard/usl " OVER
                                " run.history_every=1", out, sizeof out), 3);
    print_message("mpm said: %s", out);
    snprintf(expect, sizeof expect, "unstable at step %ld ", at);
    assert_non_null(strstr(out, expect));
    const char *eq = strstr(out, "the energy put in");
    assert_non_null(eq);
    eq = strstr(eq, ") = ");
    assert_non_null(eq);
    assert_close(strtod(eq + 4, NULL), ratio, 1e-5 * ratio);   /* %g */
}

static void sliding_block_runs_to_the_end(void **state)
{
    (void)state;
    char out[4096];
    tk_run_mpm_ok("tests/4-contact/scenes/slide.cfg -q -o build/test-energy-guard/slide "
                  "run.snapshots=0 run.history_every=1", out, sizeof out);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(guard_counts_gravity),
        cmocka_unit_test(sliding_block_runs_to_the_end),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
