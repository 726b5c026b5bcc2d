/**
 * @file acoustic_tensor.h
 * @brief Material stability of a 2D tangent: the acoustic tensor Q(n), its
 *        determinant, the direction that minimises it, and a Rankine
 *        softening tangent to try it on (xefg.md 2.4; Rabczuk and Zi,
 *        abstract: "crack propagation is governed by the material
 *        stability condition").
 *
 * **Conventions.** A tangent is a 3x3 Voigt matrix C in the order
 * (xx, yy, xy) with *engineering* shear strain: d sigma = C d eps with
 * eps = (eps_xx, eps_yy, gamma_xy = 2 eps_xy), so the isotropic C[2][2] is
 * the shear modulus mu. C need not be symmetric (a non-associated law's
 * tangent is not). It is the in-plane tangent of either idealisation:
 * plane strain (eps_zz = 0; C is the 3D tangent's in-plane rows) or plane
 * stress (sigma_zz = 0; C is condensed). The functions here do not care
 * which; acoustic_elastic_tangent() builds either.
 *
 * **The acoustic tensor** (Hill 1962; Rice 1976, "The localization of
 * plastic deformation"): a jump in the strain rate across a plane of unit
 * normal n has the form [[d eps]] = sym(g (x) n); equilibrium of the
 * traction rate across the plane, n . [[d sigma]] = 0, asks
 * Q(n) g = 0 with
 *
 *     Q_jk(n) = n_i C_ijkl n_l,     n = (cos phi, sin phi).
 *
 * A non-zero jump g (a band, the onset of a crack) is possible when
 * det Q(n) = 0. In dynamics Q(n)/rho holds the squared speeds of plane
 * waves with normal n; det Q(n) <= 0 is the loss of hyperbolicity, after
 * which the wave equation no longer fixes a solution (Belytschko, Chen, Xu
 * and Zi 2003). A crack is inserted there, with normal n, the minimiser
 * of det Q (xefg.md 2.4). Because Q(-n) = Q(n), phi in [0, pi) is enough.
 *
 * **The Rankine tangent.** A criterion f = sigma_1 - f_t(kappa), sigma_1
 * the first (largest) in-plane principal stress with unit direction n1,
 * associated flow d eps_p = d kappa m with m = df/dsigma = n1 (x) n1,
 * the multiplier kappa as the history and H = df_t/dkappa < 0
 * (softening). Consistency df = m : d sigma - H d kappa = 0 with
 * d sigma = C (d eps - d kappa m) gives d kappa = m:C:d eps / (m:C:m + H)
 * and the tangent
 *
 *     C_t = C - (C m) (x) (m C) / (m:C:m + H)
 *
 * (the tangent of associated plasticity; de Borst, Crisfield, Remmers and
 * Verhoosel, "Nonlinear finite element analysis of solids and
 * structures", the chapter on plasticity).
 *
 * In Voigt form m is strain-like, m = (n1x^2, n1y^2, 2 n1x n1y), so that
 * m . d sigma is m : d sigma and m . C m is m:C:m. For an isotropic C
 * (lambda, mu, with lambda the plane-stress lambda' = 2 lambda mu /
 * (lambda + 2 mu) in plane stress), m:C:m = lambda + 2 mu = h0 and, with
 * t = (n . n1)^2,
 *
 *     det Q_t(n) = mu (lambda + 2 mu) [1 - g(t) / (h0 + H)],
 *     g(t) = (lambda + 2 mu t)^2 / (lambda + 2 mu) + 4 mu t (1 - t).
 *
 * g is concave in t with its largest value g(1) = h0 at t = 1. So for
 * -h0 < H the minimum is at n = n1, where det Q_t(n1) = mu (lambda + 2 mu)
 * H / (h0 + H): positive for H > 0, negative for -h0 < H < 0. The critical
 * softening modulus of the associated Rankine law is H_crit = 0, for any
 * stress state (derived here; test_acoustic_tensor checks it): stability
 * is lost as soon as softening starts, and the critical normal is the
 * first principal stress direction, which is the "sigma_1 >= f_t,
 * normal = n1" rule of xefg.md 2.4. (For H < -h0, a snap-back steeper
 * than the elastic modulus, the formula gives det Q > 0 again: the
 * tangent is meant for -h0 < H.)
 */
#ifndef MPM_ACOUSTIC_TENSOR_H
#define MPM_ACOUSTIC_TENSOR_H

#include "material.h"

