/**
 * @file cohesive_law.h
 * @brief The traction-separation law of a cohesive crack (Rabczuk and Zi,
 *        eq. 17-21: the traction t_c([[u]]) on the crack; the law itself
 *        is not in our transcript, which stops at eq. 32: xefg.md 2.3).
 *
 * Our choice, an intrinsic law: the faces are held by a penalty spring of
 * stiffness K until the traction reaches f_t at the opening
 * delta_0 = f_t / K; then the traction softens, linearly to zero at
 * delta_c = 2 G_f / f_t or exponentially, so that the whole area under the
 * curve, elastic branch included, is G_f. As K grows it becomes the
 * extrinsic law of xefg.md 2.3, t = f_t (1 - delta / delta_c) or
 * t = f_t exp(-f_t delta / G_f). The opening is the effective one,
 * delta = sqrt(max(delta_n, 0)^2 + beta^2 delta_s^2) (beta = 0: normal opening
 * alone); a history variable delta_max gives secant unloading to the
 * origin; a closing face (delta_n < 0) is pushed back by the penalty K.
 */
#ifndef MPM_COHESIVE_LAW_H
#define MPM_COHESIVE_LAW_H

/** The softening curve. */
typedef enum {
    COHESIVE_LINEAR = 0,      /**< straight to zero at delta_c = 2 G_f / f_t */
    COHESIVE_EXPONENTIAL = 1  /**< exp(-f_t (delta - delta_0) / G_s) */
} CohesiveKind;

/** The law of one crack. */
typedef struct CohesiveLaw {
    CohesiveKind kind;  /**< the softening curve */
    double f_t;         /**< tensile strength (stress) */
    double G_f;         /**< fracture energy (energy / area) */
    double K;           /**< penalty stiffness (stress / length) */
    double beta;        /**< weight of the sliding in the opening (0: none) */
} CohesiveLaw;

/** The state of the law at one crack point after an opening. */
typedef struct CohesiveState {
    double tn;      /**< normal traction (+: pulls the faces together) */
    double ts;      /**< shear traction, along the crack */
    double stored;  /**< elastic energy per area held now */
} CohesiveState;

/** @brief The opening delta_0 = f_t / K where softening begins. */
double cohesive_delta0(const CohesiveLaw *L);

/** @brief The opening where the traction reaches zero: delta_c = 2 G_f / f_t
 *         (linear); infinity (exponential). */
double cohesive_delta_c(const CohesiveLaw *L);

/**
 * @brief The slope of the softening branch just past delta_0, d t / d
 *        delta (stress / length, negative): -f_t / (delta_c - delta_0)
 *        for the linear law, -f_t^2 / G_s for the exponential (G_s = G_f
 *        - f_t delta_0 / 2, the decay energy).
 */
double cohesive_softening_slope(const CohesiveLaw *L);

/**
 * @brief The envelope t(delta) for a growing effective opening
 *        delta >= 0: K delta up to delta_0, then the softening curve.
 */
double cohesive_envelope(const CohesiveLaw *L, double delta);

/** @brief The work of the envelope from 0 to @p delta, its closed-form
 *         integral (G_f once the crack is open). */
double cohesive_envelope_work(const CohesiveLaw *L, double delta);

/**
 * @brief Energy per area dissipated once the opening reached @p dmax:
 *        the work of the envelope less what the secant line to the origin
 *        gives back, W(dmax) - t(dmax) dmax / 2 (0 on the elastic branch).
 */
double cohesive_dissipated(const CohesiveLaw *L, double dmax);

/**
 * @brief The tractions for the normal and sliding openings @p dn, @p ds
 *        and the history *@p dmax (raised to the effective opening when it
 *        is passed, when @p commit): secant stiffness k = t(dmax) / dmax
 *        (K before softening), t_n = k max(dn, 0) + K min(dn, 0),
 *        t_s = beta^2 k ds, the gradient of the stored energy
 *        k (max(dn, 0)^2 + beta^2 ds^2) / 2 + K min(dn, 0)^2 / 2.
 */
CohesiveState cohesive_traction(const CohesiveLaw *L, double dn, double ds,
                                double *dmax, int commit);

#endif
