/**
 * @file test_vtu_binary.c
 * @brief The binary snapshots (run.output = "binary", vtu_binary.h): read
 *        back here by their own XML header and appended blocks, they hold
 *        exactly the points' and the grid's numbers, bit for bit, with the
 *        offsets, counts and sizes VTK's format asks for.
 *
 * The colliding disks (tests/1-mpm/scenes/disks.cfg) after 30 steps: the
 * points' file against the simulation's arrays (every double equal as
 * bits); the grid's file against the CSV that the text output writes with
 * run.precision = "full" (17 digits, which strtod reads back to the same
 * double); the final points' file equal to the snapshot's.
 */
#include "testkit.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "output.h"

#define SCENE "tests/1-mpm/scenes/disks.cfg"
#define DIR_B "build/test-vtu-binary/binary"
#define DIR_A "build/test-vtu-binary/ascii"

/** The appended block of the DataArray named @p name ("" for the Points'
 *  unnamed array): its bytes and their count, checked against @p want. */
static const unsigned char *block(const char *file, size_t len, const char *name,
                                  uint64_t want)
{
    const char *data = strstr(file, "<AppendedData encoding=\"raw\">\n_");
    assert_non_null(data);
    data += strlen("<AppendedData encoding=\"raw\">\n_");
    char key[96];
    if (*name)
        snprintf(key, sizeof key, "Name=\"%s\"", name);
    else
        snprintf(key, sizeof key, "<Points>\n<DataArray");
    const char *at = strstr(file, key);
    assert_non_null(at);
    assert_true(at < data);
    const char *o = strstr(at, "offset=\"");
    assert_non_null(o);
    unsigned long long off = strtoull(o + 8, NULL, 10);
    assert_true((size_t)(data - file) + off + 8 <= len);
    uint64_t count;
    memcpy(&count, data + off, sizeof count);
    assert_int_equal(count, want);
    assert_true((size_t)(data - file) + off + 8 + count <= len);
    return (const unsigned char *)data + off + 8;
}

/** The doubles at @p b equal @p x (ncomp 1) or (x, y, 0) (ncomp 3). */
static void same_doubles(const unsigned char *b, const double *x,
                         const double *y, int ncomp, int n)
{
    for (int p = 0; p < n; p++)
        for (int c = 0; c < ncomp; c++) {
            double v;
            memcpy(&v, b + sizeof(double) * (size_t)(ncomp * p + c), sizeof v);
            double want = c == 0 ? x[p] : c == 1 ? y[p] : 0.0;
            if (memcmp(&v, &want, sizeof v) != 0)
                fail_msg("value %d.%d: %.17g in the file, %.17g in the run", p,
                         c, v, want);
        }
}

static void points_and_grid_to_the_last_bit(void **state)
{
    (void)state;
    const char *ob[] = {"run.output=\"binary\"", "run.snapshots=0", NULL};
    const char *oa[] = {"run.precision=\"full\"", "run.snapshots=0", NULL};
    Sim *sb = tk_load_file(SCENE, ob), *sa = tk_load_file(SCENE, oa);
    tk_steps(sb, 30);
    tk_steps(sa, 30);
    double times[1] = {sb->t};
    assert_int_equal(output_make_dir(DIR_B), 0);
    assert_int_equal(output_make_dir(DIR_A), 0);
    assert_int_equal(output_snapshot(sb, DIR_B, 0, times), 0);
    assert_int_equal(output_snapshot(sa, DIR_A, 0, times), 0);
    assert_int_equal(output_points_final(sb, DIR_B), 0);

    const Particles *P = &sb->pts;
    int n = P->n;
    size_t len;
    char *f = tk_slurp(DIR_B "/particles_00000.vtu", &len);
    char want[64];
    snprintf(want, sizeof want, "NumberOfPoints=\"%d\" NumberOfCells=\"%d\"", n, n);
    assert_non_null(strstr(f, want));
    uint64_t nd = (uint64_t)n * sizeof(double);
    same_doubles(block(f, len, "", 3 * nd), P->x, P->y, 3, n);
    same_doubles(block(f, len, "velocity", 3 * nd), P->vx, P->vy, 3, n);
    same_doubles(block(f, len, "sigma_xx", nd), P->sxx, NULL, 1, n);
    same_doubles(block(f, len, "eps_xy", nd), P->exy, NULL, 1, n);
    same_doubles(block(f, len, "mass", nd), P->m, NULL, 1, n);
    const unsigned char *conn = block(f, len, "connectivity", (uint64_t)n * 4);
    const unsigned char *offs = block(f, len, "offsets", (uint64_t)n * 4);
    const unsigned char *types = block(f, len, "types", (uint64_t)n);
    const unsigned char *body = block(f, len, "body", (uint64_t)n * 4);
    for (int p = 0; p < n; p++) {
        int32_t c, o, bd;
        memcpy(&c, conn + 4 * (size_t)p, 4);
        memcpy(&o, offs + 4 * (size_t)p, 4);
        memcpy(&bd, body + 4 * (size_t)p, 4);
        assert_int_equal(c, p);
        assert_int_equal(o, p + 1);
        assert_int_equal(types[p], 1);                 /* VTK_VERTEX */
        assert_int_equal(bd, P->body[p]);
    }
    const char *end = "\n</AppendedData>\n</VTKFile>\n";   /* after the data */
    assert_true(len > strlen(end));
    assert_memory_equal(f + len - strlen(end), end, strlen(end));
    size_t lenf;
    char *g = tk_slurp(DIR_B "/particles_final.vtu", &lenf);
    assert_int_equal(lenf, len);
    assert_memory_equal(f, g, len);                    /* same time, same state */
    free(g);
    free(f);

    /* the grid: the text file's 17 digits, read back, against the bits */
    char *csv = tk_slurp(DIR_A "/grid_00000.csv", &len);
    size_t lg;
    char *gv = tk_slurp(DIR_B "/grid_00000.vtu", &lg);
    int rows = 0;
    double x[4096], y[4096], m[4096], sxx[4096];
    char *line = strtok(csv, "\n");
    while (line) {
        if (line[0] != '#' && line[0] != 'x') {
            assert_true(rows < 4096);
            assert_int_equal(sscanf(line, "%lf,%lf,%lf,%lf", &x[rows], &y[rows],
                                    &m[rows], &sxx[rows]), 4);
            rows++;
        }
        line = strtok(NULL, "\n");
    }
    assert_true(rows > 100);
    snprintf(want, sizeof want, "NumberOfPoints=\"%d\"", rows);
    assert_non_null(strstr(gv, want));
    uint64_t rd = (uint64_t)rows * sizeof(double);
    same_doubles(block(gv, lg, "", 3 * rd), x, y, 3, rows);
    same_doubles(block(gv, lg, "mass", rd), m, NULL, 1, rows);
    same_doubles(block(gv, lg, "sigma_xx", rd), sxx, NULL, 1, rows);
    printf("  %d points and %d grid nodes read back from the binary files, "
           "every double equal to the run's (or to the text's 17 digits)\n",
           n, rows);
    free(gv);
    free(csv);
    tk_free(sb);
    tk_free(sa);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(points_and_grid_to_the_last_bit),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
