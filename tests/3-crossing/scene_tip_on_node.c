/**
 * @file scene_tip_on_node.c
 * @brief Issue 7: the DCB with its crack tip exactly on a grid node, sigma_xx
 *        along the ligament against a converged static Q4 analysis.
 *
 * The DCB of tests/3-crossing/scenes/tip_*.cfg (figures/fig1/dcb_full.cfg's
 * specimen, material and damping, 2 mN on each arm's end) is damped to the
 * static state; sigma_xx at the mid-plane nodes ahead of the tip (points'
 * stresses extrapolated to the grid with mass weights, as grid_NNNNN.csv
 * has them) is compared with a plane-stress Q4 analysis of the upper half
 * (tests/support/q4.c) on a fine mesh, two mesh sizes extrapolated to zero
 * (Richardson, error of order h), sampled in four ways:
 *
 *  - (a)  the FEA at the node's own x;
 *  - (a') the FEA at the same distance from the tip: the tip is a material
 *         point and the ligament ahead of it stretches, so in the static
 *         state the tip sits about 0.25 mm left of x = 50 (the FEA says the
 *         same), and grid node x is x - x_tip from it;
 *  - (b)  the FEA stress at every material point's initial position,
 *         extrapolated to the nodes with the mass weights of the initial
 *         positions (as scene_fig2.c does);
 *  - (b') the same stresses with the weights of the points' final MPM
 *         positions: exactly how the MPM's own nodal values are made, so
 *         that MPM and (b') differ only by what each method solves.
 *
 * The study (chapter 3, "The tip on a node"; `make fig-tip`) found:
 *  - the tip node's field assignment is not the cause.  With the tip
 *    exactly on node (50, 0) that node is split at the first step (every
 *    point above in one crack field, every point below in the other,
 *    nothing in field 0), but the tip is a material point: it leaves the
 *    node as the load arrives and ends 0.24 mm to its left (the FEA: 0.25
 *    mm), so the node is shared in the static state.  Excluding the node
 *    while the tip sits on it (the crack 1e-9 mm shorter, or the line-
 *    crossing rule changed to drop the crack's end point) gives the same
 *    static stresses to round-off;
 *  - the MPM sees a crack only through which nodes are split, so every tip
 *    position between the same two nodes gives the same static state (tips
 *    49.5 and 49.99 on the 2 mm grid: identical): the crack length is
 *    resolved to a cell, and the error against the physical solution is a
 *    sawtooth of the tip's position.  A tip on a node is at the sawtooth's
 *    low end (the MPM's crack is shorter than the physical one), a tip
 *    mid-cell at its middle; a tip that passes a node while the load
 *    arrives leaves values between two plateaus (tip on the node against
 *    49.99: 4.2 % here);
 *  - on the 1 mm grid the gap at x = 51, -32.2 % against (a), is the
 *    product of three factors: the node is 1.243 mm from the moved tip, not
 *    1 mm, and the FEA there is 8.6 % lower ((a') / (a) = 0.914); sampled
 *    as the MPM samples it is 6.7 % lower again ((b') / (a') = 0.933); the
 *    MPM is 20.5 % below that (0.795).  That last part is the
 *    discretisation: at a fixed x it shrinks as the grid is refined (2 mm
 *    to 1 mm: it halves for 60 <= x <= 70); on the 0.5 mm grid the points
 *    near the tip cross cells as the ligament stretches and the profile
 *    there turns irregular (cell-crossing error), so that grid is not used
 *    here.
 *
 * This test asserts the three on the 2 mm and 1 mm grids (about 20 s).  With
 * TIP_STUDY=dir in the environment it instead reads the runs that
 * figures/fig-tip/make.sh made with build/stage3/mpm (dir/NAME/) and prints
 * the study's tables, writing one CSV per run into $TIP_CSV_DIR if set;
 * TIP_RUNS="tip_node_2mm tip_node_1mm" reads those runs only (chapter 8
 * runs them with uGIMP on build/stage8/mpm, the same tables).
 */
#include "stencil.h"
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cracks.h"
#include "q4.h"
#include "stages.h"

#define SCENES "tests/3-crossing/scenes/"
#define TIP 50.0                 /* the crack tip of every scene (mm) */

/* ---- the static Q4 reference ------------------------------------------- */

