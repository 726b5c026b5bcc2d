/**
 * @file dcb_opening.c
 * @brief make fig-tradeoff and make fig-xefg-dcb: the DCB's crack opening at
 *        the load from a run (CRAMP/MPM or XEFG) against a converged static
 *        Q4 analysis of the same loads.
 *
 * Usage: dcb_opening [-g] SCENE RUNDIR H [key=value ...]
 *
 * The opening is measured as tests/2-fields/scene_fig2.c measures it: twice
 * the y displacement of the upper arm's point nearest the loaded end of the
 * crack face (y > 0, least x, then least y), read from RUNDIR's
 * particles_final.csv (points in order).  The reference is the upper half
 * by tests/support/q4.c (linked, not copied) as tests/3-crossing/
 * scene_tip_on_node.c sets it up (transposed mesh of squares, ligament held
 * in y from the tip on), loaded with exactly the run's point loads of this
 * setting, its displacement read at that point's initial position; meshes
 * H, H/2 and H/4, extrapolated to zero from the last two with the order the
 * three show.  The crack tip is the right end of the scene's first crack
 * (50 mm in figures/fig1/dcb_full.cfg); the FEA's columns are as near H as
 * puts a node on it (exactly H, H/2, H/4 for a tip at 50 and H = 1).
 * Prints one line:
 *   points x0 y0 opening_mpm fea_H fea_H/2 fea_H/4 order fea_0 error
 * With -g (make fig-xefg-dcb: the energy release rate from the compliance)
 * nine more columns follow:
 *   tip P B load_mpm load_H load_H/2 load_H/4 load_order load_0
 * tip: the crack tip x (mm); P: the upper arm's load (N); B: the body's
 * thickness (mm); load_*: the opening at the load line, the one whose
 * product with P is twice the loads' work (sum over the loaded points of
 * f . u, both arms, over P; the FEA's: twice its upper arm's), of the run,
 * the three meshes, the order and the extrapolated value.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cracks.h"
#include "q4.h"
#include "scene_load.h"
#include "stages.h"

#define LENGTH 100.0             /* beam length (mm), from x = 0 */
#define ARM 18.0                 /* arm height (mm), above y = 0 */

/** Elements along the beam (x) for a mesh of about h with a node on the
 *  tip: the least n >= 100 / h with n tip / 100 a whole number. */
static int fea_columns(double h, double tip)
{
    int n0 = (int)lround(LENGTH / h);
    for (int n = n0; n <= 8 * n0; n++) {
        double k = n * tip / LENGTH;
        if (fabs(k - round(k)) < 1e-6)
            return n;
    }
    fprintf(stderr, "dcb_opening: no mesh near h = %g has a node on the tip "
            "x = %g; the tip goes to the next node\n", h, tip);
    return n0;
}

/** Opening 2 u_y at beam point (x, y) from the upper half meshed with about
 *  h (nX columns along x, squares of h across), and the load-line opening
 *  (twice sum f . u / P over the upper arm's loads, P their sum of fy). */
static int fea_opening(const Sim *sim, double h, int nX, double tip, double x,
                       double y, double *open, double *load_open)
{
    Q4Model q;
    double hx = LENGTH / nX;
    int nY = (int)lround(ARM / h);
    const Material *mat = &sim->scene.mat[0];
    if (q4_init(&q, nY, nX, 0.0, 0.0, h, hx, sim->scene.bodies[0].thickness,
                mat->E, mat->nu))
        return -1;
    for (int j = 0; j <= nX; j++)                /* ligament, tip node too */
        if (j * hx >= tip - 1e-9)
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
    double u[2], work = 0, P = 0;
    q4_displacement(&q, y, x, u);
    *open = 2 * u[0];
    for (int l = 0; l < sim->scene.nloads; l++) {
        const Load *L = &sim->scene.loads[l];
        for (int k = 0; k < L->count; k++) {
            int p = L->points[k];
            if (sim->pts.y[p] > 0) {
                q4_displacement(&q, sim->pts.y[p], sim->pts.x[p], u);
                work += (L->fy * u[0] + L->fx * u[1]) / L->count;
                P += L->fy / L->count;
            }
        }
    }
    *load_open = 2 * work / P;
    q4_free(&q);
    return rc;
}

/** x and y of the n points in RUNDIR/particles_final.csv (columns found by
 *  name, points in order). */
