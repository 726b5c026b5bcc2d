/*
 * Exercise "branch jump" (chapter 6): the branch functions of a crack tip.
 * Copy this file, fill in branch_functions(), and run
 *     make exercise EX=6-xefg/branch-jump SOLUTION=your_copy.c
 * The contract is in src/6-xefg/branch.h; README.md says what is checked.
 */
#include "branch.h"

int branch_functions(BranchKind kind, double m, const double tip[2],
                     const double dir[2], int side, double x, double y,
                     double *B, double *dBx, double *dBy)
{
    /* TODO: (r, theta) about the tip in its frame (x' along dir, y' to its
     * left), theta = side * acos(x'/r); the values of eq. 5 (BRANCH_LEFM,
     * four functions) or eq. 6 (BRANCH_COHESIVE, r^m sin(theta/2)); their
     * x and y derivatives from dB/dr and dB/dtheta; 0 functions at r = 0.
     * This stub returns functions that are zero everywhere: continuous, so
     * the crack never opens and the tests fail until you write them. */
    (void)m;
    (void)tip;
    (void)dir;
    (void)side;
    (void)x;
    (void)y;
    int nb = kind == BRANCH_LEFM ? 4 : 1;
    for (int k = 0; k < nb; k++) {
        B[k] = 0.0;
        if (dBx) {
            dBx[k] = 0.0;
            dBy[k] = 0.0;
        }
    }
    return nb;
}