/** The upper half of the DCB (100 x 18 mm) with the mid-plane held in y from
 *  the tip on, meshed with square elements of size h.  Stored transposed
 *  (the mesh's x is the beam's y) so that the band of K is narrow.  Its
 *  sigma_xx is recovered at the mesh nodes (the mean of the adjacent
 *  elements' values there) and interpolated bilinearly in between, so that
 *  two meshes converge alike at every point and can be extrapolated. */
typedef struct Fea {
    Q4Model q[2];                /* h and h / 2 */
    double *sxx[2];              /* recovered nodal sigma_xx of each mesh */
} Fea;

static int fea_solve(Q4Model *q, double h, const Sim *load_from)
{
    int nX = (int)lround(100.0 / h), nY = (int)lround(18.0 / h);
    const Material *mat = &load_from->scene.mat[0];
    if (q4_init(q, nY, nX, 0.0, 0.0, h, h, 1.0, mat->E, mat->nu))
        return -1;
    for (int j = 0; j <= nX; j++)                /* ligament, tip node too */
        if (j * h >= TIP - 1e-9)
            q->fix[2 * q4_node(q, 0, j)] = 1;
    q->fix[2 * q4_node(q, 0, nX) + 1] = 1;       /* no rigid x motion */
    const Load *L = &load_from->scene.loads[0];  /* the upper arm's load */
    for (int k = 0; k < L->count; k++) {
        int p = L->points[k];
        q4_point_force(q, load_from->pts.y[p], load_from->pts.x[p],
                       L->fy / L->count, L->fx / L->count);
    }
    return q4_solve(q);
}

/** sigma_xx at every mesh node: the mean of the values of the elements
 *  around it, each evaluated at the node. */
static double *fea_recover(const Q4Model *q)
{
    double *v = malloc(sizeof(double) * (size_t)(q->nx + 1) * (size_t)(q->ny + 1));
    if (!v)
        return NULL;
    double e = 1e-9 * q->dx;
    for (int j = 0; j <= q->ny; j++)
        for (int i = 0; i <= q->nx; i++) {
            double sum = 0, s[3];
            int n = 0;
            for (int di = -1; di <= 1; di += 2)
                for (int dj = -1; dj <= 1; dj += 2) {
                    if (i + (di > 0) - 1 < 0 || i + (di > 0) - 1 >= q->nx ||
                        j + (dj > 0) - 1 < 0 || j + (dj > 0) - 1 >= q->ny)
                        continue;       /* no element on that side */
                    q4_stress(q, i * q->dx + di * e, j * q->dy + dj * e, s);
                    sum += s[1];        /* the beam's xx is the mesh's yy */
                    n++;
                }
            v[q4_node(q, i, j)] = sum / n;
        }
    return v;
}

static int fea_init(Fea *f, double h, const Sim *load_from)
{
    for (int k = 0; k < 2; k++) {
        f->sxx[k] = NULL;
        if (fea_solve(&f->q[k], k ? h / 2 : h, load_from) ||
            !(f->sxx[k] = fea_recover(&f->q[k])))
            return -1;
    }
    return 0;
}

static void fea_free(Fea *f)
{
    for (int k = 0; k < 2; k++) {
        q4_free(&f->q[k]);
        free(f->sxx[k]);
    }
}

/** Recovered sigma_xx of mesh k at (x, |y|) (symmetry about the mid-plane). */
static double fea_sxx_k(const Fea *f, int k, double x, double y)
{
    const Q4Model *q = &f->q[k];
    double gx = fabs(y) / q->dx, gy = x / q->dy;  /* the mesh is transposed */
    int i = (int)floor(gx), j = (int)floor(gy);
    i = i < 0 ? 0 : i >= q->nx ? q->nx - 1 : i;
    j = j < 0 ? 0 : j >= q->ny ? q->ny - 1 : j;
    double a = gx - i, b = gy - j;
    const double *v = f->sxx[k];
    return (1 - a) * (1 - b) * v[q4_node(q, i, j)] + a * (1 - b) * v[q4_node(q, i + 1, j)] +
           (1 - a) * b * v[q4_node(q, i, j + 1)] + a * b * v[q4_node(q, i + 1, j + 1)];
}

/** sigma_xx at (x, y), extrapolated to h = 0 (error of order h). */
static double fea_sxx(const Fea *f, double x, double y)
{
    return 2 * fea_sxx_k(f, 1, x, y) - fea_sxx_k(f, 0, x, y);
}

