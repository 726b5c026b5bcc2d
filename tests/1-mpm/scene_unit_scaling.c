/**
 * @file scene_unit_scaling.c
 * @brief The same scene in two unit systems gives the same run: the half
 *        DCB of Fig. 1 in mm-g-ms (figures/fig1/dcb_half.cfg) and in SI
 *        (tests/1-mpm/scenes/dcb_half_si.cfg), 40 ms, full precision.
 *
 * Nothing in the method knows the units: every equation is homogeneous in
 * them, so scaling lengths, masses and times by 1e-3 scales every output by
 * its unit's factor (length, time, mass, energy and momentum 1e-3, stress
 * 1e6, velocity and strain 1) and changes nothing else: the same number of
 * steps, the same snapshots, every value the converted one.  Only rounding
 * differs (the scaled inputs are not exact binary multiples), a few ulp
 * per operation that the damped beam does not amplify.  The test converts
 * every number of every file (history.csv, particles_final.csv, each
 * grid_NNNNN.csv, each particles_NNNNN.vtu and particles.pvd) and asserts
 * agreement to 1e-12 of the largest value of the same kind in that file (a
 * column of pure round-off, such as the x momentum, is compared at the
 * scale of its kind, not at its own). An integer (step, material, body,
 * connectivity) must be equal. A column whose unit the test does not know
 * fails it, so that a new output column gets a unit here. The SI scene says
 * units = "SI" and gives no thickness: the default must be 1 mm there too
 * (1e-3 m), and the start line must say "s".
 */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testkit.h"

#define MM "build/test-unit-scaling/mm"
#define SI "build/test-unit-scaling/si"
#define TOL 1e-12

/** Kinds of quantity and the factor from mm-g-ms to SI. */
typedef enum { K_INT, K_LENGTH, K_TIME, K_VELOCITY, K_STRESS, K_STRAIN, K_MASS,
               K_ENERGY, K_MOMENTUM, K_KINDS } Kind;
static const double FACTOR[K_KINDS] = {1, 1e-3, 1e-3, 1, 1e6, 1, 1e-3, 1e-3, 1e-3};
static const char *const KIND_NAME[K_KINDS] = {"integer", "length", "time",
    "velocity", "stress", "strain", "mass", "energy", "momentum"};

/** The kind of a column or data array by its name; -1 if unknown. */
static int kind_of(const char *name)
{
    static const struct { const char *prefix; Kind kind; } rules[] = {
        {"step", K_INT}, {"material", K_INT}, {"body", K_INT},
        {"connectivity", K_INT}, {"offsets", K_INT}, {"types", K_INT},
        {"time", K_TIME}, {"TimeValue", K_TIME}, {"timestep", K_TIME},
        {"kinetic", K_ENERGY}, {"strain", K_ENERGY}, {"total", K_ENERGY},
        {"momentum", K_MOMENTUM}, {"x", K_LENGTH}, {"y", K_LENGTH},
        {"Points", K_LENGTH}, {"vx", K_VELOCITY}, {"vy", K_VELOCITY},
        {"velocity", K_VELOCITY}, {"sigma_", K_STRESS}, {"eps_", K_STRAIN},
        {"mass", K_MASS},
    };
    for (size_t k = 0; k < sizeof rules / sizeof rules[0]; k++) {
        size_t n = strlen(rules[k].prefix);
        /* "x" and "y" whole; the others as prefixes (kinetic_arm, ...) */
        if (n == 1 ? strcmp(name, rules[k].prefix) == 0
                   : strncmp(name, rules[k].prefix, n) == 0)
            return (int)rules[k].kind;
    }
    return -1;
}

/** The numbers of a file and the kind of each, in order. */
typedef struct Numbers {
    int n, cap;
    double *v;
    int *kind;
} Numbers;

static void push(Numbers *N, double v, int kind)
{
    if (N->n == N->cap) {
        N->cap = N->cap ? 2 * N->cap : 4096;
        N->v = realloc(N->v, sizeof(double) * (size_t)N->cap);
        N->kind = realloc(N->kind, sizeof(int) * (size_t)N->cap);
        assert_non_null(N->v);
        assert_non_null(N->kind);
    }
    N->v[N->n] = v;
    N->kind[N->n++] = kind;
}

/** A CSV file with a header row: every field, with its column's kind. */
static void read_csv(const char *path, Numbers *N)
{
    char *text = tk_slurp(path, NULL), *save = NULL;
    int kinds[64], ncol = 0;
    char *line = strtok_r(text, "\n", &save);
    assert_non_null(line);
    if (strncmp(line, "# t = ", 6) == 0) {    /* a snapshot's time and step */
        char *unit;
        push(N, strtod(line + 6, &unit), K_TIME);
        const char *step = strstr(unit, ", step ");
        assert_non_null(step);
        push(N, strtod(step + 7, NULL), K_INT);
        line = strtok_r(NULL, "\n", &save);
        assert_non_null(line);
    }
    for (char *c = line, *end; c; c = end ? end + 1 : NULL) {
        end = strchr(c, ',');
        if (end)
            *end = '\0';
        assert_true(ncol < 64);
        kinds[ncol] = kind_of(c);
        if (kinds[ncol] < 0)
            fail_msg("%s: column \"%s\" has no unit in this test", path, c);
        ncol++;
    }
    while ((line = strtok_r(NULL, "\n", &save)) != NULL) {
        int col = 0;
        for (char *c = line, *end; *c; c = end + (*end == ',')) {
            double v = strtod(c, &end);
            if (end == c || col >= ncol)
                fail_msg("%s: \"%s\" is not a row of %d numbers", path, line, ncol);
            push(N, v, kinds[col++]);
        }
        if (col != ncol)
            fail_msg("%s: a row of %d fields, not %d", path, col, ncol);
    }
    free(text);
}

