/**
 * @file main.c
 * @brief The mpm program: the one place that knows which stages a build has.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim.h"
#include "stages.h"


static void usage(FILE *f)
{
    fprintf(f,
        "usage: mpm SCENE [-o OUTDIR] [-q] [--max-memory MB] [key.path=value ...]\n"
        "\n"
        "Run the material point method (stage %d of the book) on SCENE, a\n"
        "libconfig file in units of mm, g and ms (force N, stress MPa,\n"
        "velocity m/s, energy mJ), or of m, kg and s with run.units = \"SI\".\n"
        "\n"
        "  -o OUTDIR   write output here (default: output)\n"
        "  -q          no progress line\n"
        "  --max-memory MB  refuse a scene estimated to need more than MB\n"
        "              megabytes (10^6 bytes; default: the memory available)\n"
        "  -h, --help  this text\n"
        "  key.path=value  override a scene setting, e.g. run.update=usf\n"
        "                  run.time=2.5 run.cfl=0.2 run.snapshots=0\n"
        "\n"
        "OUTDIR receives history.csv (energies, momentum), particles_NNNNN.vtu\n"
        "with particles.pvd (open in ParaView), grid_NNNNN.csv (stresses\n"
        "extrapolated to the nodes) and particles_final.csv.\n"
        "Exit status: 0 done, 1 bad input, 2 output error, 3 unstable run.\n",
        mpm_stage());
}

/** Parse the command line, load the scene with this build's stages, run
 *  it; the exit status is that of sim_run(), or 1 for bad input. */
int main(int argc, char **argv)
{
    const char *scene = NULL, *outdir = "output";
    char **over = calloc((size_t)argc + 1, sizeof(char *));
    int nover = 0, quiet = 0;
    double max_mb = 0.0;
    if (!over)
        return 1;
    for (int k = 1; k < argc; k++) {
        if (!strcmp(argv[k], "-h") || !strcmp(argv[k], "--help")) {
            usage(stdout);
            free(over);
            return 0;
        } else if (!strcmp(argv[k], "-o") && k + 1 < argc) {
            outdir = argv[++k];
        } else if (!strcmp(argv[k], "-q")) {
            quiet = 1;
        } else if (!strcmp(argv[k], "--max-memory") && k + 1 < argc) {
            char *end;
            max_mb = strtod(argv[++k], &end);
            if (end == argv[k] || *end || !(max_mb >= 1e-6 && max_mb <= 1e12)) {
                fprintf(stderr, "mpm: --max-memory %s: expected megabytes in "
                        "[1e-6, 1e12]\n", argv[k]);
                free(over);
                return 1;
            }
        } else if (argv[k][0] == '-') {
            fprintf(stderr, "mpm: unknown option %s\n", argv[k]);
            usage(stderr);
            free(over);
            return 1;
        } else if (strchr(argv[k], '=')) {
            over[nover++] = argv[k];
        } else if (!scene) {
            scene = argv[k];
        } else {
            fprintf(stderr, "mpm: more than one scene given (%s, %s)\n", scene, argv[k]);
            free(over);
            return 1;
        }
    }
    if (!scene) {
        usage(stderr);
        free(over);
        return 1;
    }
    Sim *sim = malloc(sizeof *sim);
    if (!sim) {
        free(over);
        return 1;
    }
    sim_init(sim);
    sim->memory_limit = (size_t)(max_mb * 1e6);
    mpm_install_stages(&sim->hooks);
    char err[1024];
    if (sim_load_file(sim, scene, nover, over, err, sizeof err)) {
        fprintf(stderr, "mpm: %s\n", err);
        sim_free(sim);
        free(sim);
        free(over);
        return 1;
    }
    printf("mpm (stage %d): %s: %d points, grid %d x %d cells, dt = %.6g %s, "
           "%ld steps, update %s\n", mpm_stage(), scene, sim->pts.n,
           sim->scene.ncx, sim->scene.ncy, sim->dt, sim->scene.run.units->time,
           sim->nsteps, sim->scene.run.scheme->name);
    fflush(stdout);
    int rc = sim_run(sim, outdir, !quiet);
    if ((rc == 0 || rc == 3) && hooks_run_report(sim, stdout))
        rc = rc ? rc : 2;
    if (rc == 0)
        printf("mpm: done, output in %s (%ld steps in %.3f s, %.3g particle-steps/s)\n",
               outdir, sim->step, sim->loop_seconds,
               sim->loop_seconds > 0 ? sim->pts.n * (double)sim->step / sim->loop_seconds : 0.0);
    sim_free(sim);
    free(sim);
    free(over);
    return rc;
}
