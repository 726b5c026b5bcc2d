/**
 * @file stage6.c
 * @brief Stage 6 registers the XEFG method (run.method = "xefg"), its scene
 *        section `xefg`, and the set-up, history columns and checkpoint of
 *        a scene that chooses it.
 */
#include "stage6.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "checkpoint.h"
#include "cohesive.h"
#include "growth.h"
#include "output.h"
#include "quadrature.h"
#include "scene_read.h"
#include "xefg.h"

/** The stable step of the discretisation (before run.cfl). */
static double xefg_stable(const Sim *sim)
{
    const Xefg *x = xefg_of(sim);
    return x ? x->stable_step : NAN;
}

/** Keys XEFG carries out itself: the cracks are its enrichment (a
 *  stationary crack), not the fields and motion of Tasks 1 and 7. */
static const char *const xefg_own_keys[] = {"cracks", NULL};

/** Settings XEFG does not read: its step has no stress-update scheme, no
 *  spin of the stress, no crossing search. */
static const char *const xefg_ignored_keys[] = {"run.update", "run.stress_rate",
                                                "run.crack_search", NULL};

/// [xefg_method]
/** The row of the method table: xefg_step() runs no seam of the step. */
static const Method xefg_method = {"xefg", xefg_step, xefg_stable, 0,
                                   xefg_own_keys, xefg_ignored_keys};
/// [xefg_method]

/** The keys of the `xefg` section. */
static const char *const xefg_keys[] = {"support", "gauss", "tip",
                                        "tip_exponent", NULL};

static void xefg_release(void *state)
{
    xefg_free(state);
    free(state);
}

/** The state of @p sim, made with the default settings when missing. */
static Xefg *xefg_make(Sim *sim)
{
    Xefg *x = xefg_of(sim);
    if (x)
        return x;
    x = calloc(1, sizeof *x);
    if (!x)
        return NULL;
    x->set = (XefgSettings){2.0, 4, BRANCH_COHESIVE, 1.0, 0};
    if (sim_attach(sim, "xefg", x, xefg_release)) {
        free(x);
        return NULL;
    }
    return x;
}

/// [xefg_read]
/** The `xefg` section: support = d / h, gauss = n (n x n per cell),
 *  tip = "cohesive" (eq. 6) or "lefm" (eq. 5), tip_exponent = m. */
static int xefg_read(Sim *sim, const config_setting_t *s, int index,
                     SceneReader *r)
{
    (void)index;
    Xefg *x = xefg_make(sim);
    if (!x)
        return scene_error(r, s, "xefg", "out of memory");
    if (config_setting_type(s) != CONFIG_TYPE_GROUP)
        return scene_error(r, s, "xefg", "expected a group { support = 2.0; ... }");
    if (scene_check_keys(r, s, xefg_keys))
        return -1;
    XefgSettings *set = &x->set;
    double gauss = set->gauss;
    const char *tip = "cohesive";
    set->line = (int)config_setting_source_line(s);
    if (scene_number(r, s, "support", 0, set->support, &set->support) < 0 ||
        scene_number(r, s, "gauss", 0, gauss, &gauss) < 0 ||
        scene_number(r, s, "tip_exponent", 0, set->m, &set->m) < 0 ||
        scene_string(r, s, "tip", 0, &tip) < 0)
        return -1;
    const config_setting_t *at;
    if (!(set->support >= 1.0 && set->support <= 10.0))
        return scene_error(r, (at = config_setting_get_member(s, "support")) ? at : s,
                           "support", "%g: the support radius over the point "
                           "spacing must lie in [1, 10] (2 to 3 is usual)",
                           set->support);
    if (!(gauss >= 1 && gauss <= GAUSS_MAX && gauss == floor(gauss)))
        return scene_error(r, (at = config_setting_get_member(s, "gauss")) ? at : s,
                           "gauss", "%g: Gauss points per direction must be a "
                           "whole number from 1 to %d", gauss, GAUSS_MAX);
    set->gauss = (int)gauss;
    if (!(set->m >= 1.0 && set->m <= 3.0))
        return scene_error(r, (at = config_setting_get_member(s, "tip_exponent")) ? at : s,
                           "tip_exponent", "%g: m of r^m sin(theta/2) (eq. 6) "
                           "must lie in [1, 3]", set->m);
    if (strcmp(tip, "cohesive") == 0)
        set->tip = BRANCH_COHESIVE;
    else if (strcmp(tip, "lefm") == 0)
        set->tip = BRANCH_LEFM;
    else
        return scene_error(r, config_setting_get_member(s, "tip"), "tip",
                           "\"%s\": expected \"cohesive\" (r^m sin(theta/2), "
                           "eq. 6) or \"lefm\" (the four functions of eq. 5)",
                           tip);
    return 0;
}
/// [xefg_read]

/** history.csv: the parameters' kinetic energy and the Gauss points'
 *  strain energy (the points' columns are cell averages). */
static int xefg_history(const Sim *sim, void *state, FILE *f, int header)
{
    (void)state;
    const Xefg *x = xefg_of(sim);
    if (header)
        return fprintf(f, ",xefg_kinetic,xefg_strain") < 0 ? -1 : 0;
    int d = output_digits(sim, 9);      /* run.precision = "full": 17 */
    return fprintf(f, ",%.*g,%.*g", d, xefg_kinetic_energy(x), d,
                   xefg_strain_energy(x, sim)) < 0 ? -1 : 0;
}

