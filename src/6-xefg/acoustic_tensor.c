/**
 * @file acoustic_tensor.c
 * @brief The acoustic tensor Q_jk = n_i C_ijkl n_l of a 2D Voigt tangent
 *        and its determinant (Rice 1976; xefg.md 2.4). Exercise 6.4.
 */
#include <math.h>

#include "acoustic_tensor.h"

/** Voigt row of the index pair (i, j): xx = 0, yy = 1, xy = yx = 2. */
static const int VOIGT[2][2] = {{0, 2}, {2, 1}};

void acoustic_tensor(const double C[3][3], double phi, double Q[2][2])
{
    double n[2] = {cos(phi), sin(phi)};
    /* C_ijkl = C[v(i,j)][v(k,l)]: with engineering shear the Voigt entries
     * are the tensor's components, the factor 2 of gamma_xy being the two
     * equal terms kl = 12 and kl = 21 of the contraction C_ijkl eps_kl */
    for (int j = 0; j < 2; j++)
        for (int k = 0; k < 2; k++) {
            double q = 0.0;
            for (int i = 0; i < 2; i++)
                for (int l = 0; l < 2; l++)
                    q += n[i] * C[VOIGT[i][j]][VOIGT[k][l]] * n[l];
            Q[j][k] = q;
        }
}

double acoustic_det(const double C[3][3], double phi)
{
    double Q[2][2];
    acoustic_tensor(C, phi, Q);
    return Q[0][0] * Q[1][1] - Q[0][1] * Q[1][0];
}
