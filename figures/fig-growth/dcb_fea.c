/**
 * @file dcb_fea.c
 * @brief make fig-growth: the opening at which a static Q4 analysis of the
 *        growing DCB puts G(a) = G_c, for a range of crack lengths.
 *
 * Usage: dcb_fea E NU G_C XL A0 A1 [H]
 *
 * The beam of tests/7-fracture/scenes/dcb_growth.cfg: 100 mm long (x from
 * 0), two arms 18 mm deep, thickness 1, plane stress, opened at its end.
 * The end is where the run imposes the opening: x = XL (the grid's node
 * column x = 0 for CRAMP, the first column of points, half a spacing in,
 * for XEFG), so the model is the beam from XL to 100, its crack from XL to
 * a.  The upper arm and the ligament's symmetry (held in y from the tip
 * on) under a uniform shear on its end's nodes above the crack face,
 * the model of tests/7-fracture/scene_growth_dcb.c's compliance (written
 * again here for the end at XL): C(a) = 2 delta / P, delta the force-weighted mean of the end's
 * y displacement.  Elements H (default 0.5 mm) across the arm and H/2
 * along the beam, so that every whole-mm crack length has a node for any
 * XL that is a multiple of H/2.  With the opening Delta imposed,
 * G = Delta^2 C' / (2 B C^2), so G = G_c at Delta = C sqrt(2 B G_c / C');
 * C' by the central difference over a -/+ 1 mm.
 *
 * Prints, for a = A0, A0 + 1, ..., A1 (mm): "a C dC/da Delta".
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "q4.h"

#define LENGTH 100.0   /* beam length, mm */
#define ARM 18.0       /* arm depth, mm */

/** Opening compliance for crack length @p a (from x = 0), the end at @p xl.
 *  Mesh x = beam y (across the arm), mesh y = beam x - xl, so that the
 *  band is narrow. */
static double compliance(double a, double xl, double h, double E, double nu)
{
    Q4Model q;
    double hb = 0.5 * h;                              /* along the beam */
    int nx = (int)lround(ARM / h), ny = (int)lround((LENGTH - xl) / hb);
    if (q4_init(&q, nx, ny, 0.0, 0.0, h, hb, 1.0, E, nu)) {
        fprintf(stderr, "dcb_fea: out of memory\n");
        exit(1);
    }
    for (int j = 0; j <= ny; j++)
        if (xl + j * hb >= a - 1e-9)                  /* ligament: symmetry */
            q.fix[2 * q4_node(&q, 0, j)] = 1;
    q.fix[2 * q4_node(&q, 0, ny) + 1] = 1;            /* no rigid beam-x motion */
    /* the end's nodes above the crack face (the run holds none on it):
     * P / nx each, half at the top, the face node's half on the next */
    double P = 1.0, f = P / nx;
    for (int i = 1; i <= nx; i++)
        q.f[2 * q4_node(&q, i, 0)] += i == nx ? 0.5 * f : f;
    q.f[2 * q4_node(&q, 1, 0)] += 0.5 * f;
    if (q4_solve(&q)) {
        fprintf(stderr, "dcb_fea: the Q4 solve failed at a = %g\n", a);
        exit(1);
    }
    double work = 0.0;
    for (int i = 0; i <= nx; i++)
        work += q.f[2 * q4_node(&q, i, 0)] * q.u[2 * q4_node(&q, i, 0)];
    q4_free(&q);
    return 2.0 * work / (P * P);
}

int main(int argc, char **argv)
{
    if (argc != 7 && argc != 8) {
        fprintf(stderr, "usage: dcb_fea E NU G_C XL A0 A1 [H]\n");
        return 2;
    }
    double E = atof(argv[1]), nu = atof(argv[2]), Gc = atof(argv[3]);
    double xl = atof(argv[4]), a0 = atof(argv[5]), a1 = atof(argv[6]);
    double h = argc == 8 ? atof(argv[7]) : 0.5;
    int na = (int)lround(a1 - a0) + 3;                /* a0 - 1 .. a1 + 1 */
    double *C = malloc(sizeof *C * (size_t)na);
    if (!C)
        return 1;
    for (int k = 0; k < na; k++)
        C[k] = compliance(a0 - 1.0 + k, xl, h, E, nu);
    for (int k = 1; k < na - 1; k++) {
        double dC = 0.5 * (C[k + 1] - C[k - 1]);
        printf("%.1f %.10e %.10e %.10e\n", a0 - 1.0 + k, C[k], dC,
               C[k] * sqrt(2.0 * Gc / dC));
    }
    free(C);
    return 0;
}
