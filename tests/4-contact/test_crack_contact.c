/**
 * @file test_crack_contact.c
 * @brief Crack contact on a real grid: the two halves of a block cut by a
 *        crack are given velocities by hand, Tasks 0-2 run, and the contact
 *        subscriber adjusts the nodes (section 2.2).
 *
 * The crack runs left to right through the middle of a row of cells, so
 * its normal (above to below) is (0, -1) and every node next to it carries
 * field 0 and field 1 or 2. Checked at every node: the momentum summed
 * over its fields is unchanged to round-off; where the halves approach,
 * the normal relative velocity is removed (frictionless and stick) and,
 * frictionless, the tangential one is kept; where they separate, nothing
 * changes, bit for bit.
 */
#include "testkit.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "crack_contact.h"
#include "step.h"

static const char *scene =
    "grid = { origin = [0.0, 0.0]; cells = [12, 12]; cell_size = [1.0, 1.0]; };\n"
    "run = { time = 1.0; snapshots = 0; };\n"
    "materials = ( { name = \"m\"; E = 1.0; nu = 0.3; rho = 1.0e-3; } );\n"
    "bodies = ( { material = \"m\"; rectangle = { min = [2.0, 2.0]; max = [10.0, 10.0]; }; } );\n"
    "cracks = ( { points = ( [3.0, 6.5], [9.0, 6.5] ); contact = { law = \"frictionless\"; }; } );\n";

/** Load the scene with @p law (and mu); halves at (u, -v) above, (-u, v)
 *  below; run Tasks 0-2 up to the contact seam. */
static Sim *halves(ContactLawKind law, double mu, double u, double v)
{
    Sim *sim = tk_load(scene);
    ContactState *S = sim_state(sim, "crack contact");
    assert_non_null(S);
    S->crack[0].law.kind = law;
    S->crack[0].law.mu = mu;
    Particles *P = &sim->pts;
    for (int p = 0; p < P->n; p++) {
        int above = P->y[p] > 6.5;
        P->vx[p] = above ? u : -u;
        P->vy[p] = above ? -v : v;
    }
    grid_clear(&sim->grid, 1);
    locate_points(sim);
    assert_int_equal(assign_fields(sim), 0);
    extrapolate(sim, EXTRAP_MASS | EXTRAP_FORCE);
    grid_velocities(sim);
    return sim;
}

/** Per node: momentum summed over its fields. */
static void node_momenta(const Sim *sim, double *px, double *py)
{
    const Grid *g = &sim->grid;
    for (int n = 0; n < g->nnodes; n++) {
        px[n] = py[n] = 0;
        for (int s = n; s >= 0; s = field_next(&sim->fields, g, s)) {
            px[n] += g->px[s];
            py[n] += g->py[s];
        }
    }
}

/** The fields of node @p n in contact: a (above), b (below); 0 if none. */
static int pair_at(const Sim *sim, int n, int *a, int *b)
{
    const Grid *g = &sim->grid;
    int f[3] = {-1, -1, -1};
    for (int s = n; s >= 0; s = field_next(&sim->fields, g, s))
        if (g->m[s] > 0)
            f[field_key(&sim->fields, g, s)] = s;
    if (f[0] >= 0 && f[1] >= 0) {
        *a = f[1];
        *b = f[0];
        return 1;
    }
    if (f[0] >= 0 && f[2] >= 0) {
        *a = f[0];
        *b = f[2];
        return 1;
    }
    return 0;
}

/** Run the Task 2 contact on halves moving as given; check the node
 *  momenta, and return the number of nodes with two fields. */
