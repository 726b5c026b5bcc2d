/**
 * @file scene_beam_leaves.c
 * @brief The beam impact of the paper's Fig. 5 with contact between bodies
 *        (figures/fig5/beam_impact_contact.cfg): the impactor strikes the
 *        beam, pushes it down, and leaves it; with one velocity field
 *        (figures/fig6/beam_impact.cfg) it is still held at that time.
 *
 * A reduced run: MUSL at cfl 0.2 (the scene's 0.1 takes twice as long) to
 * 5.4 ms, the contact scene and then the one-field scene, the points of each
 * body watched every step. Contact means a step of the contact run in
 * which the contact task adjusted at least one node (history.csv's
 * material_contact_nodes > 0); for the one-field run, a step after which
 * a node is reached by points of both bodies (they share its velocity).
 * The impactor has left at the last contact step when no contact follows
 * to the end of the run and its y momentum is upward from then on.
 *
 * What it asserts, and why each bound is what it is:
 * - the impactor leaves: its last contact is at least WINDOW = 0.2 ms
 *   (1475 steps, a twentieth of the contact's duration; 0.28 ms measured)
 *   before the end, its y momentum is upward from then on, and in the last
 *   WINDOW it changes by less than 1e-9 of its initial value: a free body's
 *   momentum is constant to round-off (its internal forces sum to zero at
 *   the nodes; 3e-16 measured). Contact that always sticks (law "stick"
 *   with V_sep = V_contact = 1e-9) holds it and fails this.
 * - with one field it does not leave by the same time: a node is shared
 *   by both bodies at the end of that run, and the impactor's y momentum
 *   changed by more than 1e-3 of its initial value over the last WINDOW
 *   (a force acts on it; 2.9e-2 measured, the beam pulling it back).
 * - contact starts only when the gap between the bodies' point domains
 *   (each point fills h/ppc x h/ppc) has closed to half a cell, computed
 *   from the initial layout and the impact speed: the relative-volume test
 *   must not find contact at a node that both bodies merely reach. With
 *   the approach test alone it starts at 0.31 ms, a cell apart, and fails.
 * - frictionless contact does no work: material_contact_work, the work of
 *   each adjustment on the adjusted relative velocity (zero in exact
 *   arithmetic for this law), stays below 1e-9 of the initial energy
 *   (round-off of some 1e5 adjustments; 2e-16 measured). Friction
 *   (mu = 0.3) gives -0.34 and fails this.
 * - energy went into the beam: the impactor's kinetic energy at the end,
 *   after it left, is below its initial kinetic energy (0.92 of it
 *   measured), and the beam's kinetic + strain energy is above 1 % of the
 *   initial energy (16 % measured, 8 of it the scheme's gain). With the
 *   approach test alone the impactor leaves with 1.15 times its initial
 *   kinetic energy.
 * The total energy drift is printed, not asserted (MUSL at this step:
 * 8.2 %, in two steps up, in the rebound and at the separation; 2.2 % at
 * the scene's cfl 0.1; the stick law gives 47 %, the approach test alone
 * 268 %): what bounds it is stage 5's question.
 * It prints contact start and end, the impactor's momentum and kinetic
 * energy before and after, the beam's share, the energy drift and the
 * contact work, for both runs.
 *
 * BEAM_OVERRIDES="key=value ..." adds overrides to the contact run, to see
 * a check fail: "contact.[0].law=stick contact.[0].V_sep=1e-9
 * contact.[0].V_contact=1e-9" (always stuck: the numbers of one field),
 * "contact.[0].V_sep=1e-9 contact.[0].V_contact=1e9" (the approach test
 * alone), "contact.[0].law=stick", "contact.[0].law=friction
 * contact.[0].mu=0.3".
 */
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "material_contact.h"

static const char *const CONTACT_SCENE = "figures/fig5/beam_impact_contact.cfg";
static const char *const ONE_FIELD_SCENE = "figures/fig6/beam_impact.cfg";
/** The run's last WINDOW ms: the impactor must be free through it. */
#define WINDOW 0.2

