/*
 * Exercise "acoustic tensor" (chapter 6): the acoustic tensor of a 2D
 * tangent and its determinant, the core of the crack-growth criterion.
 * Copy this file, fill in acoustic_tensor() and acoustic_det(), and run
 *     make exercise EX=6-xefg/acoustic-tensor SOLUTION=your_copy.c
 * The contract is in src/6-xefg/acoustic_tensor.h; README.md says what is
 * checked.
 */
#include <math.h>

#include "acoustic_tensor.h"

void acoustic_tensor(const double C[3][3], double phi, double Q[2][2])
{
    /* TODO: n = (cos phi, sin phi); Q_jk = n_i C_ijkl n_l, with the
     * tensor components C_ijkl read from the Voigt matrix C (order xx, yy,
     * xy, engineering shear): which entry is C_1212? C_1112? C_1211?
     * This stub returns Q = 0: no wave propagates in any direction, so
     * every test of a tangent fails until you write it. */
    (void)C;
    (void)phi;
    Q[0][0] = Q[0][1] = Q[1][0] = Q[1][1] = 0.0;
}

double acoustic_det(const double C[3][3], double phi)
{
    /* TODO: the determinant of acoustic_tensor(C, phi). Q need not be
     * symmetric (C need not be). */
    double Q[2][2];
    acoustic_tensor(C, phi, Q);
    return 0.0;
}
