/**
 * @file apic_setup.c
 * @brief run.transfer = "flip" | "apic": the key, and the set-up of APIC
 *        (each point's B_p from its body's initial velocity gradient, the
 *        checkpoint of B_p).
 */
#include <stdio.h>
#include <stdlib.h>

#include "apic.h"
#include "checkpoint.h"
#include "scene_read.h"
#include "step.h"

const Transfer transfer_apic = {"apic", apic_scatter, apic_gather};
const Transfer transfer_flip = {"flip", NULL, NULL};

/** The paper's bilinear stencil as a stencil function, so that APIC with
 *  run.shape = "linear" runs through the loops of the other rows. */
static void linear_stencil(const Sim *sim, int p, Stencil *st)
{
    stencil_linear(sim, p, st);
    st->n = STENCIL_NODES;
}

/** Save or restore B_p. */
static int apic_checkpoint(Sim *sim, void *state, FILE *f, int save)
{
    Apic *A = state;
    (void)sim;
    return checkpoint_io(f, A->B, sizeof(double) * 4 * (size_t)A->n, save);
}

static void apic_release(void *state)
{
    Apic *A = state;
    free(A->B);
    free(A);
}

/// [apic_prepare]
int apic_prepare(Sim *sim, void *state, char *err, size_t errlen)
{
    RunSettings *run = &sim->scene.run;
    const char *file = sim->scene.file;
    int n = sim->pts.n;
    (void)state;
    if (run->method->step != sim_step) {
        snprintf(err, errlen, "%s: run.transfer = \"apic\" needs run.method = "
                 "\"mpm\" (the method \"%s\" has no grid transfer)", file,
                 run->method->name);
        return -1;
    }
    if (sim->hooks.seam[SEAM_TASK1_FIELDS].n) {
        snprintf(err, errlen, "%s: run.transfer = \"apic\" with cracks or contact "
                 "between bodies (several velocity fields at a node) is not done "
                 "yet (chapter 8): use run.transfer = \"flip\"", file);
        return -1;
    }
    Apic *A = calloc(1, sizeof *A);
    if (A)
        A->B = calloc(4 * (size_t)(n > 0 ? n : 1), sizeof(double));
    if (!A || !A->B || sim_attach(sim, APIC_STATE, A, apic_release)) {
        if (A)
            free(A->B);
        free(A);
        snprintf(err, errlen, "%s: out of memory (APIC)", file);
        return -1;
    }
    A->row = transfer_apic;
    A->n = n;
    run->transfer = &A->row;
    if (!run->stencil)                 /* linear, through the loops of rows */
        run->stencil = linear_stencil;
    locate_points(sim);                /* Task 0 of the first step, early */
    for (int p = 0; p < n; p++)        /* v = v_0 + L (x - c): C_p = L */
        apic_set_gradient(sim, p, sim->scene.bodies[sim->pts.body[p]].L);
    if (hooks_on_checkpoint(&sim->hooks, apic_checkpoint, A)) {
        snprintf(err, errlen, "%s: too many checkpoint hooks", file);
        return -1;
    }
    return 0;
}
/// [apic_prepare]

/** Read run.transfer; "apic" subscribes its set-up, which sets
 *  RunSettings::transfer to the run's own row. */
static int transfer_read(Sim *sim, const config_setting_t *s, int index,
                         SceneReader *r)
{
    const char *name = config_setting_get_string(s);
    const void *row;
    (void)index;
    if (!name)
        return scene_error(r, s, "transfer", "expected a string in quotes");
    if (scene_choice(r, &sim->hooks, config_setting_parent(s), "run",
                     "transfer", name, &row))
        return -1;
    if (row != &transfer_apic)
        return 0;                       /* "flip": the paper's, nothing */
    if (hooks_on_prepare(&sim->hooks, apic_prepare, NULL))
        return scene_error(r, s, "transfer", "too many set-up hooks");
    return 0;
}

void apic_install(Hooks *h)
{
    hooks_add_key(h, "run", "transfer", transfer_read, NULL);
    hooks_add_choice(h, "run.transfer", "flip", &transfer_flip);
    hooks_add_choice(h, "run.transfer", "apic", &transfer_apic); /* Jiang 2015 */
}
