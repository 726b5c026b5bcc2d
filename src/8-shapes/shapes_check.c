/**
 * @file shapes_check.c
 * @brief The limits of uGIMP and CPDI in this stage: the MPM step and
 *        every domain inside the grid (a node off the grid would take a
 *        share of the point's mass). Cracks, crack contact and contact
 *        between bodies read the point's own stencil (contact_stencil.h).
 */
#include "shapes_check.h"

#include <stdio.h>

#include "cpdi.h"
#include "gimp.h"
#include "j_integral.h"
#include "material_contact.h"
#include "step.h"

/** The first point whose domain is not inside the grid, or -1; its
 *  coordinate along the side it crosses in *@p at. */
static int domain_outside(const Sim *sim, double *at)
{
    const Particles *P = &sim->pts;
    const Grid *g = &sim->grid;
    double xmax = g->ox + g->ncx * g->dx, ymax = g->oy + g->ncy * g->dy;
    int n = P->n, first = n;
    /* the lowest index, whatever the number of threads */
#pragma omp parallel for num_threads(sim->threads) reduction(min : first)
    for (int p = 0; p < n; p++) {
        double l = gimp_half(sim, p), hx = l * g->dx, hy = l * g->dy;
        if (!(P->x[p] - hx >= g->ox && P->x[p] + hx <= xmax &&
              P->y[p] - hy >= g->oy && P->y[p] + hy <= ymax) && p < first)
            first = p;
    }
    if (first == n)
        return -1;
    double hx = gimp_half(sim, first) * g->dx;
    *at = P->x[first] - hx >= g->ox && P->x[first] + hx <= xmax ? P->y[first]
                                                                : P->x[first];
    return first;
}

int gimp_domains_inside(Sim *sim, void *state, Seam seam)
{
    double at;
    (void)state;
    (void)seam;
    int p = domain_outside(sim, &at);
    return p < 0 ? 0 : step_fail(sim, p, "GIMP domain (left the grid)", at);
}

/// [shapes_prepare]
int shapes_prepare(Sim *sim, void *state, char *err, size_t errlen)
{
    const Scene *sc = &sim->scene;
    const char *name = sc->run.shape ? sc->run.shape->name : "linear";
    double at;
    (void)state;
    if (sc->run.shape != &shape_gimp && sc->run.shape != &shape_cpdi)
        return 0;
    if (sc->run.method->step != sim_step) {
        snprintf(err, errlen, "%s: run.shape = \"%s\" needs run.method = "
                 "\"mpm\" (the method \"%s\" has its own shape functions)",
                 sc->file, name, sc->run.method->name);
        return -1;
    }
    const JState *J = sim_state(sim, "j-integral");
    for (int k = 0; J && k < J->ncracks; k++)
        if (J->set[k].on) {             /* stage 7 reads a linear stencil */
            char where[SCENE_AT_LEN];
            snprintf(err, errlen, "%s: cracks.[%d].j_integral with run.shape "
                     "= \"%s\": the J-integral and K (stage 7) read the four "
                     "nodes of a linear stencil: use run.shape = \"linear\"",
                     scene_lines_at(sc->lines, sc->file, J->set[k].line, where,
                                    SCENE_AT_LEN), k, name);
            return -1;
        }
    const MaterialContact *M = sim_state(sim, "material contact");
    if (M && M->normal == NORMAL_REGRESSION) {  /* its fit: a linear stencil */
        char where[SCENE_AT_LEN];
        snprintf(err, errlen, "%s: contact normal = \"regression\" with "
                 "run.shape = \"%s\": the fit reads the four nodes of a "
                 "linear stencil: use normal = \"gradients\" (the default)",
                 scene_lines_at(sc->lines, sc->file, M->normal_line, where,
                                SCENE_AT_LEN), name);
        return -1;
    }
    if (sc->run.shape == &shape_cpdi)
        return cpdi_prepare(sim, err, errlen);
    int p = domain_outside(sim, &at);
    if (p >= 0) {
        snprintf(err, errlen, "%s: run.shape = \"gimp\": point %d (at %g) has "
                 "its domain outside the grid; add a cell of margin", sc->file,
                 p, at);
        return -1;
    }
    if (hooks_on_step(&sim->hooks, SEAM_TASK7, gimp_domains_inside, NULL)) {
        snprintf(err, errlen, "%s: too many step hooks", sc->file);
        return -1;
    }
    return 0;
}
/// [shapes_prepare]
