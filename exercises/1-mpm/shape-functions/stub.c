/*
 * Exercise "shape functions" (chapter 1): your bilinear shape functions.
 * Copy this file, fill in shape_linear(), and run
 *     make exercise EX=1-mpm/shape-functions SOLUTION=your_copy.c
 * The contract is in src/1-mpm/shape.h; README.md says what is checked.
 */
#include "shape.h"

void shape_linear(double xi, double eta, double idx, double idy,
                  double S[4], double Gx[4], double Gy[4])
{
    /* TODO: N_k(xi, eta) for corners 0 (0,0), 1 (1,0), 2 (0,1), 3 (1,1),
     * and their x and y derivatives (mind the chain rule: d/dx = idx d/dxi).
     * This stub returns zeros, so the tests fail until you write them. */
    (void)xi;
    (void)eta;
    (void)idx;
    (void)idy;
    for (int k = 0; k < 4; k++)
        S[k] = Gx[k] = Gy[k] = 0.0;
}