/// [acoustic_tensor]
/**
 * @brief The acoustic tensor Q_jk = n_i C_ijkl n_l of the Voigt tangent
 *        @p C (xx, yy, xy; engineering shear) for n = (cos phi, sin phi).
 *
 * In Voigt terms, with the pair map v(1,1) = xx, v(2,2) = yy,
 * v(1,2) = v(2,1) = xy: C_ijkl = C[v(i,j)][v(k,l)]. Q is symmetric when C
 * is; Q(n) g is the traction n . sigma of the strain sym(g (x) n).
 * @param C    the tangent, d sigma = C d eps
 * @param phi  the angle of the normal n from the x axis
 * @param Q    the 2x2 result, Q[j][k]
 */
void acoustic_tensor(const double C[3][3], double phi, double Q[2][2]);

/**
 * @brief det Q(n) for n = (cos phi, sin phi): positive while plane waves
 *        with normal n propagate; <= 0 where a discontinuity with that
 *        normal may form (loss of material stability).
 * @param C    the tangent (as acoustic_tensor())
 * @param phi  the angle of the normal
 * @return Q11 Q22 - Q12 Q21
 */
double acoustic_det(const double C[3][3], double phi);
/// [acoustic_tensor]

/** What acoustic_critical() found. */
typedef struct AcousticCritical {
    double phi;       /**< the critical normal's angle, in [0, pi) */
    double det_min;   /**< det Q there, the least over all normals */
    int unstable;     /**< 1 when det_min <= 0: stability is lost */
    int evaluations;  /**< how many times det Q was evaluated */
} AcousticCritical;

/** Samples of the scan of acoustic_critical(): one per degree. */
#define ACOUSTIC_SAMPLES 180

/**
 * @brief The normal that minimises det Q(n) over phi in [0, pi), and
 *        whether stability is lost there (min det Q <= 0).
 *
 * A scan of @p samples equally spaced angles finds the least sample; a
 * golden-section search on the two intervals around it narrows the
 * bracket to 1e-10 rad. The angle is then as good as the rounding of
 * det Q allows: about sqrt(eps) rad where det Q is quadratic about its
 * minimum, eps^(1/4) ~ 1e-4 rad where it is flat to fourth order, as it
 * is for the Rankine tangent. det Q is a trigonometric polynomial in
 * 2 phi of degree 2 (Q is quadratic in (cos phi, sin phi)), so it has at
 * most two minima in [0, pi); a scan of 1 degree lands in the basin of
 * the lower one unless the two are nearly equal, and then either is a
 * fair answer. Where det Q does not depend on phi (isotropic elasticity)
 * every normal is critical and the angle returned is whichever rounding
 * favours.
 * @param C        the tangent (as acoustic_tensor())
 * @param samples  the scan's angles (ACOUSTIC_SAMPLES; at least 8)
 * @return the critical angle, det Q there and the verdict
 */
AcousticCritical acoustic_critical(const double C[3][3], int samples);

/**
 * @brief The isotropic elastic tangent of Young's modulus @p E and
 *        Poisson's ratio @p nu, plane strain (lambda + 2 mu, lambda, mu)
 *        or plane stress (E / (1 - nu^2) (1, nu, (1 - nu) / 2)).
 * @param E      Young's modulus
 * @param nu     Poisson's ratio
 * @param plane  PLANE_STRAIN or PLANE_STRESS
 * @param C      the Voigt matrix (xx, yy, xy; engineering shear)
 */
void acoustic_elastic_tangent(double E, double nu, PlaneKind plane,
                              double C[3][3]);

/**
 * @brief The angle in [0, pi) of the first principal direction n1 of the
 *        in-plane stress (sxx, syy, sxy), the direction of sigma_1:
 *        phi1 = atan2(2 sxy, sxx - syy) / 2; 0 where sigma_1 = sigma_2.
 * @param s  the stress (sxx, syy, sxy)
 * @return phi1
 */
double acoustic_principal_angle(const double s[3]);

/**
 * @brief The tangent of a Rankine softening law at stress @p s:
 *        C_t = C - (C m) (x) (m C) / (m . C m + H), m = n1 (x) n1 in
 *        strain-like Voigt form (n1x^2, n1y^2, 2 n1x n1y).
 *
 * Meant for the loading branch of f = sigma_1 - f_t(kappa) = 0 with
 * -m . C m < H (see the file's comment for the derivation); a general,
 * not necessarily isotropic, @p C may be given.
 * @param C   the elastic tangent
 * @param s   the stress (sxx, syy, sxy) that fixes n1
 * @param H   the softening modulus df_t/dkappa (< 0 softens)
 * @param Ct  the tangent (may not be @p C)
 * @return m . C m, the elastic modulus h0 of the flow direction
 */
double acoustic_rankine_tangent(const double C[3][3], const double s[3],
                                double H, double Ct[3][3]);

#endif