/** Nodal sigma_xx on the mid-plane at x. */
static double fea_node(const Fea *f, double x)
{
    return fea_sxx(f, x, 0);
}

/* ---- mid-plane nodal values --------------------------------------------- */

/** Mass-weighted extrapolation of the point values @p v to the mid-plane
 *  nodes (row y = 0), with the weights of positions (@p x, @p y), as
 *  output_grid_csv() does: out[i] for node column i, NAN where no mass. */
static void midplane(const Sim *sim, const double *x, const double *y,
                     const double *v, double *out)
{
    const Grid *g = &sim->grid;
    int j0 = (int)lround(-g->oy / g->dy);
    double *w = calloc((size_t)g->nnx, sizeof(double));
    for (int i = 0; i < g->nnx; i++)
        out[i] = 0;
    for (int p = 0; p < sim->pts.n; p++) {
        Stencil st;
        stencil_at(g, x[p], y[p], &st);
        for (int a = 0; a < STENCIL_NODES; a++) {
            int n = st.slot[a];
            if (n / g->nnx != j0)
                continue;
            double m = sim->pts.m[p] * st.S[a];
            out[n % g->nnx] += m * v[p];
            w[n % g->nnx] += m;
        }
    }
    for (int i = 0; i < g->nnx; i++)
        out[i] = w[i] > 0 ? out[i] / w[i] : NAN;
    free(w);
}

/* ---- one run ------------------------------------------------------------ */

/** A run in its static state, its initial point positions, and the four
 *  FEA samplings of it. */
typedef struct Run {
    const char *name;
    Sim *sim;
    double *x0, *y0;             /* initial positions */
    double tip;                  /* crack tip x, static state */
    double *mpm;                 /* per node column: MPM sigma_xx at y = 0 */
    double *a, *a2, *b, *b2;     /* FEA: (a), (a'), (b), (b') */
} Run;

static Sim *load_scene(const char *path, double tip, char *err, size_t errlen)
{
    Sim *sim = malloc(sizeof *sim);
    if (!sim)
        return NULL;
    sim_init(sim);
    mpm_install_stages(&sim->hooks);
    int rc;
    if (tip == TIP) {
        rc = sim_load_file(sim, path, 0, NULL, err, errlen);
    } else {                     /* the same scene, the tip moved to tip */
        FILE *f = fopen(path, "rb");
        char *text = calloc(1 << 16, 1), *out = calloc(1 << 16, 1);
        size_t n = f ? fread(text, 1, (1 << 16) - 1, f) : 0;
        if (f)
            fclose(f);
        char *at = n ? strstr(text, "[50.0, 0.0] );") : NULL;
        if (!at) {
            snprintf(err, errlen, "%s: no crack tip [50.0, 0.0]", path);
            rc = -1;
        } else {
            *at = '\0';
            snprintf(out, 1 << 16, "%s[%.17g, 0.0]%s", text, tip,
                     at + strlen("[50.0, 0.0]"));
            rc = sim_load_string(sim, out, path, err, errlen);
        }
        free(text);
        free(out);
    }
    if (rc) {
        sim_free(sim);
        free(sim);
        return NULL;
    }
    return sim;
}

static void run_init(Run *r, const char *name, Sim *sim)
{
    int n = sim->pts.n, nn = sim->grid.nnx;
    *r = (Run){.name = name, .sim = sim};
    r->x0 = malloc(sizeof(double) * (size_t)n);
    r->y0 = malloc(sizeof(double) * (size_t)n);
    memcpy(r->x0, sim->pts.x, sizeof(double) * (size_t)n);
    memcpy(r->y0, sim->pts.y, sizeof(double) * (size_t)n);
    double **cols[] = {&r->mpm, &r->a, &r->a2, &r->b, &r->b2};
    for (int k = 0; k < 5; k++)
        *cols[k] = calloc((size_t)nn, sizeof(double));
}

