/**
 * @file j_integral.h
 * @brief The J-integral at the tips of CRAMP cracks (chapter 7): a crack's
 *        `j_integral` settings, the tips it has, and the dynamic J of each
 *        tip on square domains of a few cells (Guo and Nairn, CMES 6
 *        (2004), the domain form of their eq. 1).
 */
#ifndef MPM_J_INTEGRAL_H
#define MPM_J_INTEGRAL_H

#include <libconfig.h>

#include "cracks.h"
#include "sim.h"

struct SceneReader;

/** Most contours of one crack's j_integral. */
#define J_CONTOURS_MAX 8

/** One crack's `j_integral` settings, as the scene gave them. */
typedef struct JSettings {
    int on;                       /**< the crack has the key */
    long every;                   /**< steps between evaluations */
    int ncontours;                /**< how many contours */
    int contour[J_CONTOURS_MAX];  /**< half-widths of the domains, in cells */
    int line;                     /**< line of the key (scene_lines_at()) */
    int contours_line;            /**< line of its contours */
} JSettings;

/** One tip that J is evaluated at: a crack's end that lies in a body. */
typedef struct JTip {
    int crack;                    /**< stage 2's crack index */
    int end;                      /**< 0: its first point, 1: its last */
    double x;                     /**< the tip now */
    double y;                     /**< the tip now */
    double ex;                    /**< unit vector ahead of the tip (x1) */
    double ey;                    /**< its y */
    double J[J_CONTOURS_MAX];     /**< the latest J per contour (N/mm) */
    double KI[J_CONTOURS_MAX];    /**< the latest K_I per contour (MPa mm^1/2) */
    double KII[J_CONTOURS_MAX];   /**< the latest K_II per contour */
    int kink;                     /**< 0: the crack runs straight along x1
                                       through the widest domain; k > 0:
                                       its k-th segment back from the tip
                                       (points k - 1 to k back) is the
                                       first that turns (j_tip_kink()) */
    double Jface[J_CONTOURS_MAX]; /**< the face term's part of J */
    double KIface[J_CONTOURS_MAX];  /**< its part of K_I */
    double KIIface[J_CONTOURS_MAX]; /**< its part of K_II */
} JTip;

/// [j_state]
/** Stage 7's state: the settings per crack, the tips, the points' first
 *  positions (their displacement u = x - X) and scratch per field slot. */
typedef struct JState {
    int ncracks;                  /**< entries of set */
    JSettings *set;               /**< per crack (on = 0 without the key) */
    int ntips;                    /**< tips evaluated */
    JTip *tip;                    /**< the tips */
    long every;                   /**< the smallest every of the cracks:
                                       every tip is evaluated then */
    long at_step;                 /**< step of the latest evaluation */
    double at_time;               /**< its time */
    int npoints;                  /**< points of X, Y */
    double *X;                    /**< first position x of each point */
    double *Y;                    /**< first position y */
    int *near;                    /**< scratch: the points beside a kinked
                                       tip's faces (j_faces.c) */
    int cap;                      /**< slots of the scratch below */
    double *mux;                  /**< per slot: sum m S u_x */
    double *muy;                  /**< per slot: sum m S u_y */
    double *m;                    /**< per slot: sum m S */
} JState;
/// [j_state]

/** The keys of a crack's j_integral group (NULL-ended). */
extern const char *const j_integral_keys[];

/** @brief Read `cracks.[index].j_integral` and, for the first crack that
 *         has it, subscribe stage 7's hooks (set-up, Task 7, history,
 *         report, checkpoint). @return 0, or -1 with the message in @p r. */
int j_integral_read(Sim *sim, const config_setting_t *s, int index,
                    struct SceneReader *r);

/** @brief Set-up: find the tips, check that every contour lies in the
 *         grid, keep the first positions, allocate the scratch.
 *  @return 0, or -1 with "file:line: ..." in @p err. */
int j_integral_prepare(Sim *sim, void *state, char *err, size_t errlen);

/**
 * @brief J at every tip and contour, now, into JTip::J (N/mm, that is
 *        mJ/mm^2): the domain integral over the square of half-width c
 *        cells about the tip, with the weight q falling from 1 to 0
 *        across its outermost ring of cells,
 *
 *   J = sum_p A_p [ (sigma_ij u_i,1 - (W + T) delta_1j) q_,j
 *                   + rho ((a_i + kappa v_i) u_i,1 - v_i v_i,1) q ]
 *
 * in the tip's frame (x1 ahead), from the points' stresses, strains,
 * velocities and areas A_p = V_p / thickness, and the gradients of the
 * displacement and velocity the grid gives each point through its own
 * velocity fields (so each side of the crack sees its own nodes).
 *
 * K_I and K_II (JTip::KI, JTip::KII) on the same domains and weights, by
 * the interaction integral with Williams' fields of unit K as auxiliary
 * states (stage 6's williams_field(), in the tip's frame: x1 ahead, x2
 * its left normal),
 *
 * \verbatim
   M^(m) = sum_p A_p [ (sigma_ij u^m_i,1 + sigma^m_ij u_i,1
                        - sigma_ij eps^m_ij delta_1j) q_,j
                       + rho (a_i + kappa v_i) u^m_i,1 q ]
   \endverbatim
 *
 * At a tip whose crack turns inside the domain (JTip::kink), both gain
 * the face terms of j_face_terms().
 *
 * K_I = E' M^(I) / 2, K_II = E' M^(II) / 2 (E' = E in plane stress,
 * E / (1 - nu^2) in plane strain; Yau, Chen and Shih 1980), with E and nu
 * of each point's material (a linear elastic body about the tip).
 * @return 0; -1 when out of memory for a grid that grew.
 */