static int check_contact(ContactLawKind law, double u, double v, int expect_change)
{
    Sim *sim = halves(law, 0.0, u, v);
    Grid *g = &sim->grid;
    ContactState *S = sim_state(sim, "crack contact");
    int nn = g->nnodes, ns = g->nslots;
    double *px0 = malloc(sizeof(double) * (size_t)nn), *py0 = malloc(sizeof(double) * (size_t)nn);
    double *px1 = malloc(sizeof(double) * (size_t)nn), *py1 = malloc(sizeof(double) * (size_t)nn);
    double *gx = malloc(sizeof(double) * (size_t)ns), *gy = malloc(sizeof(double) * (size_t)ns);
    node_momenta(sim, px0, py0);
    memcpy(gx, g->px, sizeof(double) * (size_t)ns);
    memcpy(gy, g->py, sizeof(double) * (size_t)ns);
    assert_int_equal(crack_contact_task(sim, S, SEAM_TASK2_CONTACT), 0);
    /* the normal of every extra slot, summed at the step's first contact:
       (0, -1), above to below */
    for (int s = nn; s < ns; s++) {
        const CrackNormals *N = &S->normals;
        double len = hypot(N->nx[s - nn], N->ny[s - nn]);
        assert_close(N->nx[s - nn] / len, 0.0, 1e-15);
        assert_close(N->ny[s - nn] / len, -1.0, 1e-15);
        assert_int_equal(N->tag[s - nn], 0);
    }
    node_momenta(sim, px1, py1);
    int pairs = 0;
    for (int n = 0; n < nn; n++) {
        double scale = 0;
        for (int s = n; s >= 0; s = field_next(&sim->fields, g, s))
            scale += fabs(gx[s]) + fabs(gy[s]);
        assert_close(px1[n], px0[n], 4 * DBL_EPSILON * scale);
        assert_close(py1[n], py0[n], 4 * DBL_EPSILON * scale);
        int a, b;
        if (!pair_at(sim, n, &a, &b))
            continue;
        pairs++;
        double dvx = g->px[a] / g->m[a] - g->px[b] / g->m[b];
        double dvy = g->py[a] / g->m[a] - g->py[b] / g->m[b];
        double dvx0 = gx[a] / g->m[a] - gx[b] / g->m[b];
        if (!expect_change) {                /* separating: left alone */
            assert_true(g->px[a] == gx[a] && g->py[a] == gy[a]);
            assert_true(g->px[b] == gx[b] && g->py[b] == gy[b]);
            continue;
        }
        assert_close(dvy, 0.0, 1e-12 * (fabs(u) + fabs(v)));   /* normal removed */
        if (law == CONTACT_STICK)
            assert_close(dvx, 0.0, 1e-12 * (fabs(u) + fabs(v)));
        else
            assert_close(dvx, dvx0, 1e-12 * fabs(dvx0) + 1e-300);
    }
    printf("  law %d, u = %g, v = %g: %d nodes with both sides, %d adjusted\n",
           (int)law, u, v, pairs, S->task_nodes);
    assert_int_equal(S->task_nodes, expect_change ? pairs : 0);
    free(px0);
    free(py0);
    free(px1);
    free(py1);
    free(gx);
    free(gy);
    tk_free(sim);
    return pairs;
}

static void approaching_halves_frictionless(void **state)
{
    (void)state;
    assert_true(check_contact(CONTACT_FRICTION, 0.3, 0.1, 1) >= 5);
}

static void approaching_halves_stick(void **state)
{
    (void)state;
    assert_true(check_contact(CONTACT_STICK, 0.3, 0.1, 1) >= 5);
}

static void separating_halves_are_left_alone(void **state)
{
    (void)state;
    assert_true(check_contact(CONTACT_FRICTION, 0.3, -0.1, 0) >= 5);
    assert_true(check_contact(CONTACT_STICK, 0.3, -0.1, 0) >= 5);
}

static void contact_off_changes_nothing(void **state)
{
    (void)state;
    assert_true(check_contact(CONTACT_NONE, 0.3, 0.1, 0) >= 5);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(approaching_halves_frictionless),
        cmocka_unit_test(approaching_halves_stick),
        cmocka_unit_test(separating_halves_are_left_alone),
        cmocka_unit_test(contact_off_changes_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