/** What one run saw. */
typedef struct BeamRun {
    double t_start;     /* first contact step (ms), -1: none */
    double t_last;      /* last contact step (ms), -1: none */
    double t_end;       /* end of the run */
    double t_half_cell; /* when the domains' gap is h/2 (from the layout) */
    double py_min_after; /* least impactor y momentum after the last contact */
    double p0;          /* impactor's initial |y momentum| */
    double dpy_window;  /* its y momentum change over the last WINDOW ms */
    double k0, k_end;   /* impactor kinetic energy at the start, at the end */
    double e0, drift;   /* initial total energy, max |E - E0| / E0 */
    double beam_end;    /* beam's kinetic + strain energy at the end / E0 */
    double work;        /* material contact work / E0 (contact run) */
    int most_nodes;     /* most contact (or shared) nodes in one step */
    int shared_end;     /* nodes shared by both bodies at the end */
} BeamRun;

/** Kinetic and strain energy of the points of body @p b. */
static void body_energy(const Sim *sim, int b, double *kin, double *strain)
{
    const Particles *P = &sim->pts;
    *kin = *strain = 0.0;
    for (int p = 0; p < P->n; p++)
        if (P->body[p] == b) {
            *kin += 0.5 * P->m[p] * (P->vx[p] * P->vx[p] + P->vy[p] * P->vy[p]);
            *strain += 0.5 * P->vol[p] * (P->sxx[p] * P->exx[p] + P->syy[p] * P->eyy[p] +
                                          2.0 * P->sxy[p] * P->exy[p]);
        }
}

/** Y momentum of the points of body @p b. */
static double body_py(const Sim *sim, int b)
{
    const Particles *P = &sim->pts;
    double py = 0.0;
    for (int p = 0; p < P->n; p++)
        if (P->body[p] == b)
            py += P->m[p] * P->vy[p];
    return py;
}

/** Nodes that points of both bodies reach (from the points' current
 *  positions: the four nodes of each point's cell). */
static int shared_nodes(const Sim *sim, unsigned *seen)
{
    const Grid *g = &sim->grid;
    const Particles *P = &sim->pts;
    memset(seen, 0, sizeof(unsigned) * (size_t)g->nnodes);
    for (int p = 0; p < P->n; p++) {
        int i = (int)floor((P->x[p] - g->ox) / g->dx);
        int j = (int)floor((P->y[p] - g->oy) / g->dy);
        for (int dj = 0; dj < 2; dj++)
            for (int di = 0; di < 2; di++)
                seen[(j + dj) * g->nnx + i + di] |= 1u << P->body[p];
    }
    int n = 0;
    for (int k = 0; k < g->nnodes; k++)
        n += seen[k] == 3u;
    return n;
}

/** Index of the body named @p name. */
static int body_named(const Sim *sim, const char *name)
{
    for (int b = 0; b < sim->scene.nbodies; b++)
        if (strcmp(sim->scene.bodies[b].name, name) == 0)
            return b;
    fail_msg("no body \"%s\"", name);
    return -1;
}

/** Run @p scene (reduced by @p over, plus BEAM_OVERRIDES when @p extra). */
static BeamRun run_beam(const char *scene, int extra)
{
    const char *over[16] = {"run.update=musl", "run.cfl=0.2", "run.time=5.4"};
    int n = 3;
    char buf[512] = "";
    const char *env = extra ? getenv("BEAM_OVERRIDES") : NULL;
    if (env) {
        snprintf(buf, sizeof buf, "%s", env);
        for (char *tok = strtok(buf, " "); tok && n < 15; tok = strtok(NULL, " "))
            over[n++] = tok;
        printf("  overrides:%s%s\n", " ", env);
    }
    over[n] = NULL;
    Sim *sim = tk_load_file(scene, over);
    MaterialContact *M = sim_state(sim, "material contact");
    int beam = body_named(sim, "beam"), imp = body_named(sim, "impactor");
    const Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    unsigned *seen = malloc(sizeof(unsigned) * (size_t)g->nnodes);
    assert_non_null(seen);

    BeamRun r;
    memset(&r, 0, sizeof r);
    r.t_start = r.t_last = -1.0;
    /* the domains' gap: each point fills a square of side h/ppc */
    double top = -INFINITY, bottom = INFINITY, v0 = 0.0;
    for (int p = 0; p < P->n; p++) {
        double half = 0.5 * g->dy / sim->scene.bodies[P->body[p]].ppc;
        if (P->body[p] == beam)
            top = fmax(top, P->y[p] + half);
        else {
            bottom = fmin(bottom, P->y[p] - half);
            v0 = P->vy[p];
        }
    }
    r.t_half_cell = (bottom - top - 0.5 * g->dy) / -v0;
    Totals t0 = sim_totals(sim);
    r.e0 = t0.kinetic + t0.strain;
    double s, py_window = NAN;
    body_energy(sim, imp, &r.k0, &s);
    r.p0 = fabs(body_py(sim, imp));
    long window = sim->nsteps - (long)(WINDOW / sim->dt);
    while (sim->step < sim->nsteps) {
        if (sim->step == window)
            py_window = body_py(sim, imp);
        tk_steps(sim, 1);
        int nodes = M ? M->nodes : shared_nodes(sim, seen);
        if (nodes > 0) {
            if (r.t_start < 0)
                r.t_start = sim->t;
            r.t_last = sim->t;
            r.py_min_after = INFINITY;
        } else if (r.t_last >= 0)
            r.py_min_after = fmin(r.py_min_after, body_py(sim, imp));
        if (nodes > r.most_nodes)
            r.most_nodes = nodes;
        Totals t = sim_totals(sim);
        r.drift = fmax(r.drift, fabs(t.kinetic + t.strain - r.e0) / r.e0);
    }
    r.t_end = sim->t;
    r.dpy_window = body_py(sim, imp) - py_window;
    double kb, sb;
    body_energy(sim, imp, &r.k_end, &s);
    body_energy(sim, beam, &kb, &sb);
    r.beam_end = (kb + sb) / r.e0;
    r.work = M ? M->work / r.e0 : 0.0;
    r.shared_end = shared_nodes(sim, seen);
    free(seen);
    tk_free(sim);
    return r;
}