/** The MPM's nodal values and the FEA's four samplings (static state). */
static void run_compare(Run *r, const Fea *f)
{
    const Sim *sim = r->sim;
    const Grid *g = &sim->grid;
    int n = sim->pts.n;
    r->tip = cracks_of(sim)->crack[0].x[cracks_of(sim)->crack[0].n - 1];
    midplane(sim, sim->pts.x, sim->pts.y, sim->pts.sxx, r->mpm);
    double *s0 = malloc(sizeof(double) * (size_t)n);
    for (int p = 0; p < n; p++)  /* FEA stress of each point, where it was */
        s0[p] = fabs(r->y0[p]) < 2 * g->dy ? fea_sxx(f, r->x0[p], r->y0[p]) : 0;
    midplane(sim, r->x0, r->y0, s0, r->b);
    midplane(sim, sim->pts.x, sim->pts.y, s0, r->b2);
    for (int i = 0; i < g->nnx; i++) {
        double x = g->ox + i * g->dx;
        r->a[i] = x >= 0 && x <= 100 ? fea_node(f, x) : NAN;
        double xm = x - (r->tip - TIP);          /* same distance from tip */
        r->a2[i] = xm >= 0 && xm <= 100 ? fea_node(f, xm) : NAN;
    }
    free(s0);
}

static void run_free(Run *r)
{
    if (r->sim) {
        sim_free(r->sim);
        free(r->sim);
    }
    free(r->x0);
    free(r->y0);
    free(r->mpm);
    free(r->a);
    free(r->a2);
    free(r->b);
    free(r->b2);
}

static double node_x(const Run *r, int i)
{
    return r->sim->grid.ox + i * r->sim->grid.dx;
}

/** Column of the first node with x > x_min. */
static int first_node_after(const Run *r, double x_min)
{
    const Grid *g = &r->sim->grid;
    int i = (int)floor((x_min - g->ox) / g->dx + 1e-9) + 1;
    return node_x(r, i) > x_min + 1e-9 ? i : i + 1;
}

/** Column of the node nearest x. */
static int node_near(const Run *r, double x)
{
    return (int)lround((x - r->sim->grid.ox) / r->sim->grid.dx);
}

static double rel(double v, double ref)
{
    return v / ref - 1;
}

/** Largest |MPM / (b') - 1| over the nodes with lo <= x <= hi. */
static double worst_b2(const Run *r, double lo, double hi, double *at)
{
    double worst = 0;
    for (int i = 0; i < r->sim->grid.nnx; i++) {
        double x = node_x(r, i);
        if (x < lo - 1e-9 || x > hi + 1e-9)
            continue;
        double d = fabs(rel(r->mpm[i], r->b2[i]));
        if (d > worst) {
            worst = d;
            *at = x;
        }
    }
    return worst;
}

/* ---- the test ------------------------------------------------------------ */

/** Key bits of the pair fields at the node (x, 0) with mass: returns the
 *  number of crack-side fields with mass, and whether field 0 has mass. */
static int crack_fields_at(const Sim *sim, double x, int *field0)
{
    const Grid *g = &sim->grid;
    int n = (int)lround(-g->oy / g->dy) * g->nnx + (int)lround((x - g->ox) / g->dx);
    assert_true(fabs(grid_node_x(g, n) - x) < 1e-9 && fabs(grid_node_y(g, n)) < 1e-9);
    int count = 0;
    *field0 = g->m[n] > 0;
    for (int s = field_next(&sim->fields, g, n); s >= 0;
         s = field_next(&sim->fields, g, s))
        count += g->m[s] > 0 && field_key(&sim->fields, g, s) != 0;
    return count;
}

static Sim *must_load(const char *path, double tip)
{
    char err[1024];
    Sim *sim = load_scene(path, tip, err, sizeof err);
    if (!sim)
        fail_msg("scene refused: %s", err);
    return sim;
}

/** Damp to the static state; the study saw kinetic / strain energy at most
 *  1.23e-3 on these grids with the ligament stresses then steady to 0.1 %
 *  (2 mm grid, 360 to 1200 ms). */
static void run_static(Sim *sim)
{
    tk_steps(sim, sim->nsteps);
    Totals t = sim_totals(sim);
    printf("  static: kinetic / strain energy %.3g\n", t.kinetic / t.strain);
    assert_true(t.kinetic < 2e-3 * t.strain);
}

/** Static mid-plane sigma_xx of the 2 mm scene with its tip at x = tip,
 *  and the steps at which node (50, 0) had crack fields with mass. */
typedef struct TipRun {
    Run r;
    int split_first;             /* node (50, 0) at step 1: crack fields */
    int field0_first;            /* ... and whether field 0 had mass */
    long nsplit, last_split;     /* steps with crack fields there, last one */
    double tip_max;              /* largest x of the tip during the run */
} TipRun;

