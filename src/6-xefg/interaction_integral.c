/**
 * @file interaction_integral.c
 * @brief K_I and K_II by the domain interaction integral (Yau, Chen and
 *        Shih 1980; Moran and Shih 1987; Moes, Dolbow and Belytschko 1999)
 *        over the Gauss points of the XEFG discretisation, with the
 *        Williams near-tip fields (Anderson, Fracture Mechanics, chapter 2)
 *        as auxiliary states.
 */
#include "interaction_integral.h"

#include <math.h>

#include "xefg.h"

/** pi (M_PI is not C11). */
#define PI 3.14159265358979323846

/// [williams_field]
void williams_field(int mode, double mu, double kappa, double r, double theta,
                    double s[3], double u[2], double du[4])
{
    double sh = sin(0.5 * theta), ch = cos(0.5 * theta);
    double s3 = sin(1.5 * theta), c3 = cos(1.5 * theta);
    double st = sin(theta), ct = cos(theta);
    double p = 1.0 / sqrt(2.0 * PI * r);        /* K / sqrt(2 pi r) */
    /* u_i = C sqrt(r) f_i(theta), C = 1 / (2 mu sqrt(2 pi)); f' = df/dtheta */
    double f[2], g[2];
    if (mode == 1) {
        if (s) {
            s[0] = p * ch * (1.0 - sh * s3);
            s[1] = p * ch * (1.0 + sh * s3);
            s[2] = p * sh * ch * c3;
        }
        f[0] = ch * (kappa - 1.0 + 2.0 * sh * sh);
        f[1] = sh * (kappa + 1.0 - 2.0 * ch * ch);
        g[0] = -0.5 * sh * (kappa - 1.0 + 2.0 * sh * sh) + ch * st;
        g[1] = 0.5 * ch * (kappa + 1.0 - 2.0 * ch * ch) + sh * st;
    } else {
        if (s) {
            s[0] = -p * sh * (2.0 + ch * c3);
            s[1] = p * sh * ch * c3;
            s[2] = p * ch * (1.0 - sh * s3);
        }
        f[0] = sh * (kappa + 1.0 + 2.0 * ch * ch);
        f[1] = -ch * (kappa - 1.0 - 2.0 * sh * sh);
        g[0] = 0.5 * ch * (kappa + 1.0 + 2.0 * ch * ch) - sh * st;
        g[1] = 0.5 * sh * (kappa - 1.0 - 2.0 * sh * sh) + ch * st;
    }
    double C = 1.0 / (2.0 * mu * sqrt(2.0 * PI)), sr = sqrt(r);
    for (int i = 0; i < 2; i++) {
        if (u)
            u[i] = C * sr * f[i];
        /* d/dx1 = cos d/dr - sin / r d/dtheta, d/dx2 = sin d/dr + cos / r
         * d/dtheta, with d/dr (sqrt r f) = f / (2 sqrt r) */
        if (du) {
            du[2 * i] = C / sr * (0.5 * ct * f[i] - st * g[i]);
            du[2 * i + 1] = C / sr * (0.5 * st * f[i] + ct * g[i]);
        }
    }
}
/// [williams_field]

/**
 * The slope dq/dr of the weight q at distance r of the tip: q = 1 within
 * rd, 0 beyond 2 rd, and between them the smooth step q = 1 - 3 t^2 + 2 t^3,
 * t = r / rd - 1, whose slope is continuous. A linear ramp has kinks at rd
 * and 2 rd that cut through the background cells, which their Gauss rule
 * does not integrate: on the edge crack it cost 1 to 1.5 % of K_I at every
 * spacing (scene_edge_crack.c).
 */
static double weight_slope(double r, double rd)
{
    if (r <= rd || r >= 2.0 * rd)
        return 0.0;
    double t = r / rd - 1.0;
    return 6.0 * t * (t - 1.0) / rd;
}

/** The weight q itself (for the inertia term, which q multiplies). */
static double weight(double r, double rd)
{
    if (r <= rd)
        return 1.0;
    if (r >= 2.0 * rd)
        return 0.0;
    double t = r / rd - 1.0;
    return 1.0 - 3.0 * t * t + 2.0 * t * t * t;
}

