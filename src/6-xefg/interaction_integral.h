/**
 * @file interaction_integral.h
 * @brief Stress intensity factors K_I and K_II at a tip of an XEFG crack by
 *        the domain form of the interaction integral (Yau, Chen and Shih,
 *        J. Appl. Mech. 47 (1980) 335-341; Moran and Shih, Eng. Fract.
 *        Mech. 27 (1987) 615-642; in the form used for XFEM by Moes,
 *        Dolbow and Belytschko, IJNME 46 (1999) 131-150), with the
 *        Williams near-tip fields as the auxiliary states (xefg.md Test 3).
 */
#ifndef MPM_INTERACTION_INTEGRAL_H
#define MPM_INTERACTION_INTEGRAL_H

#include "sim.h"

/**
 * @brief The Williams near-tip field of unit stress intensity (K = 1 MPa
 *        sqrt(mm)) of mode I (@p mode = 1) or mode II (@p mode = 2), in the
 *        tip's frame (x1 ahead of the crack, x2 its left normal) at polar
 *        coordinates (r, theta), theta in [-pi, pi] (+-pi on the faces).
 *
 * Stresses and displacements as in Anderson, Fracture Mechanics (3rd ed.),
 * chapter 2: sigma = g(theta) / sqrt(2 pi r), u = sqrt(r / (2 pi))
 * f(theta) / (2 mu); the gradients by the chain rule in (r, theta).
 * @param mode   1 (mode I) or 2 (mode II)
 * @param mu     shear modulus
 * @param kappa  3 - 4 nu (plane strain) or (3 - nu) / (1 + nu) (plane stress)
 * @param r      distance from the tip, > 0
 * @param theta  angle from the x1 axis
 * @param s      stress 11, 22, 12 (may be NULL)
 * @param u      displacement 1, 2 (may be NULL)
 * @param du     gradient du[2 i + j] = d u_i / d x_j (may be NULL)
 */
void williams_field(int mode, double mu, double kappa, double r, double theta,
                    double s[3], double u[2], double du[4]);

/**
 * @brief K_I and K_II at end @p end (0 or 1) of crack @p crack of an XEFG
 *        simulation, from the Gauss points' stresses and the displacement
 *        gradients of the discretisation, by the domain interaction
 *        integral
 *
 *   I^(m) = int_A [sigma_ij u^m_i,1 + sigma^m_ij u_i,1 - sigma^m_ij eps_ij
 *           delta_1j] q_,j dA + int_A rho (a_i + kappa v_i) u^m_i,1 q dA
 *
 * (the second integral, the inertia of a moving body, is zero at rest;
 * the auxiliary state is static, so no kinetic term crosses),
 * in the tip's frame (x1 ahead of the crack, x2 its left normal, at
 * either end: a straight crack under a uniform remote stress has the same
 * K_I and K_II at both tips), m = I, II the auxiliary Williams fields of
 * unit K, and since I^(m) = 2 K_m / E' (Irwin's
 * J = (K_I^2 + K_II^2) / E' for the sum of the two states),
 * K_I = E' I^(I) / 2 and K_II = E' I^(II) / 2,
 * E' = E / (1 - nu^2) in plane strain, E in plane stress (run.plane).
 * The weight q is 1 within @p radius of the tip and falls to 0 at 2 radius
 * as the smooth step 1 - 3 t^2 + 2 t^3 (t = r / radius - 1), so that only
 * the ring between contributes, away from the singular tip; the ring must lie
 * in one material, hold no other crack and keep off the body's boundary,
 * and the crack must be straight across it.
 * @param sim    a simulation of run.method = "xefg" (a linear elastic body)
 * @param crack  the crack (stage 2's order)
 * @param end    its end: 0 (first point) or 1 (last point)
 * @param radius r_d (mm), a few node spacings
 * @param K      K_I and K_II (MPa sqrt(mm))
 * @return 0; -1 when the method is not xefg, the end is not a tip, radius
 *         is not positive, the ring holds no Gauss point or more than one
 *         material
 */
int xefg_stress_intensity(const Sim *sim, int crack, int end, double radius,
                          double K[2]);

#endif
