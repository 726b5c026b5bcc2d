/**
 * @file k_auxiliary.c
 * @brief The auxiliary states of the interaction integral at a CRAMP tip
 *        (chapter 7, "From J to K"): Williams' mode-I and mode-II fields
 *        of unit K (stage 6's williams_field()) in the tip's frame, turned
 *        to global axes so that the integrand's contractions can be taken
 *        there, as J's are.
 */
#include <math.h>

#include "interaction_integral.h"
#include "j_integral.h"

/// [k_auxiliary]
void k_auxiliary(const JTip *T, const Crack *c, const Material *m,
                 int plane_strain, double x, double y, double s[2][2][2],
                 double du[2][2][2])
{
    double e1[2] = {T->ex, T->ey}, e2[2] = {-T->ey, T->ex};  /* x2: left */
    double dx = x - T->x, dy = y - T->y;
    double x1 = e1[0] * dx + e1[1] * dy, x2 = e2[0] * dx + e2[1] * dy;
    /* theta from x1 towards x2, +-pi on the faces: e1, e2 are a
     * right-handed frame at either end of the crack (e1 ahead of the tip,
     * j_integral_tips()), so atan2 needs no turn at a crack's first point;
     * behind a kink the cut follows the crack (j_tip_angle()) */
    double r = hypot(x1, x2), theta = j_tip_angle(c, T, x1, x2);
    double mu = m->E / (2.0 * (1.0 + m->nu));
    double kappa = plane_strain ? 3.0 - 4.0 * m->nu
                                : (3.0 - m->nu) / (1.0 + m->nu);
    /* Q = [e1 e2]: A_global = Q A' Q^T */
    double Q[2][2] = {{e1[0], e2[0]}, {e1[1], e2[1]}};
    for (int mode = 0; mode < 2; mode++) {
        double s3[3], g4[4];
        williams_field(mode + 1, mu, kappa, r > 0.0 ? r : 1e-300, theta, s3,
                       NULL, g4);
        double sl[2][2] = {{s3[0], s3[2]}, {s3[2], s3[1]}};
        double gl[2][2] = {{g4[0], g4[1]}, {g4[2], g4[3]}};
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++) {
                s[mode][i][j] = du[mode][i][j] = 0.0;
                for (int a = 0; a < 2; a++)
                    for (int b = 0; b < 2; b++) {
                        s[mode][i][j] += Q[i][a] * sl[a][b] * Q[j][b];
                        du[mode][i][j] += Q[i][a] * gl[a][b] * Q[j][b];
                    }
            }
    }
}
/// [k_auxiliary]