static void tip_run(TipRun *t, double tip)
{
    Sim *sim = must_load(SCENES "tip_node_2mm.cfg", tip);
    *t = (TipRun){.last_split = -1, .tip_max = tip};
    run_init(&t->r, "2 mm", sim);
    const Crack *c = &cracks_of(sim)->crack[0];
    for (long k = 1; k <= sim->nsteps; k++) {
        tk_steps(sim, 1);
        int f0, cf = crack_fields_at(sim, TIP, &f0);
        if (k == 1) {
            t->split_first = cf;
            t->field0_first = f0;
        }
        if (cf) {
            t->nsplit++;
            t->last_split = k;
        }
        t->tip_max = fmax(t->tip_max, c->x[c->n - 1]);
    }
    Totals e = sim_totals(sim);
    assert_true(e.kinetic < 2e-3 * e.strain);   /* see run_static() */
    t->r.tip = c->x[c->n - 1];
    midplane(sim, sim->pts.x, sim->pts.y, sim->pts.sxx, t->r.mpm);
    printf("tip at x = %.12g: node (50, 0) at step 1: %d crack fields, field 0 "
           "%s; crack fields in %ld of %ld steps, the last at step %ld; tip "
           "at most %.5f, static at %.5f\n", tip, t->split_first,
           t->field0_first ? "with mass" : "empty", t->nsplit, sim->nsteps,
           t->last_split, t->tip_max, t->r.tip);
    printf("  sigma_xx at y = 0: x = 52: %.6e, 60: %.6e, 70: %.6e\n",
           t->r.mpm[node_near(&t->r, 52)], t->r.mpm[node_near(&t->r, 60)],
           t->r.mpm[node_near(&t->r, 70)]);
}

/** Largest relative difference of the mid-plane sigma_xx of two runs on
 *  the same grid over the ligament 50 < x <= 70 (sigma_xx falls to a
 *  seventh of its value at x = 52 there, and passes through zero near
 *  x = 90). */
static double ligament_diff(const Run *p, const Run *q, double *at)
{
    double worst = 0;
    for (int i = 0; i < p->sim->grid.nnx; i++) {
        double x = node_x(p, i);
        if (x <= TIP || x > 70 + 1e-9)
            continue;
        double d = fabs(rel(p->mpm[i], q->mpm[i]));
        if (d > worst || isnan(d)) {
            worst = isnan(d) ? INFINITY : d;
            *at = x;
        }
    }
    return worst;
}

/** The hypothesis: with the tip exactly on node (50, 0), every
 *  point above is sent to one crack field of that node and every point
 *  below to the other, cutting the node's tie between the arms and the
 *  ligament.  True at the first step; but the tip is a material point and
 *  leaves the node, and excluding the node while the tip sits on it (the
 *  crack 1e-9 mm shorter) gives the same static state. */
static void tip_node_classification_is_not_the_cause(void **state)
{
    (void)state;
    TipRun on, off;
    tip_run(&on, TIP);
    tip_run(&off, TIP - 1e-9);
    assert_int_equal(on.split_first, 2);     /* both sides ... */
    assert_false(on.field0_first);           /* ... and nothing in field 0 */
    assert_int_equal(off.split_first, 0);
    /* shared in the static state: the study saw the last split at step 137
       of 3460 and the tip 0.24 mm left of the node (the FEA: 0.25 mm) */
    assert_true(on.last_split < on.r.sim->nsteps / 20);
    assert_true(on.r.tip < TIP - 0.2);
    double at = 0, d = ligament_diff(&on.r, &off.r, &at);
    printf("ligament sigma_xx, tip on the node against 1e-9 mm short: largest "
           "relative difference %.3g (x = %g)\n", d, at);
    /* this test: 4e-15; the study, from ten-digit CSVs, 50 < x <= 70: 0 on
       the 2 mm and 1 mm grids, 9.4e-10 on the 0.5 mm grid */
    assert_true(d <= 1e-8);
    run_free(&on.r);
    run_free(&off.r);
}

/** The MPM sees a crack only through the fields of the nodes: a crack whose
 *  tip stays between the same two nodes gives the same static state
 *  wherever the tip is.  The tip on node (50, 0) differs from that state
 *  only because the tip, on its way left, first overshoots 0.009 mm to the
 *  right of the node while the load arrives, and the node is split then. */
