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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(crack_output_files),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
