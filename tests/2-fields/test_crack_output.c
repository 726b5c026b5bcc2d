/**
 * @file test_crack_output.c
 * @brief Stage 2's outputs: the cracks in every snapshot and the number of
 *        multi-field nodes in history.csv.
 */
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/** The program writes the cracks with every snapshot (ParaView polyline
 *  and CSV) and counts the multi-field nodes in history.csv. */
static void crack_output_files(void **state)
{
    (void)state;
    char out[4096];
    assert_int_equal(tk_run_mpm("figures/fig1/dcb_full.cfg -q -o "
                                "build/test-out/crack-output run.time=1.0 "
                                "run.snapshots=2", out, sizeof out), 0);
    char *hist = tk_slurp("build/test-out/crack-output/history.csv", NULL);
    assert_non_null(strstr(hist, ",multi_field_nodes\n"));
    /* the last row: the DCB's crack splits 26 nodes of the mid-plane */
    char *last = hist + strlen(hist) - 1;
    while (last > hist && last[-1] != '\n')
        last--;
    assert_int_equal(atoi(strrchr(last, ',') + 1), 26);
    free(hist);
    for (int k = 0; k <= 2; k++) {
        char path[256];
        snprintf(path, sizeof path, "build/test-out/crack-output/cracks_%05d.csv", k);
        char *csv = tk_slurp(path, NULL);
        assert_true(strncmp(csv, "# t = ", 6) == 0);   /* the snapshot's time */
        assert_non_null(strstr(csv, "\ncrack,point,x,y\n0,0,"));
        assert_non_null(strstr(csv, "\n0,1,"));
        free(csv);
        snprintf(path, sizeof path, "build/test-out/crack-output/cracks_%05d.vtp", k);
        char *vtp = tk_slurp(path, NULL);
        assert_non_null(strstr(vtp, "NumberOfPoints=\"2\" NumberOfLines=\"1\""));
        assert_non_null(strstr(vtp, "</VTKFile>"));
        free(vtp);
    }
}

/** The DataSet entries of the series @p path: their timesteps and files,
 *  at most @p max; @return how many. */
static int series_entries(const char *path, char time[][32], char file[][32],
                          int max)
{
    char *pvd = tk_slurp(path, NULL);
    int n = 0;
    assert_non_null(strstr(pvd, "<VTKFile type=\"Collection\""));
    assert_non_null(strstr(pvd, "</Collection>\n</VTKFile>\n"));
    for (const char *e = strstr(pvd, "<DataSet "); e; e = strstr(e + 1, "<DataSet ")) {
        assert_true(n < max);
        if (sscanf(e, "<DataSet timestep=\"%31[^\"]\" file=\"%31[^\"]\"/>",
                   time[n], file[n]) != 2)
            fail_msg("%s: entry %d is not <DataSet timestep=... file=.../>", path, n);
        n++;
    }
    free(pvd);
    return n;
}

/** cracks.pvd lists every cracks_NNNNN.vtp, at the times particles.pvd
 *  gives the snapshots, so that ParaView opens the cracks as one series
 *  that moves with the points. */
static void crack_series_follows_the_points(void **state)
{
    (void)state;
    char out[4096], ct[8][32], cf[8][32], pt[8][32], pf[8][32];
    /* no file of an earlier run may stand in for one this run must write */
    assert_int_equal(tk_shell("rm -rf build/test-out/crack-series", out, sizeof out), 0);
    assert_int_equal(tk_run_mpm("figures/fig1/dcb_full.cfg -q -o "
                                "build/test-out/crack-series run.time=3.0 "
                                "run.snapshots=3", out, sizeof out), 0);
    int nc = series_entries("build/test-out/crack-series/cracks.pvd", ct, cf, 8);
    int np = series_entries("build/test-out/crack-series/particles.pvd", pt, pf, 8);
    assert_int_equal(np, 4);                    /* t = 0 and three more */
    assert_int_equal(nc, np);
    for (int k = 0; k < nc; k++) {
        char name[32], path[256];
        snprintf(name, sizeof name, "cracks_%05d.vtp", k);
        assert_string_equal(cf[k], name);
        assert_string_equal(ct[k], pt[k]);       /* the same time, as written */
        snprintf(path, sizeof path, "build/test-out/crack-series/%s", cf[k]);
        free(tk_slurp(path, NULL));              /* the file is there */
    }
    assert_true(strcmp(ct[0], "0") == 0 && atof(ct[nc - 1]) > 2.9);
    FILE *more = fopen("build/test-out/crack-series/cracks_00004.vtp", "r");
    assert_null(more);                           /* and no file is left out */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(crack_output_files),
        cmocka_unit_test(crack_series_follows_the_points),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