static void crack_length_is_seen_to_a_cell(void **state)
{
    (void)state;
    TipRun a, b, on;
    tip_run(&a, 49.5);
    tip_run(&b, 49.99);
    tip_run(&on, TIP);
    assert_int_equal(a.nsplit, 0);
    assert_int_equal(b.nsplit, 0);
    double at = 0, d = ligament_diff(&a.r, &b.r, &at);
    printf("tips 49.5 and 49.99 (node (50, 0) never split): largest relative "
           "difference %.3g\n", d);
    assert_true(d == 0);                     /* study: identical */
    d = ligament_diff(&on.r, &b.r, &at);
    printf("tip on the node against tip 49.99: largest relative difference "
           "%.2f %% (x = %g)\n", 100 * d, at);
    assert_true(on.nsplit > 1);
    assert_true(d <= 0.045);                 /* study: 4.2 % */
    run_free(&a.r);
    run_free(&b.r);
    run_free(&on.r);
}

static void print_row(const Run *r, int i)
{
    char a[32] = "   n/a  ";          /* (a) at x <= 50: the tip or a face */
    if (node_x(r, i) > TIP + 1e-9)
        snprintf(a, sizeof a, "%+6.2f %%", 100 * rel(r->mpm[i], r->a[i]));
    printf("  x = %7.3f (%.3f from the tip): MPM %.4e; (a) %s, (a') "
           "%+6.2f %%, (b) %+6.2f %%, (b') %+6.2f %%\n", node_x(r, i),
           node_x(r, i) - r->tip, r->mpm[i], a,
           100 * rel(r->mpm[i], r->a2[i]), 100 * rel(r->mpm[i], r->b[i]),
           100 * rel(r->mpm[i], r->b2[i]));
}

/** Issue 7's comparison on the 1 mm grid, bounded by the study's numbers,
 *  and the 2 mm grid to see the gap at a fixed x shrink. */
static void tip_on_node_bounded_by_fea(void **state)
{
    (void)state;
    Run r1, r2;
    run_init(&r2, "2 mm", must_load(SCENES "tip_node_2mm.cfg", TIP));
    run_init(&r1, "1 mm", must_load(SCENES "tip_node_1mm.cfg", TIP));
    Fea f;
    assert_int_equal(fea_init(&f, 0.25, r1.sim), 0);
    Run *runs[] = {&r2, &r1};
    double worst_far[2], at;
    for (int k = 0; k < 2; k++) {
        Run *r = runs[k];
        run_static(r->sim);
        run_compare(r, &f);
        printf("%s grid, tip on a node: static tip at x = %.4f; MPM against "
               "the FEA\n", r->name, r->tip);
        print_row(r, first_node_after(r, TIP));
        print_row(r, node_near(r, 55));
        print_row(r, node_near(r, 60));
        print_row(r, node_near(r, 70));
        worst_far[k] = worst_b2(r, 60, 70, &at);
        printf("  largest |MPM / (b') - 1| for 60 <= x <= 70: %.2f %% (x = %g)\n",
               100 * worst_far[k], at);
    }
    int i51 = first_node_after(&r1, TIP);
    double gap51 = rel(r1.mpm[i51], r1.b2[i51]);
    double worst55 = worst_b2(&r1, 55, 70, &at);
    printf("1 mm grid: x = 51: %.2f %% against (b'); 55 <= x <= 70: at most "
           "%.2f %%; the gap for 60 <= x <= 70 is %.2f of the 2 mm grid's\n",
           100 * gap51, 100 * worst55, worst_far[1] / worst_far[0]);
    /* this test (FEA h = 0.25, 0.125): -20.43 %, 8.03 %, 0.50; the study
       (FEA h = 0.125, 0.0625): -20.54 %, 8.05 %, 0.50 */
    assert_true(fabs(gap51) <= 0.21);
    assert_true(worst55 <= 0.085);
    assert_true(worst_far[1] <= 0.55 * worst_far[0]);
    fea_free(&f);
    run_free(&r1);
    run_free(&r2);
}

/* ---- the study's tables (TIP_STUDY=dir) ---------------------------------- */

/** Read the static state that build/stage3/mpm wrote into dir/name:
 *  particles_final.csv (positions and stresses, in point order) and the
 *  crack's last snapshot. */