int j_integral_evaluate(const Sim *sim, JState *S);

/**
 * @brief The auxiliary states of the interaction integral at (@p x, @p y)
 *        about tip @p T: Williams' near-tip fields of K_I = 1 (mode 0) and
 *        K_II = 1 (mode 1) MPa mm^1/2 of material @p m (stage 6's
 *        williams_field(), Anderson, Fracture Mechanics, ch. 2), built in
 *        the tip's frame (x1 ahead, x2 its left normal) and given in global
 *        axes: stress s[mode][i][j] and displacement gradient
 *        du[mode][i][j] = d u_i / d x_j.
 * @param T            the tip (its place and frame)
 * @param c            its crack (behind a kink the cut of theta follows
 *                     it: j_tip_angle())
 * @param m            the material about it (E, nu)
 * @param plane_strain 1 for plane strain, 0 for plane stress
 * @param x            where, x (mm)
 * @param y            where, y (mm)
 * @param s            out: the auxiliary stresses, per mode
 * @param du           out: the auxiliary displacement gradients, per mode
 */
void k_auxiliary(const JTip *T, const Crack *c, const Material *m,
                 int plane_strain, double x, double y, double s[2][2][2],
                 double du[2][2][2]);

/** What one point brings to J: its gradients and the rest. */
typedef struct JPoint {
    double D[2][2];   /**< displacement gradient du_i/dx_k */
    double L[2][2];   /**< velocity gradient dv_i/dx_k */
    double a[2];      /**< acceleration, from its nodes */
} JPoint;

/** @brief The gradients of point @p p from the slots of its stencil
 *         (eq. 6), the slots' displacements as j_integral_evaluate() left
 *         them in @p S. */
void j_point_gradients(const Sim *sim, const JState *S, int p, JPoint *jp);

/** @brief The strain energy density W = sigma_ij eps_ij / 2 of point
 *         @p p (linear elastic). */
double j_strain_energy(const Particles *P, int p);

/** @brief The weight q of the domain of half-width @p c cells about tip
 *         @p T at (x, y), and its gradient @p dq. @return q. */
double j_weight(const Grid *g, const JTip *T, int c, double x, double y,
                double dq[2]);

/** @brief Where crack @p c, walked back from tip @p T through the square
 *         of half-width @p cells cells about it, first turns away from
 *         the tip's direction: sets JTip::kink. */
void j_tip_kink(const Grid *g, const Crack *c, JTip *T, int cells);

/** @brief The polar angle about tip @p T of the point (@p x1, @p x2) of
 *         its frame, with the cut along the crack @p c: atan2(x2, x1) on a
 *         crack straight through the domain; behind a kink (JTip::kink),
 *         continued across the ray theta = pi (material there) to the
 *         crack's own faces, so that the auxiliary fields are continuous
 *         wherever the material is. @return theta (rad). */
double j_tip_angle(const Crack *c, const JTip *T, double x1, double x2);

/** @brief The face terms of J and of the interaction integrals at a
 *         kinked tip (JTip::kink > 0), added to JTip::J, JTip::KI and
 *         JTip::KII (the latter still M^(I), M^(II)) and kept in
 *         JTip::Jface, JTip::KIface, JTip::KIIface: over the faces behind
 *         the kink, traction-free,
 *         int (W + T) m_1 q ds for J and
 *         int (sigma_ij eps^m_ij m_1 - sigma^m_ij m_j u_i,1) q ds for M^(m),
 *         m the normal out of the material; the fields on each face from
 *         the points beside it. */
void j_face_terms(const Sim *sim, const JState *S, JTip *T);

/** @brief Make the scratch hold @p slots field slots (never shrinks).
 *  @return 0, or -1 when out of memory. */
int j_integral_fit(JState *S, int slots);

/** @brief Bring each tip's point and direction up to date with the
 *         cracks (stage 2 moves them at Task 7). */
void j_integral_tips(const Sim *sim, JState *S);

/** @brief Task 7: move the tips with the cracks, evaluate J every
 *         JState::every steps and at the last step. */
int j_integral_task7(Sim *sim, void *state, Seam seam);

/** @brief history.csv: columns per tip and contour, the latest
 *         evaluation: J_crack0_last_c4 (crack 0's last point, 4 cells),
 *         then KI_crack0_last_c4 and KII_crack0_last_c4. */
int j_integral_history(const Sim *sim, void *state, FILE *f, int header);

/** @brief The end of a run: J, K_I and K_II per tip and contour, and
 *         the spread of J. */
int j_integral_report(const Sim *sim, void *state, FILE *f);

/** @brief Save or restore the first positions and the latest J. */
int j_integral_checkpoint(Sim *sim, void *state, FILE *f, int save);

/** @brief Release stage 7's state. */
void j_integral_release(void *state);

#endif
