/**
 * @file fuzz_scene.c
 * @brief The fuzz target of the scene reader (libFuzzer, `make fuzz`; and
 *        replayed by tests/fuzz/replay.c under make check).
 *
 * Any text is either refused with a message that names the scene, or
 * loaded with the stages of the full build and run for a few steps. It
 * aborts when
 *   - a refusal says nothing, or does not start with the scene's name;
 *   - a loaded scene holds, or a step that reported no failure leaves, a
 *     point whose state is not finite, or a loaded scene's energies or
 *     momentum are not ("accepted with nonsense");
 * and the sanitizers stop it on any memory or undefined-behaviour error.
 * A scene is loaded under FUZZ_MEMORY_LIMIT (Sim::memory_limit), so a large
 * grid is refused from its estimate instead of allocated. Texts with
 * "@include" are skipped: they would read files of the machine.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_load.h"
#include "stages.h"

/** The fuzzer's entry point: one input, 0 when it was handled. */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/** Bytes a fuzzed scene may need (its estimate, footprint.h). */
#define FUZZ_MEMORY_LIMIT (64u << 20)
/** Steps taken at most of a loaded scene. */
#define FUZZ_STEPS 5
/** Points plus nodes times steps at most, to keep one input fast. */
#define FUZZ_WORK 50000.0

/** Name the scene is loaded under. */
#define FUZZ_NAME "fuzz.cfg"

/** Stop with what was wrong, for the fuzzer to keep the input. */
static void nonsense(const Sim *sim, const char *what, int p, double value)
{
    if (p >= 0)
        fprintf(stderr, "fuzz_scene: accepted with nonsense: %s of point %d is "
                "%g after %ld steps\n", what, p, value, sim->step);
    else
        fprintf(stderr, "fuzz_scene: accepted with nonsense: %s is %g after %ld "
                "steps\n", what, value, sim->step);
    abort();
}

/** Abort unless every point's state is finite and its mass and volume
 *  positive. */
static void check_points(const Sim *sim)
{
    const Particles *P = &sim->pts;
    for (int p = 0; p < P->n; p++) {
        const double v[] = {P->x[p], P->y[p], P->vx[p], P->vy[p], P->sxx[p],
                            P->syy[p], P->sxy[p], P->exx[p], P->eyy[p], P->exy[p]};
        static const char *const name[] = {"x", "y", "vx", "vy", "sxx", "syy",
                                           "sxy", "exx", "eyy", "exy"};
        for (size_t k = 0; k < sizeof v / sizeof v[0]; k++)
            if (!isfinite(v[k]))
                nonsense(sim, name[k], p, v[k]);
        if (!(P->m[p] > 0 && isfinite(P->m[p])))
            nonsense(sim, "mass", p, P->m[p]);
        if (!(P->vol[p] > 0 && isfinite(P->vol[p])))
            nonsense(sim, "volume", p, P->vol[p]);
    }
}

/** Abort unless the sums history.csv writes first are finite (a run may
 *  still grow them past the largest double: steps police points only). */
static void check_totals(const Sim *sim)
{
    Totals t = sim_totals(sim);
    const double v[] = {t.kinetic, t.strain, t.px, t.py};
    static const char *const name[] = {"kinetic energy", "strain energy",
                                       "momentum x", "momentum y"};
    for (size_t k = 0; k < sizeof v / sizeof v[0]; k++)
        if (!isfinite(v[k]))
            nonsense(sim, name[k], -1, v[k]);
}

/** LeakSanitizer's hook, for the fuzzer and the replay alike: libconfig
 *  1.5's scanner leaks the string it was reading when the text ends or
 *  breaks inside it; those leaks are not the reader's. */
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void)
{
    return "leak:strbuf_append\nleak:libconfig_yylex\n";
}

/** LeakSanitizer's options: no table of the suppressions used. */
const char *__lsan_default_options(void);
const char *__lsan_default_options(void)
{
    return "print_suppressions=0";
}

/** Load @p text; if it loads, check it and run a few steps. */
static void try_scene(const char *text)
{
    Sim *sim = malloc(sizeof *sim);
    if (!sim)
        return;
    sim_init(sim);
    sim->memory_limit = FUZZ_MEMORY_LIMIT;
    mpm_install_stages(&sim->hooks);
    char err[1024] = "";
    if (sim_load_string(sim, text, FUZZ_NAME, err, sizeof err)) {
        if (strncmp(err, FUZZ_NAME, strlen(FUZZ_NAME)) != 0) {
            fprintf(stderr, "fuzz_scene: refused without naming the scene: \"%s\"\n", err);
            abort();
        }
    } else {
        if (!(isfinite(sim->dt) && sim->dt > 0))
            nonsense(sim, "time step", -1, sim->dt);
        check_points(sim);
        check_totals(sim);
        long steps = sim->nsteps < FUZZ_STEPS ? sim->nsteps : FUZZ_STEPS;
        if ((sim->pts.n + (double)sim->grid.nnodes) * (double)steps > FUZZ_WORK)
            steps = 0;
        for (long k = 0; k < steps && sim_advance(sim) == 0; k++)
            check_points(sim);
    }
    sim_free(sim);
    free(sim);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    if (!strstr(text, "@include"))
        try_scene(text);
    free(text);
    return 0;
}