/** The end of a run: the discretisation and the energy now. */
static int xefg_report(const Sim *sim, void *state, FILE *f)
{
    (void)state;
    const Xefg *x = xefg_of(sim);
    const char *eu = sim->scene.run.units->energy, *tu = sim->scene.run.units->time;
    return fprintf(f, "mpm: xefg: %d nodes, %d parameters (%d step, %d branch), "
                   "%d Gauss points; stable step %.6g %s (power iteration, %d "
                   "iterations); energy at t = %g %s: kinetic %.6g + strain %.6g "
                   "%s\n", x->nnode, x->ndof, x->nstep, x->nbranch, x->ngauss,
                   x->stable_step, tu, x->power_iterations, sim->t, tu,
                   xefg_kinetic_energy(x), xefg_strain_energy(x, sim), eu) < 0 ? -1 : 0;
}

/** The checkpoint: displacements, velocities, stresses and strains. */
static int xefg_checkpoint(Sim *sim, void *state, FILE *f, int save)
{
    (void)state;
    Xefg *x = xefg_of(sim);
    int n[2] = {x->ndof, x->ngauss};
    int m[2] = {x->ndof, x->ngauss};
    if (checkpoint_io(f, m, sizeof m, save) || m[0] != n[0] || m[1] != n[1] ||
        checkpoint_io(f, x->u, 2 * sizeof(double) * (size_t)x->ndof, save) ||
        checkpoint_io(f, x->v, 2 * sizeof(double) * (size_t)x->ndof, save) ||
        checkpoint_io(f, x->a, 2 * sizeof(double) * (size_t)x->ndof, save) ||
        checkpoint_io(f, x->gs, 3 * sizeof(double) * (size_t)x->ngauss, save) ||
        checkpoint_io(f, x->ge, 3 * sizeof(double) * (size_t)x->ngauss, save))
        return -1;
    if (!save)
        xefg_to_points(x, sim);
    return 0;
}

/** A cohesive crack under another method: refused at its first `cohesive`
 *  group, which holds its growth too (CRAMP's cracks are traction-free or
 *  in contact; stage 7 grows them by J). */
static int cohesive_refused(const Sim *sim, char *err, size_t errlen)
{
    const Cohesive *c = cohesive_of(sim);
    for (int k = 0; c && k < c->ncrack; k++) {
        if (!c->set[k].on)
            continue;
        char at[SCENE_AT_LEN];
        snprintf(err, errlen, "%s: cohesive: a cohesive law acts in the XEFG "
                 "method only, but run.method is \"%s\": add method = \"xefg\" "
                 "to run, or remove the cohesive group of crack %d",
                 scene_lines_at(sim->scene.lines, sim->scene.file,
                                c->set[k].line, at, SCENE_AT_LEN),
                 sim->scene.run.method->name, k);
        return -1;
    }
    return 0;
}

/// [xefg_prepare]
/** Set-up of a scene that chooses the method: the discretisation, then the
 *  history columns and the checkpoint section (and a cohesive crack's). */
static int xefg_prepare(Sim *sim, void *state, char *err, size_t errlen)
{
    (void)state;
    Xefg *x = xefg_of(sim);
    if (sim->scene.run.method != &xefg_method) {
        if (cohesive_refused(sim, err, errlen))
            return -1;
        if (!x)
            return 0;                        /* an MPM scene: nothing */
        char at[SCENE_AT_LEN];
        snprintf(err, errlen, "%s: xefg: the section sets the XEFG method, "
                 "but run.method is \"%s\": add method = \"xefg\" to run",
                 scene_lines_at(sim->scene.lines, sim->scene.file, x->set.line,
                                at, SCENE_AT_LEN),
                 sim->scene.run.method->name);
        return -1;
    }
    if (!x && !(x = xefg_make(sim))) {
        snprintf(err, errlen, "%s: out of memory", sim->scene.file);
        return -1;
    }
    if (xefg_build(x, sim, err, errlen))
        return -1;
    xefg_to_points(x, sim);
    if (hooks_on_history(&sim->hooks, xefg_history, x) ||
        hooks_on_report(&sim->hooks, xefg_report, x) ||
        hooks_on_checkpoint(&sim->hooks, xefg_checkpoint, x) ||
        (x->coh && cohesive_subscribe(sim, x->coh)) ||
        (x->grow && growth_subscribe(sim, x->grow))) {
        snprintf(err, errlen, "%s: too many subscribers at a seam",
                 sim->scene.file);
        return -1;
    }
    return 0;
}
/// [xefg_prepare]

/// [stage6_install]
void stage6_install(Hooks *h)
{
    hooks_add_choice(h, "run.method", "xefg", &xefg_method);
    hooks_add_key(h, "", "xefg", xefg_read, xefg_keys);
    hooks_add_key(h, "cracks", "cohesive", cohesive_read, cohesive_keys);
    hooks_add_key(h, "cracks.cohesive", "growth", growth_read, growth_keys);
    hooks_on_prepare(h, xefg_prepare, NULL);
}
/// [stage6_install]