/// [xefg_stress_intensity]
int xefg_stress_intensity(const Sim *sim, int crack, int end, double radius,
                          double K[2])
{
    const Xefg *x = xefg_of(sim);
    K[0] = K[1] = 0.0;
    if (!x || crack < 0 || crack >= x->ncrack || end < 0 || end > 1 ||
        !x->crack[crack].tip[end] || !(radius > 0.0))
        return -1;
    const CrackLine *c = &x->crack[crack];
    double tip[2], dir[2];
    crack_line_tip(c, end, tip, dir);
    /* the tip's frame: e1 = dir (ahead), e2 = its left normal */
    double e[2][2] = {{dir[0], dir[1]}, {-dir[1], dir[0]}};
    /* crack_line_side() is +1 left of the crack walked from point 0 to
     * n - 1. At end 1, dir runs that way and e2 points to that side; at
     * end 0, dir points back along the crack (crack_line_tip()), so e2 is
     * the walk's right normal and a point's side in the tip's frame is
     * minus crack_line_side(). Williams' theta (Anderson, ch. 2) is
     * measured from e1 towards e2: without the turn the auxiliary fields
     * at end 0 were mirrored, K_I came out near 0 and K_II with the wrong
     * sign (issue 27). */
    int turn = end == 0 ? -1 : 1;
    double damping = sim->scene.run.damping;
    const Particles *P = &sim->pts;
    int mat = -1, used = 0;
    double I[2] = {0.0, 0.0};
    for (int gp = 0; gp < x->ngauss; gp++) {
        double dx = x->gx[gp] - tip[0], dy = x->gy[gp] - tip[1];
        double x1 = e[0][0] * dx + e[0][1] * dy, x2 = e[1][0] * dx + e[1][1] * dy;
        double r = hypot(x1, x2), dq = weight_slope(r, radius);
        double qw = weight(r, radius);
        if (qw == 0.0 || r == 0.0)
            continue;                 /* q = 0 beyond the ring (r = 0: a
                                         point of no area at the tip) */
        int I0 = x->gnode[gp];
        if (mat < 0)
            mat = P->mat[I0];
        else if (P->mat[I0] != mat)
            return -1;
        used++;
        /* theta = +-pi on the faces: the side of the crack decides, as for
         * the branch functions (branch.h), taken in the tip's frame */
        int side = turn * crack_line_side(c, x->gx[gp], x->gy[gp], NULL);
        double theta = (side < 0 ? -1.0 : 1.0) * atan2(fabs(x2), x1);
        double qj[2] = {dq * x1 / r, dq * x2 / r};  /* grad q, tip frame */

        /* sigma and grad u in global axes: u_i,j = sum_q u_qi psi_q,j */
        const double *sg = x->gs + 3 * gp;
        double S[2][2] = {{sg[0], sg[2]}, {sg[2], sg[1]}}, G[2][2] = {{0}};
        double A[2] = {0.0, 0.0};     /* a + kappa v, as eq. of motion has */
        for (int k = x->gauss.start[gp]; k < x->gauss.start[gp + 1]; k++) {
            int q = x->gauss.dof[k];
            for (int i = 0; i < 2; i++) {
                G[i][0] += x->u[2 * q + i] * x->gauss.Nx[k];
                G[i][1] += x->u[2 * q + i] * x->gauss.Ny[k];
                A[i] += (x->a[2 * q + i] + damping * x->v[2 * q + i]) *
                        x->gauss.N[k];
            }
        }
        double At[2] = {e[0][0] * A[0] + e[0][1] * A[1],     /* tip frame */
                        e[1][0] * A[0] + e[1][1] * A[1]};
        /* to the tip's frame: A'_ij = e_i . A . e_j */
        double s[2][2], gu[2][2];
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 2; j++) {
                s[i][j] = gu[i][j] = 0.0;
                for (int a = 0; a < 2; a++)
                    for (int b = 0; b < 2; b++) {
                        s[i][j] += e[i][a] * S[a][b] * e[j][b];
                        gu[i][j] += e[i][a] * G[a][b] * e[j][b];
                    }
            }
        double eps[2][2] = {{gu[0][0], 0.5 * (gu[0][1] + gu[1][0])},
                            {0.5 * (gu[0][1] + gu[1][0]), gu[1][1]}};

        const Material *m = &sim->scene.mat[mat];
        double mu = m->E / (2.0 * (1.0 + m->nu));
        double kappa = sim->scene.run.plane == PLANE_STRAIN
                           ? 3.0 - 4.0 * m->nu
                           : (3.0 - m->nu) / (1.0 + m->nu);
        /* per unit thickness: Gauss weights are area x thickness */
        double w = x->gw[gp] / sim->scene.bodies[P->body[I0]].thickness;
        for (int mode = 1; mode <= 2; mode++) {
            double sa3[3], dua[4];
            williams_field(mode, mu, kappa, r, theta, sa3, NULL, dua);
            double sa[2][2] = {{sa3[0], sa3[2]}, {sa3[2], sa3[1]}};
            double W12 = 0.0;                     /* sigma^aux : eps */
            for (int i = 0; i < 2; i++)
                for (int j = 0; j < 2; j++)
                    W12 += sa[i][j] * eps[i][j];
            /* [sigma_ij u^aux_i,1 + sigma^aux_ij u_i,1 - W^(1,2) delta_1j]
             * q_,j, W^(1,2) = sigma^aux_ij eps_ij */
            double sum = -W12 * qj[0];
            for (int i = 0; i < 2; i++)
                for (int j = 0; j < 2; j++)
                    sum += (s[i][j] * dua[2 * i] + sa[i][j] * gu[i][0]) * qj[j];
            /* inertia: rho (a_i + kappa v_i) u^aux_i,1 q (the auxiliary
             * state is static: no kinetic cross term) */
            sum += m->rho * (At[0] * dua[0] + At[1] * dua[2]) * qw;
            I[mode - 1] += w * sum;
        }
    }
    if (!used)
        return -1;
    const Material *m = &sim->scene.mat[mat];
    double Ep = sim->scene.run.plane == PLANE_STRAIN
                    ? m->E / (1.0 - m->nu * m->nu) : m->E;
    K[0] = 0.5 * Ep * I[0];                        /* I = 2 K / E' */
    K[1] = 0.5 * Ep * I[1];
    return 0;
}
/// [xefg_stress_intensity]
