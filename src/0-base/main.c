/**
 * @file main.c
 * @brief The mpm program: the one place that knows which stages a build has.
 */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "checkpoint.h"
#include "run.h"
#include "scene_load.h"
#include "scene_keys.h"
#include "sim.h"
#include "stages.h"

/* The one variable of the program that is not in a struct: a signal
   handler can reach nothing else. It holds the number of the signal
   (SIGINT, SIGTERM) that asked the run to stop, 0 before. */
static volatile sig_atomic_t stop_signal;

static void on_stop_signal(int signo)
{
    stop_signal = signo;
}

/** SIGINT and SIGTERM end the run after the step it is in (a second one
 *  ends it at once); writes to a full file fail with EFBIG instead of
 *  killing the program (SIGXFSZ), so that the message names the file. */
static void install_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop_signal;
    sa.sa_flags = SA_RESTART | SA_RESETHAND;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    signal(SIGXFSZ, SIG_IGN);
}

/** The help text; the scene sections and the stages' output files are
 *  this build's, read from the registries its stages fill. */
static void usage(FILE *f)
{
    Hooks h;
    char sections[256], outputs[1024] = "";
    memset(&h, 0, sizeof h);
    mpm_install_stages(&h);
    scene_sections_list(&h, sections, sizeof sections);
    for (int k = 0; k < h.noutputs; k++)
        snprintf(outputs + strlen(outputs), sizeof outputs - strlen(outputs),
                 ";\n%s", h.outputs[k]);
    fprintf(f,
        "usage: mpm SCENE [-o OUTDIR] [-q] [--stop-at STEP] [--max-memory MB]\n"
        "           [key.path=value ...]\n"
        "       mpm --restart OUTDIR [-q] [--stop-at STEP] [--max-memory MB]\n"
        "\n"
        "Run the material point method (stage %d of the book) on SCENE, a\n"
        "libconfig file in units of mm, g and ms (force N, stress MPa,\n"
        "velocity m/s, energy mJ), or of m, kg and s with run.units = \"SI\".\n"
        "\n"
        "  -o OUTDIR        write output here (default: output)\n"
        "  -q               no progress line\n"
        "  --stop-at STEP   stop after step STEP, writing a checkpoint\n"
        "  --restart OUTDIR go on from OUTDIR/checkpoint.mpm (written every\n"
        "                   run.checkpoint_every steps, at --stop-at, and when\n"
        "                   the run is interrupted) with the same scene\n"
        "  --max-memory MB  refuse a scene estimated to need more than MB\n"
        "                   megabytes (10^6 bytes; default: the memory available)\n"
        "  --keys           print every scene key this build accepts, with the\n"
        "                   stage that adds it\n"
        "  -h, --help       this text\n"
        "  key.path=value   override a scene setting, e.g. run.update=usf\n"
        "                   run.time=2.5 run.cfl=0.2 run.snapshots=0\n"
        "\n"
        "Scene sections of this build:\n  %s.\n"
        "Every key with its type, unit, default and range: the book's page\n"
        "\"Scene reference\" (chapters/scene-reference.md).\n"
        "\n"
        "OUTDIR receives history.csv (energies, momentum), particles_NNNNN.vtu\n"
        "with particles.pvd (open in ParaView), grid_NNNNN.csv (stresses\n"
        "extrapolated to the nodes) and particles_final.csv%s; each file is\n"
        "written whole under a temporary name, then renamed. With\n"
        "run.output = \"binary\" the snapshots, the grid's (grid_NNNNN.vtu)\n"
        "and the final points (particles_final.vtu) are binary .vtu, every\n"
        "number to the last bit.\n"
        "SIGINT or SIGTERM stop the run after its current step with the points\n"
        "and a checkpoint written.\n"
        "Exit status: 0 done (or stopped at --stop-at), 1 bad input, 2 output\n"
        "error, 3 unstable run (or stopped by a rule: a crack out of room to\n"
        "grow), 130 interrupted (SIGINT), 143 (SIGTERM).\n",
        mpm_stage(), sections, outputs);
}

/** What the command line asks. */
typedef struct Args {
    const char *scene;   /**< the scene file */
    const char *outdir;  /**< -o, or the directory of --restart */
    char **over;         /**< overrides */
    int nover;           /**< how many */
    int quiet;           /**< -q */
    int restart;         /**< --restart */
    long stop_at;        /**< --stop-at, 0: none */
    int named_out;       /**< -o was given */
    double max_mb;       /**< --max-memory, 0: the memory available */
} Args;