static int read_run(Run *r, const char *dir)
{
    char path[1024], line[1024];
    snprintf(path, sizeof path, "%s/%s/particles_final.csv", dir, r->name);
    FILE *f = fopen(path, "r");                  /* skip "# t = ..." and names */
    if (!f || !fgets(line, sizeof line, f) || !fgets(line, sizeof line, f)) {
        fprintf(stderr, "cannot read %s\n", path);
        if (f)
            fclose(f);
        return -1;
    }
    Particles *P = &r->sim->pts;
    for (int p = 0; p < P->n; p++) {
        double v[5];
        if (!fgets(line, sizeof line, f) ||
            sscanf(line, "%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3],
                   &v[4]) != 5) {
            fprintf(stderr, "%s: short file\n", path);
            fclose(f);
            return -1;
        }
        P->x[p] = v[0];
        P->y[p] = v[1];
        P->sxx[p] = v[4];
    }
    fclose(f);
    Crack *c = &cracks_of(r->sim)->crack[0];
    for (int k = 9; k >= 0; k--) {               /* the last snapshot */
        snprintf(path, sizeof path, "%s/%s/cracks_%05d.csv", dir, r->name, k);
        if (!(f = fopen(path, "r")))
            continue;
        while (fgets(line, sizeof line, f)) {
            int ci, pi;
            double x, y;
            if (sscanf(line, "%d,%d,%lf,%lf", &ci, &pi, &x, &y) == 4 && ci == 0) {
                c->x[pi] = x;
                c->y[pi] = y;
            }
        }
        fclose(f);
        return 0;
    }
    fprintf(stderr, "no cracks_*.csv in %s/%s\n", dir, r->name);
    return -1;
}

