/**
 * @file dcb_opening.c
 * @brief make fig-tradeoff: the DCB's crack opening at the load from an MPM
 *        run against a converged static Q4 analysis of the same loads.
 *
 * Usage: dcb_opening SCENE RUNDIR H [key=value ...]
 *
 * The opening is measured as tests/2-fields/scene_fig2.c measures it: twice
 * the y displacement of the upper arm's point nearest the loaded end of the
 * crack face (y > 0, least x, then least y), read from RUNDIR's
 * particles_final.csv (points in order).  The reference is the upper half
 * by tests/support/q4.c (linked, not copied) as tests/3-crossing/
 * scene_tip_on_node.c sets it up (transposed mesh of squares, ligament held
 * in y from the tip on), loaded with exactly the MPM's point loads of this
 * setting, its displacement read at that point's initial position; meshes
 * H, H/2 and H/4, extrapolated to zero from the last two with the order the
 * three show.  Prints one line:
 *   points x0 y0 opening_mpm fea_H fea_H/2 fea_H/4 order fea_0 error
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "q4.h"
#include "sim.h"
#include "stages.h"

#define TIP 50.0                 /* crack tip x (mm) */

/** Opening 2 u_y at beam point (x, y) from the upper half meshed with h. */
static int fea_opening(const Sim *sim, double h, double x, double y, double *open)
{
    Q4Model q;
    int nX = (int)lround(100.0 / h), nY = (int)lround(18.0 / h);
    const Material *mat = &sim->scene.mat[0];
    if (q4_init(&q, nY, nX, 0.0, 0.0, h, h, 1.0, mat->E, mat->nu))
        return -1;
    for (int j = 0; j <= nX; j++)                /* ligament, tip node too */
        if (j * h >= TIP - 1e-9)
            q.fix[2 * q4_node(&q, 0, j)] = 1;
    q.fix[2 * q4_node(&q, 0, nX) + 1] = 1;       /* no rigid x motion */
    for (int l = 0; l < sim->scene.nloads; l++) {
        const Load *L = &sim->scene.loads[l];
        for (int k = 0; k < L->count; k++) {
            int p = L->points[k];
            if (sim->pts.y[p] > 0)               /* the upper arm's loads */
                q4_point_force(&q, sim->pts.y[p], sim->pts.x[p],
                               L->fy / L->count, L->fx / L->count);
        }
    }
    int rc = q4_solve(&q);
    double u[2];
    q4_displacement(&q, y, x, u);
    *open = 2 * u[0];
    q4_free(&q);
    return rc;
}

/** y of point p in RUNDIR/particles_final.csv (column found by name). */
static int final_y(const char *dir, int p, double *y)
{
    char path[1024], line[4096];
    snprintf(path, sizeof path, "%s/particles_final.csv", dir);
    FILE *f = fopen(path, "r");                 /* "# t = ...", then the names */
    if (!f || !fgets(line, sizeof line, f) || !fgets(line, sizeof line, f)) {
        fprintf(stderr, "dcb_opening: cannot read %s\n", path);
        if (f)
            fclose(f);
        return -1;
    }
    int col = -1, k = 0;
    for (char *tok = strtok(line, ",\r\n"); tok; tok = strtok(NULL, ",\r\n"), k++)
        if (strcmp(tok, "y") == 0)
            col = k;
    for (int r = 0; col >= 0 && fgets(line, sizeof line, f); r++) {
        if (r < p)
            continue;
        char *s = line;
        for (k = 0; k < col && s; k++)
            s = strchr(s, ',') ? strchr(s, ',') + 1 : NULL;
        fclose(f);
        return s && sscanf(s, "%lf", y) == 1 ? 0 : -1;
    }
    fclose(f);
    fprintf(stderr, "dcb_opening: no point %d (or no y column) in %s\n", p, path);
    return -1;
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: dcb_opening SCENE RUNDIR H [key=value ...]\n");
        return 1;
    }
    double h = atof(argv[3]);
    Sim sim;
    char err[1024];
    sim_init(&sim);
    mpm_install_stages(&sim.hooks);
    if (sim_load_file(&sim, argv[1], argc - 4, argv + 4, err, sizeof err)) {
        fprintf(stderr, "dcb_opening: %s\n", err);
        return 1;
    }
    const Particles *P = &sim.pts;
    int tip = -1;
    for (int p = 0; p < P->n; p++)              /* as scene_fig2.c */
        if (P->y[p] > 0 && (tip < 0 || P->x[p] < P->x[tip] ||
            (P->x[p] == P->x[tip] && P->y[p] < P->y[tip])))
            tip = p;
    double x0 = P->x[tip], y0 = P->y[tip], y1, f[3];
    if (final_y(argv[2], tip, &y1))
        return 1;
    for (int k = 0; k < 3; k++)
        if (fea_opening(&sim, h / (1 << k), x0, y0, &f[k])) {
            fprintf(stderr, "dcb_opening: FEA failed (h = %g)\n", h / (1 << k));
            return 1;
        }
    /* error ~ h^r: r from the three meshes, then Richardson on the last two */
    double r = log2((f[1] - f[0]) / (f[2] - f[1]));
    if (!(r > 0.5 && r < 4))
        r = 1;                                  /* fig-tip's assumption */
    double ref = f[2] + (f[2] - f[1]) / (pow(2, r) - 1), mpm = 2 * (y1 - y0);
    printf("%d %.6f %.6f %.8g %.8g %.8g %.8g %.3f %.8g %.6e\n", P->n, x0, y0, mpm,
           f[0], f[1], f[2], r, ref, mpm / ref - 1);
    sim_free(&sim);
    return 0;
}