static int final_xy(const char *dir, int n, double *x, double *y)
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
    int cx = -1, cy = -1, k = 0, r = 0;
    for (char *tok = strtok(line, ",\r\n"); tok; tok = strtok(NULL, ",\r\n"), k++) {
        if (strcmp(tok, "x") == 0)
            cx = k;
        if (strcmp(tok, "y") == 0)
            cy = k;
    }
    for (; cx >= 0 && cy >= 0 && r < n && fgets(line, sizeof line, f); r++) {
        char *s = line;
        int got = 0;
        for (k = 0; s && got < 2; k++) {
            if (k == cx)
                got += sscanf(s, "%lf", &x[r]) == 1;
            if (k == cy)
                got += sscanf(s, "%lf", &y[r]) == 1;
            s = strchr(s, ',') ? strchr(s, ',') + 1 : NULL;
        }
        if (got < 2)
            break;
    }
    fclose(f);
    if (r < n) {
        fprintf(stderr, "dcb_opening: %d of %d points (or no x, y columns) in %s\n",
                r, n, path);
        return -1;
    }
    return 0;
}

/** Richardson: error ~ h^r, r from the three meshes, then the last two
 *  extrapolated to h = 0. */
static double extrapolate(const double f[3], double *r)
{
    *r = log2((f[1] - f[0]) / (f[2] - f[1]));
    if (!(*r > 0.5 && *r < 4))
        *r = 1;                                 /* fig-tip's assumption */
    return f[2] + (f[2] - f[1]) / (pow(2, *r) - 1);
}

int main(int argc, char **argv)
{
    int g = argc > 1 && strcmp(argv[1], "-g") == 0;
    argc -= g;
    argv += g;
    if (argc < 4) {
        fprintf(stderr, "usage: dcb_opening [-g] SCENE RUNDIR H [key=value ...]\n");
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
    const Cracks *C = cracks_of(&sim);
    if (!C || C->ncracks < 1) {
        fprintf(stderr, "dcb_opening: %s has no crack\n", argv[1]);
        return 1;
    }
    const Crack *ck = &C->crack[0];                /* its right end */
    double tip = ck->x[ck->x[0] > ck->x[ck->n - 1] ? 0 : ck->n - 1];
    const Particles *P = &sim.pts;
    int at = -1;
    for (int p = 0; p < P->n; p++)              /* as scene_fig2.c */
        if (P->y[p] > 0 && (at < 0 || P->x[p] < P->x[at] ||
            (P->x[p] == P->x[at] && P->y[p] < P->y[at])))
            at = p;
    double *X = malloc(2 * (size_t)P->n * sizeof *X), *Y = X + P->n;
    if (!X || final_xy(argv[2], P->n, X, Y))
        return 1;
    double x0 = P->x[at], y0 = P->y[at], f[3], lf[3];
    int nX = fea_columns(h, tip);
    for (int k = 0; k < 3; k++)
        if (fea_opening(&sim, h / (1 << k), nX << k, tip, x0, y0, &f[k], &lf[k])) {
            fprintf(stderr, "dcb_opening: FEA failed (h = %g)\n", h / (1 << k));
            return 1;
        }
    double r, ref = extrapolate(f, &r), mpm = 2 * (Y[at] - y0);
    printf("%d %.6f %.6f %.8g %.8g %.8g %.8g %.3f %.8g %.6e", P->n, x0, y0, mpm,
           f[0], f[1], f[2], r, ref, mpm / ref - 1);
    if (g) {
        /* the run's load-line opening: the loads' work f . u over P, both
           arms (the upper arm's load P = the sum of its fy) */
        double work = 0, Pu = 0, lr, lref = extrapolate(lf, &lr);
        for (int l = 0; l < sim.scene.nloads; l++) {
            const Load *L = &sim.scene.loads[l];
            for (int k = 0; k < L->count; k++) {
                int p = L->points[k];
                work += (L->fx * (X[p] - P->x[p]) + L->fy * (Y[p] - P->y[p])) / L->count;
                if (P->y[p] > 0)
                    Pu += L->fy / L->count;
            }
        }
        printf(" %.8g %.8g %.8g %.8g %.8g %.8g %.8g %.3f %.8g", tip, Pu,
               sim.scene.bodies[0].thickness, work / Pu, lf[0], lf[1], lf[2], lr, lref);
    }
    printf("\n");
    free(X);
    sim_free(&sim);
    return 0;
}