/** @return -1 to go on, else the exit status (after help or an error). */
static int parse_args(int argc, char **argv, Args *a)
{
    for (int k = 1; k < argc; k++) {
        const char *s = argv[k];
        if (!strcmp(s, "-h") || !strcmp(s, "--help")) {
            usage(stdout);
            return 0;
        } else if (!strcmp(s, "--keys")) {
            Hooks h;
            memset(&h, 0, sizeof h);
            mpm_install_stages(&h);
            return scene_keys_print(&h, mpm_stage(), stdout) ? 2 : 0;
        } else if (!strcmp(s, "-o") && k + 1 < argc) {
            a->outdir = argv[++k];
            a->named_out = 1;
        } else if (!strcmp(s, "-q")) {
            a->quiet = 1;
        } else if (!strcmp(s, "--restart") && k + 1 < argc) {
            a->outdir = argv[++k];
            a->restart = 1;
        } else if (!strcmp(s, "--stop-at") && k + 1 < argc) {
            char *end;
            errno = 0;
            a->stop_at = strtol(argv[++k], &end, 10);
            if (errno || *end || end == argv[k] || a->stop_at < 1) {
                fprintf(stderr, "mpm: --stop-at %s: expected a step number >= 1\n",
                        argv[k]);
                return 1;
            }
        } else if (!strcmp(s, "--max-memory") && k + 1 < argc) {
            char *end;
            a->max_mb = strtod(argv[++k], &end);
            if (end == argv[k] || *end || !(a->max_mb >= 1e-6 && a->max_mb <= 1e12)) {
                fprintf(stderr, "mpm: --max-memory %s: expected megabytes in "
                        "[1e-6, 1e12]\n", argv[k]);
                return 1;
            }
        } else if (s[0] == '-') {
            fprintf(stderr, "mpm: unknown option %s\n", s);
            usage(stderr);
            return 1;
        } else if (strchr(s, '=')) {
            a->over[a->nover++] = argv[k];
        } else if (!a->scene) {
            a->scene = s;
        } else {
            fprintf(stderr, "mpm: more than one scene given (%s, %s)\n", a->scene, s);
            return 1;
        }
    }
    if (a->restart && (a->scene || a->nover || a->named_out)) {
        fprintf(stderr, "mpm: --restart takes the scene and its overrides from "
                "the checkpoint, and writes into its directory; give no scene, "
                "override or -o\n");
        return 1;
    }
    if (!a->scene && !a->restart) {
        usage(stderr);
        return 1;
    }
    return -1;
}

/** Load the scene (for --restart, the checkpoint's), run it, report;
 *  the exit status of sim_run(), or 1 for bad input. */
static int load_and_run(Sim *sim, Args *a)
{
    CheckpointScene cs = {NULL, 0, NULL};
    char err[2048];
    if (a->restart) {
        if (checkpoint_scene(a->outdir, mpm_stage(), &cs, err, sizeof err)) {
            fprintf(stderr, "mpm: --restart: %s\n", err);
            return 1;
        }
        a->scene = cs.path;
    }
    int rc = 1;
    if (sim_load_file(sim, a->scene, a->restart ? cs.noverrides : a->nover,
                      a->restart ? cs.overrides : a->over, err, sizeof err)) {
        fprintf(stderr, "mpm: %s\n", err);
        goto done;
    }
    const Method *method = sim->scene.run.method;
    int mpm = method_reads(method, "run.update");  /* an update scheme */
    printf("mpm (stage %d): %s: %d points, grid %d x %d cells, dt = %.6g %s, "
           "%ld steps, %s %s, %d thread%s\n", mpm_stage(), a->scene, sim->pts.n,
           sim->scene.ncx, sim->scene.ncy, sim->dt, sim->scene.run.units->time,
           sim->nsteps, mpm ? "update" : "method",
           mpm ? sim->scene.run.scheme->name : method->name, sim->threads,
           sim->threads == 1 ? "" : "s");
    fflush(stdout);
    RunOptions opt = {!a->quiet, a->restart, a->stop_at, &stop_signal};
    rc = sim_run(sim, a->outdir, &opt);
    int ended = sim->step == sim->nsteps;
    if ((rc == 0 || rc == 3) && ended && hooks_run_report(sim, stdout))
        rc = rc ? rc : 2;
    if (rc == 0 && ended)
        printf("mpm: done, output in %s (%ld steps in %.3f s, %.3g particle-steps/s)\n",
               a->outdir, sim->loop_steps, sim->loop_seconds,
               sim->loop_seconds > 0 ?
               sim->pts.n * (double)sim->loop_steps / sim->loop_seconds : 0.0);
done:
    checkpoint_scene_free(&cs);
    return rc;
}

/** Parse the command line, load the scene with this build's stages, run
 *  it; the exit status is that of sim_run(), or 1 for bad input. */
int main(int argc, char **argv)
{
    Args a = {NULL, "output", calloc((size_t)argc + 1, sizeof(char *)), 0, 0, 0, 0, 0, 0.0};
    Sim *sim = malloc(sizeof *sim);
    if (!a.over || !sim) {
        fprintf(stderr, "mpm: out of memory\n");
        free(a.over);
        free(sim);
        return 1;
    }
    int rc = parse_args(argc, argv, &a);
    if (rc < 0) {
        install_signals();
        sim_init(sim);
        sim->memory_limit = (size_t)(a.max_mb * 1e6);
        mpm_install_stages(&sim->hooks);
        rc = load_and_run(sim, &a);
        sim_free(sim);
    }
    free(sim);
    free(a.over);
    return rc;
}
