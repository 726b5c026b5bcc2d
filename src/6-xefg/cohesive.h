/**
 * @file cohesive.h
 * @brief Cohesive XEFG cracks (Rabczuk and Zi, eq. 17-21 and the crack
 *        term of eq. 30): a crack's `cohesive` settings, the quadrature
 *        points along its segments with the jump of the enriched
 *        displacement there, the tractions of the law as internal forces,
 *        and the energy the law stores and dissipates.
 */
#ifndef MPM_COHESIVE_H
#define MPM_COHESIVE_H

#include <stddef.h>

#include "cell_list.h"
#include "cohesive_law.h"
#include "energy_balance.h"
#include "xefg.h"

/** One crack's `cohesive` group. */
typedef struct CohesiveSettings {
    int on;           /**< the crack has one */
    CohesiveLaw law;  /**< its law (K = 0 until the default is set) */
    int notch;        /**< its first segments, as given, traction-free: a
                           notch with a cohesive ligament grown from its tip
                           (key notch_segments, default 0) */
    int line;         /**< line of the group, for messages */
} CohesiveSettings;

/// [cohesive_state]
/** The cohesive state of a scene: settings per crack, then (at set-up)
 *  the points along the cracks and their history. */
typedef struct Cohesive {
    int ncrack;              /**< entries of set */
    CohesiveSettings *set;   /**< per crack (on = 0: traction-free) */
    int npt;                 /**< quadrature points along the cracks */
    int *crack;              /**< crack of each point */
    double *px;              /**< where: x */
    double *py;              /**< where: y */
    double *w;               /**< weight: length x thickness */
    double *tx;              /**< unit tangent (the segment's direction):
                                  x; the normal (-ty, tx) points to side +1 */
    double *ty;              /**< unit tangent: y */
    ShapeRows jump;          /**< per point: the parameters whose function
                                  jumps there and the jump, N = Phi_I
                                  (E+ - E-): [[u]] = sum N u_q */
    double *dmax;            /**< history: largest effective opening */
    double *dn;              /**< normal opening now */
    double *ds;              /**< sliding opening now */
    double *tn;              /**< normal traction now */
    double *ts;              /**< shear traction now */
    double *stored;          /**< elastic energy per area now */
} Cohesive;
/// [cohesive_state]

/** @brief The cohesive state of @p sim (NULL when no crack has one). */
static inline Cohesive *cohesive_of(const Sim *sim)
{
    return (Cohesive *)sim_state(sim, "xefg cohesive");
}

/** The keys of a crack's `cohesive` group. */
extern const char *const cohesive_keys[];

/**
 * @brief Read cracks.[@p index].cohesive = { law = "linear"; f_t = ...;
 *        G_f = ...; penalty = ...; shear = ...; }.
 * @return 0, or -1 with a message naming the file and line.
 */
int cohesive_read(Sim *sim, const config_setting_t *s, int index,
                  struct SceneReader *r);

/**
 * @brief Set-up with the discretisation built: the default penalties, the
 *        points on every segment of a cohesive crack inside a body
 *        (@p x's Gauss rule, pieces no longer than a point spacing) and
 *        their jump rows; all arrays of the step allocated here.
 * @return 0, or -1 with a message in @p err.
 */
int cohesive_build(Cohesive *c, const Xefg *x, const Sim *sim,
                   const CellList *cl, char *err, size_t errlen);

/**
 * @brief The jump row of crack @p k at (px, py) from the last row of @p R
 *        (the place's own row): the enriched parameters of the crack and
 *        their jumps Phi_I [[E_q]] into @p dof and @p N (NULL: count only).
 * @return how many entries.
 */
int cohesive_jump_row(const Xefg *x, const ShapeRows *R, int k, double px,
                      double py, int *dof, double *N);

/**
 * @brief The points of segment @p g of crack @p k (the parts inside a
 *        body, in pieces no longer than @p h, @p x's Gauss rule on each)
 *        appended to @p c with their jump rows, using @p R as scratch and
 *        growing the arrays beyond *@p cap points only when needed.
 * @return 0, or -1 with a message in @p err.
 */
int cohesive_segment_points(Cohesive *c, const Xefg *x, const Sim *sim,
                            const CellList *cl, int k, int g, double h,
                            ShapeRows *R, int *cap, char *err, size_t errlen);

/** @brief Release what cohesive_build() and cohesive_read() allocated. */
void cohesive_free(Cohesive *c);

/**
 * @brief The openings of the parameters' displacements @p u at every
 *        point, the law's tractions (the history raised when @p commit),
 *        and their internal forces int [[psi_q]] t dGamma added to @p f
 *        (2 per parameter; NULL: the tractions only).
 */
void cohesive_force(Cohesive *c, const double *u, double *f, int commit);

/** @brief The penalty stiffness K applied to the openings of @p z, added
 *         to @p kz (for the stable step's power iteration). */
void cohesive_stiffness(const Cohesive *c, const double *z, double *kz);

/** @brief Elastic energy the law holds now (mJ). */
double cohesive_stored_energy(const Cohesive *c);

/** @brief Energy the law has dissipated (mJ). */
double cohesive_dissipated_energy(const Cohesive *c);

/** @brief The energy account of an XEFG run with a cohesive crack, in
 *         stage 5's terms: in = the start (kinetic + strain) + the work of
 *         the held places; stored = kinetic + strain + what the law holds;
 *         damping = XEFG's damped work (Xefg::w_damped); dissipated = every
 *         stage's SEAM_ENERGY term (the law's dissipation). */
EnergyTerms cohesive_energy_terms(const Sim *sim);

/** @brief The history columns, report, checkpoint and energy term of a
 *         scene with a cohesive crack. @return 0, or -1 when a seam is
 *         full. */
int cohesive_subscribe(Sim *sim, Cohesive *c);

#endif