static void print_run(const char *what, const BeamRun *r)
{
    char after[32] = "- (in contact at the end)";
    if (isfinite(r->py_min_after))
        snprintf(after, sizeof after, "%.4g", r->py_min_after);
    printf("  %s (MUSL, cfl 0.2, to %.3g ms):\n"
           "    contact from %.3f ms (the domains half a cell apart at %.3f ms) to "
           "%.3f ms, most nodes in one step %d, nodes shared at the end %d\n"
           "    impactor y momentum: least after the last contact %s, change over "
           "the last %.2g ms %.3g of its initial %.4g (g m/s)\n"
           "    impactor kinetic energy %.4g mJ before, %.4g mJ at the end (%.4f); "
           "beam kinetic + strain at the end %.4f of E0\n"
           "    energy drift (max |E - E0|/E0) %.2f %%, contact work %.2e of E0\n",
           what, r->t_end, r->t_start, r->t_half_cell, r->t_last, r->most_nodes,
           r->shared_end, after, WINDOW, r->dpy_window / r->p0, r->p0,
           r->k0, r->k_end, r->k_end / r->k0, r->beam_end, 100 * r->drift, r->work);
}

static BeamRun contact_run;    /* the first test's run, when it passed */
static int contact_done;

static void impactor_leaves_with_contact(void **state)
{
    (void)state;
    BeamRun r = run_beam(CONTACT_SCENE, 1);
    print_run("contact between the bodies", &r);
    assert_true(r.t_start > 0);                      /* they meet */
    assert_true(r.t_last > r.t_start);
    assert_true(r.t_end - r.t_last >= WINDOW);       /* it left, for good */
    assert_true(r.py_min_after > 0);                 /* and it goes up */
    assert_true(fabs(r.dpy_window) < 1e-9 * r.p0);   /* free: no force on it */
    assert_true(r.t_start >= r.t_half_cell);         /* not across a gap */
    assert_true(fabs(r.work) < 1e-9);                /* frictionless: no work */
    assert_true(r.k_end < r.k0);                     /* it gave energy away */
    assert_true(r.beam_end > 0.01);                  /* to the beam */
    contact_run = r;                                 /* a run that passed */
    contact_done = 1;
}

static void one_field_holds_it(void **state)
{
    (void)state;
    BeamRun r = run_beam(ONE_FIELD_SCENE, 0);
    print_run("one velocity field", &r);
    assert_true(r.t_start > 0);
    assert_true(r.shared_end > 0);                   /* it shares nodes, */
    assert_true(fabs(r.dpy_window) > 1e-3 * r.p0);   /* and the beam holds it */
    if (contact_done)                                /* when contact had let go */
        assert_true(r.t_end - contact_run.t_last >= WINDOW);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(impactor_leaves_with_contact),
        cmocka_unit_test(one_field_holds_it),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