/** An XML file (VTU, PVD): every number in an attribute value or between
 *  tags, with the kind of the attribute or of the data array it is in
 *  (by its Name, or Points). The words around must agree too: they are
 *  returned joined in @p words. */
static void read_xml(const char *path, Numbers *N, char **words)
{
    char *text = tk_slurp(path, NULL);
    size_t len = strlen(text), w = 0;
    char *out = malloc(len + 1);
    assert_non_null(out);
    int kind = -1;
    for (char *c = text; *c;) {
        char name[64];
        if (sscanf(c, "Name=\"%63[^\"]\"", name) == 1 || sscanf(c, "<%63[A-Za-z]>", name) == 1)
            if (kind_of(name) >= 0)
                kind = kind_of(name);
        if (strncmp(c, "timestep=\"", 10) == 0) {
            kind = K_TIME;
            memcpy(out + w, c, 10);
            w += 10;
            c += 10;
        } else if (c[0] == '=' && c[1] == '"') {  /* another attribute: a word */
            char *q = strchr(c + 2, '"');
            assert_non_null(q);
            memcpy(out + w, c, (size_t)(q + 1 - c));
            w += (size_t)(q + 1 - c);
            c = q + 1;
            continue;
        }
        if ((isdigit((unsigned char)*c) || *c == '-') &&
            !isalnum((unsigned char)c[-1]) && c[-1] != '_') {
            char *end;
            double v = strtod(c, &end);
            if (end != c && (*end == '"' || *end == '<' || isspace((unsigned char)*end))) {
                if (kind < 0)
                    fail_msg("%s: a number (%s) outside a named array", path, c);
                push(N, v, kind);
                out[w++] = '#';
                c = end;
                continue;
            }
        }
        out[w++] = *c++;
    }
    out[w] = '\0';
    *words = out;
    free(text);
}

/** Both files converted and compared; returns the worst relative error. */
static double compare(const char *file, int xml)
{
    char a[512], b[512];
    snprintf(a, sizeof a, MM "/%s", file);
    snprintf(b, sizeof b, SI "/%s", file);
    Numbers mm = {0}, si = {0};
    char *wa = NULL, *wb = NULL;
    if (xml) {
        read_xml(a, &mm, &wa);
        read_xml(b, &si, &wb);
        if (strcmp(wa, wb) != 0)
            fail_msg("%s: the two files differ in more than their numbers", file);
    } else {
        read_csv(a, &mm);
        read_csv(b, &si);
    }
    if (mm.n != si.n)
        fail_msg("%s: %d numbers in mm-g-ms, %d in SI", file, mm.n, si.n);
    double scale[K_KINDS] = {0}, worst = 0.0;
    for (int k = 0; k < mm.n; k++)
        scale[mm.kind[k]] = fmax(scale[mm.kind[k]], fabs(mm.v[k]));
    for (int k = 0; k < mm.n; k++) {
        int kind = mm.kind[k];
        if (si.kind[k] != kind)
            fail_msg("%s: number %d is a %s in one file, a %s in the other", file,
                     k, KIND_NAME[kind], KIND_NAME[si.kind[k]]);
        if (kind == K_INT) {
            if (mm.v[k] != si.v[k])
                fail_msg("%s: integer %d: %.17g against %.17g", file, k, mm.v[k], si.v[k]);
            continue;
        }
        double diff = fabs(si.v[k] / FACTOR[kind] - mm.v[k]);
        double err = scale[kind] > 0 ? diff / scale[kind] : diff;  /* all zero */
        if (!(err <= TOL))
            fail_msg("%s: number %d (a %s): %.17g mm-g-ms, %.17g SI: %.3g of the "
                     "largest %s", file, k, KIND_NAME[kind], mm.v[k], si.v[k], err,
                     KIND_NAME[kind]);
        worst = fmax(worst, err);
    }
    free(mm.v);
    free(mm.kind);
    free(si.v);
    free(si.kind);
    free(wa);
    free(wb);
    return worst;
}

static void same_run_in_two_unit_systems(void **state)
{
    (void)state;
    char out[8192];
    int rc = tk_run_mpm("figures/fig1/dcb_half.cfg -q -o " MM " run.time=40.0 "
                        "run.snapshots=4 run.precision=full", out, sizeof out);
    assert_int_equal(rc, 0);
    assert_non_null(strstr(out, "dt = 0.113347 ms, 353 steps"));
    rc = tk_run_mpm("tests/1-mpm/scenes/dcb_half_si.cfg -q -o " SI " run.time=0.04 "
                    "run.snapshots=4 run.precision=full", out, sizeof out);
    assert_int_equal(rc, 0);                /* units = "SI": its words, its thickness */
    assert_non_null(strstr(out, "dt = 0.000113347 s, 353 steps"));
    static const char *const csv[] = {"history.csv", "particles_final.csv",
        "grid_00000.csv", "grid_00001.csv", "grid_00002.csv", "grid_00003.csv",
        "grid_00004.csv"};
    static const char *const xml[] = {"particles.pvd", "particles_00000.vtu",
        "particles_00001.vtu", "particles_00002.vtu", "particles_00003.vtu",
        "particles_00004.vtu"};
    double worst = 0.0;
    for (size_t k = 0; k < sizeof csv / sizeof csv[0]; k++)
        worst = fmax(worst, compare(csv[k], 0));
    for (size_t k = 0; k < sizeof xml / sizeof xml[0]; k++)
        worst = fmax(worst, compare(xml[k], 1));
    printf("  13 files, every number: largest difference after conversion "
           "%.3g of its kind's largest value (bound %g)\n", worst, TOL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(same_run_in_two_unit_systems),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
