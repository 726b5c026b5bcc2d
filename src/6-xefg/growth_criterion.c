/**
 * @file growth_criterion.c
 * @brief When and where a tip grows (xefg.md 2.4; the paper's criterion
 *        is beyond our transcript, so the details are our choice): the
 *        stress averaged over the Gauss points ahead of the tip; the loss
 *        of stability of the bulk's tangent there (the acoustic tensor of
 *        a Rankine softening law), which comes when the maximum principal
 *        stress reaches f_t; the crack growing normal to sigma_1, the
 *        acoustic tensor's critical normal.
 */
#include <math.h>

#include "growth.h"

/** pi (M_PI is not C11). */
#define PI 3.14159265358979323846

/// [growth_default_radius]
double growth_default_radius(double h, double Ep, const CohesiveLaw *L)
{
    /* L = (K_Ic / f_t)^2 / pi = E' G_f / (pi f_t^2); the point method
     * takes the stress at L / 2 ahead of the tip (our reading: the half
     * disk of that radius) */
    double half_L = Ep * L->G_f / (2.0 * PI * L->f_t * L->f_t);
    return fmin(1.5 * h, fmax(half_L, 0.5 * h));
}
/// [growth_default_radius]

/// [growth_stability_lost]
int growth_stability_lost(const double s[3], double f_t, const double C[3][3],
                          double H, AcousticCritical *a)
{
    double sigma1 = 0.5 * (s[0] + s[1]) + hypot(0.5 * (s[0] - s[1]), s[2]);
    double Ct[3][3];
    if (sigma1 >= f_t)              /* on the Rankine surface: softening */
        acoustic_rankine_tangent(C, s, H, Ct);
    else                            /* inside it: elastic */
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                Ct[i][j] = C[i][j];
    *a = acoustic_critical(Ct, ACOUSTIC_SAMPLES);
    return a->unstable;
}
/// [growth_stability_lost]

/// [growth_tip_stress]
int growth_tip_stress(const Xefg *x, int c, int end, double radius,
                      double s[3])
{
    double tip[2], dir[2], w = 0.0, r2 = radius * radius;
    crack_line_tip(&x->crack[c], end, tip, dir);
    s[0] = s[1] = s[2] = 0.0;
    int n = 0;
    for (int p = 0; p < x->ngauss; p++) {
        double dx = x->gx[p] - tip[0], dy = x->gy[p] - tip[1];
        if (dx * dx + dy * dy > r2 || dx * dir[0] + dy * dir[1] < 0.0)
            continue;                      /* not in the half disk ahead */
        for (int k = 0; k < 3; k++)
            s[k] += x->gw[p] * x->gs[3 * p + k];
        w += x->gw[p];
        n++;
    }
    for (int k = 0; k < 3 && w > 0.0; k++)
        s[k] /= w;
    return n;
}
/// [growth_tip_stress]

/// [growth_criterion]
double growth_criterion(const double s[3], const double ahead[2],
                        double dir[2])
{
    double mean = 0.5 * (s[0] + s[1]), half = 0.5 * (s[0] - s[1]);
    double radius = hypot(half, s[2]);
    double sigma1 = mean + radius;             /* Mohr's circle */
    dir[0] = ahead[0];
    dir[1] = ahead[1];
    if (!(radius > 1e-9 * fabs(mean)))
        return sigma1;               /* no principal direction: straight on */
    /* sigma_1 along (cos a, sin a), a = atan2(2 s_xy, s_xx - s_yy) / 2; the
     * crack's normal is that direction, so it grows along (-sin a, cos a),
     * the sigma_2 direction, the way that points ahead */
    double a = 0.5 * atan2(s[2], half);
    double tx = -sin(a), ty = cos(a);
    if (tx * ahead[0] + ty * ahead[1] < 0.0)
        tx = -tx, ty = -ty;
    dir[0] = tx;
    dir[1] = ty;
    return sigma1;
}
/// [growth_criterion]