static int study(const char *dir)
{
    static const char *names[] = {
        "tip_node_2mm", "tip_mid_51", "tip_node_1mm", "tip_mid_101",
        "tip_node_05mm", "tip_mid_201"};
    enum { NALL = sizeof names / sizeof names[0] };
    const char *hs = getenv("TIP_FEA_H");
    double h = hs ? atof(hs) : 0.125;
    const char *csv = getenv("TIP_CSV_DIR");
    /* TIP_RUNS="name ...": only these runs of the list (chapter 8 reads
       the two tips on a node run with uGIMP); the FEA is loaded from
       tip_node_1mm's points where it is among them, else the first's */
    const char *only = getenv("TIP_RUNS");
    int NRUNS = 0, load = 0;
    for (int k = 0; k < NALL; k++) {
        const char *at = only ? strstr(only, names[k]) : names[k];
        size_t len = strlen(names[k]);
        if (at && (at[len] == '\0' || at[len] == ' ')) {
            if (!strcmp(names[k], "tip_node_1mm"))
                load = NRUNS;
            names[NRUNS++] = names[k];
        }
    }
    if (NRUNS == 0) {
        fprintf(stderr, "TIP_RUNS=%s: none of the study's runs\n", only);
        return 1;
    }
    Run runs[NALL];
    char err[1024], path[512];
    for (int k = 0; k < NRUNS; k++) {
        snprintf(path, sizeof path, SCENES "%s.cfg", names[k]);
        Sim *sim = load_scene(path, TIP, err, sizeof err);
        if (!sim) {
            fprintf(stderr, "%s\n", err);
            return 1;
        }
        run_init(&runs[k], names[k], sim);
    }
    Fea f;                       /* loaded where the points were at first */
    if (fea_init(&f, h, runs[load].sim)) {
        fprintf(stderr, "FEA failed\n");
        return 1;
    }
    for (int k = 0; k < NRUNS; k++)
        if (read_run(&runs[k], dir))
            return 1;
    printf("FEA: Q4, h = %g and %g mm, extrapolated to h = 0\n", h, h / 2);
    printf("(a) FEA at the node's x; (a') FEA at the same distance from the "
           "moved tip; (b) FEA at the points' initial positions, weights of "
           "the initial positions; (b') the same with the weights of the "
           "points' final positions (as the MPM)\n\n");
    for (int k = 0; k < NRUNS; k++) {
        Run *r = &runs[k];
        run_compare(r, &f);
        const Grid *g = &r->sim->grid;
        int last_split = first_node_after(r, r->tip) - 1;
        if (node_x(r, last_split) > r->tip)
            last_split--;
        int moved = 0, near = 0;      /* first row, 10 mm ahead of the tip */
        for (int p = 0; p < r->sim->pts.n; p++) {
            if (fabs(r->y0[p]) > g->dy || r->x0[p] < TIP || r->x0[p] > TIP + 10)
                continue;
            near++;
            moved += floor((r->x0[p] - g->ox) / g->dx) !=
                     floor((r->sim->pts.x[p] - g->ox) / g->dx);
        }
        double ke = NAN, se = NAN;
        snprintf(path, sizeof path, "%s/%s/history.csv", dir, r->name);
        FILE *h_f = fopen(path, "r");
        if (h_f) {
            char line[1024];
            while (fgets(line, sizeof line, h_f))
                sscanf(line, "%*f,%*f,%lf,%lf", &ke, &se);
            fclose(h_f);
        }
        printf("%s: dx = %.4f mm; static tip at x = %.4f (moved %+.4f); last "
               "split node x = %.4f, first shared node x = %.4f (%.2f dx ahead "
               "of the tip); kinetic / strain energy %.2g; points of the "
               "mid-plane rows within 10 mm ahead of the tip that changed "
               "cell: %d of %d\n", r->name, g->dx, r->tip, r->tip - TIP,
               node_x(r, last_split), node_x(r, last_split + 1),
               (node_x(r, last_split + 1) - r->tip) / g->dx, ke / se, moved, near);
        int shown = -1;
        for (int i = last_split + 1; i < g->nnx; i++) {
            double x = node_x(r, i);
            if (x > 80)
                break;
            if (x <= TIP + g->dx * 2.01 || i == node_near(r, 55) ||
                i == node_near(r, 60) || i == node_near(r, 70)) {
                if (i != shown)
                    print_row(r, i);
                shown = i;
            }
        }
        if (csv) {
            snprintf(path, sizeof path, "%s/%s.csv", csv, r->name);
            FILE *o = fopen(path, "w");
            if (!o) {
                fprintf(stderr, "cannot write %s\n", path);
                return 1;
            }
            fprintf(o, "x,r,mpm,fea_a,fea_a2,fea_b,fea_b2\n");
            for (int i = last_split + 1; i < g->nnx; i++)
                if (node_x(r, i) <= 100)
                    fprintf(o, "%.6f,%.6f,%.8g,%.8g,%.8g,%.8g,%.8g\n",
                            node_x(r, i), node_x(r, i) - r->tip, r->mpm[i],
                            r->a[i], r->a2[i], r->b[i], r->b2[i]);
            fclose(o);
        }
        printf("\n");
    }
    printf("Summary: MPM against the FEA, %% (first ligament node: the first "
           "node with x > 50)\n");
    printf("| run | dx | static tip | first node x | (a) | (a') | (b) | (b') "
           "| x ~ 55: (a) | (b') | x ~ 60: (a) | (b') | x ~ 70: (a) | (b') |\n");
    printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- "
           "| --- | --- | --- |\n");
    for (int k = 0; k < NRUNS; k++) {
        Run *r = &runs[k];
        int i = first_node_after(r, TIP);
        printf("| %s | %.4f | %.3f | %.3f | %+.1f | %+.1f | %+.1f | %+.1f |",
               r->name, r->sim->grid.dx, r->tip, node_x(r, i),
               100 * rel(r->mpm[i], r->a[i]), 100 * rel(r->mpm[i], r->a2[i]),
               100 * rel(r->mpm[i], r->b[i]), 100 * rel(r->mpm[i], r->b2[i]));
        double xs[] = {55, 60, 70};
        for (int m = 0; m < 3; m++) {
            int j = node_near(r, xs[m]);
            printf(" %+.1f | %+.1f |", 100 * rel(r->mpm[j], r->a[j]),
                   100 * rel(r->mpm[j], r->b2[j]));
        }
        printf("\n");
    }
    fea_free(&f);
    for (int k = 0; k < NRUNS; k++)
        run_free(&runs[k]);
    return 0;
}

int main(void)
{
    const char *dir = getenv("TIP_STUDY");
    if (dir)
        return study(dir);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tip_node_classification_is_not_the_cause),
        cmocka_unit_test(crack_length_is_seen_to_a_cell),
        cmocka_unit_test(tip_on_node_bounded_by_fea),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
