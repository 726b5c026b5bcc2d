/**
 * @file growth.h
 * @brief Cohesive XEFG cracks that grow (Rabczuk and Zi, section 2 and
 *        xefg.md 2.3-2.4; the transcript stops at eq. 32, so when, where
 *        and how a tip grows are our choices): a tip grows by one segment
 *        when the maximum principal stress averaged ahead of it reaches
 *        the law's f_t, normal to that stress or (direction = "hoop") by
 *        the largest hoop stress of K_I, K_II; the new segment starts
 *        closed, on the elastic branch of the intrinsic law, and the
 *        discretisation is updated around it only, in room reserved at
 *        set-up.
 */
#ifndef MPM_GROWTH_H
#define MPM_GROWTH_H

#include <stddef.h>
#include <stdio.h>

#include "acoustic_tensor.h"
#include "cell_list.h"
#include "cohesive_law.h"
#include "quadrature.h"
#include "xefg.h"

/** One crack's `growth` group. */
typedef struct XefgGrowthSettings {
    int on;            /**< the crack has one */
    double length;     /**< length of a new segment (0: one node spacing) */
    int max_segments;  /**< most segments the crack may add (0: the default) */
    int hoop;          /**< direction = "hoop": where by the largest hoop
                            stress of K_I, K_II (0: normal to sigma_1) */
    int tip;           /**< criterion = "tip": when by the cohesive zone's
                            own tip (growth_tip_zone(); 0: "average") */
    double max_speed;  /**< a tip grows again only length / max_speed
                            after its last event (0: no limit) */
    double radius;     /**< radius of the half disk criterion = "average"
                            averages over (0: the default,
                            growth_default_radius()) */
    double tip_radius[2]; /**< the radius in use at each end: `radius`,
                            or the default of the material at the tip */
    double tangent[2][3][3]; /**< the elastic tangent of the material at
                            each end (Voigt, acoustic_elastic_tangent()) */
    double softening;  /**< H of the bulk's Rankine tangent at a tip: h
                            times the law's softening slope (the crack
                            band of width h; Bazant and Oh 1983) */
    int line;          /**< line of the group, for messages */
} XefgGrowthSettings;

/** One growth event, for the outputs and the tests. */
typedef struct GrowthEvent {
    int crack;         /**< which crack */
    int end;           /**< which end grew (0 or 1) */
    long step;         /**< the step after which it grew */
    double t;          /**< the time */
    double sigma1;     /**< the averaged sigma_1 that made it grow */
    double KI;         /**< K_I at the tip (direction = "hoop"; else 0) */
    double KII;        /**< K_II at the tip (direction = "hoop"; else 0) */
    double x0;         /**< the old tip: x */
    double y0;         /**< the old tip: y */
    double x1;         /**< the new tip: x */
    double y1;         /**< the new tip: y */
} GrowthEvent;

/// [growth_state]
/** The growth state of a scene: settings per crack, the room reserved at
 *  set-up and the scratch a growth event works in (no allocation inside a
 *  time step). */
typedef struct Growth {
    int ncrack;              /**< entries of set */
    XefgGrowthSettings *set;     /**< per crack (on = 0: the crack stays) */
    double radius;           /**< the widest default averaging radius
                                  ahead of a tip, 1.5 h */
    double k_radius;         /**< r_d of the interaction integral that
                                  K_I, K_II of direction = "hoop" take */
    double h;                /**< the node spacing */
    int *point_cap;          /**< per crack: room for points of its line */
    int dof_cap;             /**< room for parameters */
    int gauss_cap;           /**< room for Gauss points (and their rows) */
    int coh_cap;             /**< room for cohesive points */
    CellList cl;             /**< the nodes' cell list, kept from set-up */
    int nevent;              /**< growth events so far */
    int event_cap;           /**< room for events */
    GrowthEvent *event;      /**< the events */
    int power_runs;          /**< power iterations run after set-up */
    long waits;              /**< steps a tip met its criterion but waited
                                  for its max_speed */
    char msg[480];           /**< the message that stops a run */
    /* scratch, sized at set-up */
    int *add;                /**< per node: parameters it gains */
    int *shift;              /**< per node: parameters inserted before it */
    int *mark;               /**< per Gauss point / node: what to redo */
    int *len;                /**< per row: new length */
    double *diag;            /**< per parameter: int rho E^2 (lumping) */
    double *zs;              /**< the power iteration's vector z */
    double *kzs;             /**< its K z */
    double *gss;             /**< its Gauss-point stresses */
    QuadPoint *quad;         /**< one cell's quadrature points */
    QuadWork *qw;            /**< the room of their cutting */
    int quad_cap;            /**< their room */
    ShapeRows row;           /**< one place's row */
    ShapeRows rows;          /**< rows of the nodes and cohesive points
                                  redone in an event */
} Growth;
/// [growth_state]

/** @brief The growth state of @p sim (NULL when no crack grows). */
static inline Growth *growth_of(const Sim *sim)
{
    return (Growth *)sim_state(sim, "xefg growth");
}

/** The keys of a crack's `growth` group. */
extern const char *const growth_keys[];

/**
 * @brief Read cracks.[@p index].growth = { length = ...; max_segments =
 *        ...; } (both optional). @return 0, or -1 with a message naming
 *        the file and line.
 */
int growth_read(Sim *sim, const config_setting_t *s, int index,
                struct SceneReader *r);

/**
 * @brief Set-up with the discretisation and its cohesive points built:
 *        refuse growth on a crack without a cohesive law, set the
 *        defaults, and reserve the room every growth event may use.
 * @return 0, or -1 with a message naming the file and line in @p err.
 */
int growth_build(Growth *g, Xefg *x, const Sim *sim, char *err,
                 size_t errlen);

/** @brief Release what growth_build() and growth_read() allocated. */
void growth_free(Growth *g);

/**
 * @brief The default radius of criterion = "average": the half length
 *        of the material's critical distance, L / 2 = E' G_f / (2 pi
 *        f_t^2) (Taylor's point method; chapter 6c), kept within
 *        [h / 2, 1.5 h] of the node spacing @p h: no narrower than the
 *        tip's own Gauss points, no wider than the 1.5 h that smooths
 *        single points. @p Ep is E' (E / (1 - nu^2) in plane strain).
 */
double growth_default_radius(double h, double Ep, const CohesiveLaw *L);

/**
 * @brief When a tip grows under criterion = "average": the loss of
 *        material stability of the bulk ahead of it (Rabczuk and Zi,
 *        abstract; xefg.md 2.4). The bulk's tangent at the averaged stress
 *        @p s is the elastic @p C while sigma_1 < @p f_t, and on the
 *        Rankine surface sigma_1 >= f_t the softening tangent of
 *        acoustic_rankine_tangent() with modulus @p H (< 0); stability is
 *        lost where det Q(n) <= 0 for some normal n (acoustic_critical(),
 *        into @p a). For this tangent that is sigma_1 >= f_t with n the
 *        first principal direction (acoustic_tensor.h derives it).
 * @return 1 when stability is lost (the tip grows), else 0
 */
int growth_stability_lost(const double s[3], double f_t, const double C[3][3],
                          double H, AcousticCritical *a);

/**
 * @brief The stress averaged over the Gauss points within @p radius of
 *        the tip at end @p end of crack @p c and ahead of it (the half
 *        disk its direction points into), weighted by their weights, into
 *        @p s (xx, yy, xy); criterion = "average" passes the tip's
 *        XefgGrowthSettings::tip_radius.
 *        @return the number of points averaged.
 */
int growth_tip_stress(const Xefg *x, int c, int end, double radius,
                      double s[3]);

/**
 * @brief When a tip grows under criterion = "tip" (our choice, chapter 6b,
 *        "Petersson's beam"): the value compared with f_t of crack @p c's
 *        law @p L at end @p end. Where the crack's last segment holds
 *        cohesive points, K dmax, the largest of them: it reaches f_t when
 *        the cohesive zone's own tip (where the traction reaches f_t) has
 *        come into the last segment, so that a closed segment always lies
 *        ahead of it, as on a pre-inserted ligament; where it holds none
 *        (a traction-free notch), sigma_1 of the stress averaged over the
 *        half disk of radius h / 2 ahead of the tip (the Gauss points
 *        nearest it). @return that value, or NAN when neither has a point.
 */
double growth_tip_zone(const Growth *g, const Xefg *x, int c, int end,
                       const CohesiveLaw *L);

/**
 * @brief The criterion of a tip: from the averaged stress @p s, the value
 *        that is compared with f_t (returned) and the unit direction the
 *        crack grows in, @p dir, the one of the two that points ahead
 *        (@p ahead). Rankine: sigma_1, and the crack grows normal to the
 *        sigma_1 direction. The acoustic-tensor criterion (xefg.md 2.4)
 *        plugs in here.
 */
double growth_criterion(const double s[3], const double ahead[2],
                        double dir[2]);

/**
 * @brief Where a tip grows under direction = "hoop" (our choice, chapter
 *        6b): K_I and K_II at end @p end of crack @p c by the interaction
 *        integral (xefg_stress_intensity(), r_d = Growth::k_radius), into
 *        @p K, and the unit direction @p dir turned from @p ahead by the
 *        angle of largest hoop stress, hoop_angle() (Erdogan and Sih
 *        1963), K_I < 0 counting as 0 as for CRAMP's cracks (chapter 7b).
 * @return 0, or -1 when the integral fails (its ring holds no Gauss point
 *         or two materials).
 */
int growth_hoop_direction(const Sim *sim, const Growth *g, int c, int end,
                          const double ahead[2], double K[2], double dir[2]);

/**
 * @brief After a step: every growing tip whose criterion reaches f_t grows
 *        by one segment (growth_insert()). @return 0, or -1 with
 *        Sim::fail filled when a crack is full or the update fails.
 */
int growth_after_step(Sim *sim, Xefg *x, Growth *g);

/**
 * @brief Add the segment from the tip at end @p end of crack @p c to
 *        (@p px, @p py) and update what it touches: the crack's line, the
 *        enrichment of the nodes whose supports it meets (new parameters,
 *        zero, mass lumped), the Gauss points and rows near it, the rows
 *        at the nodes, its cohesive points and the jump rows near it, and
 *        the stable step (power iteration; the run's step only falls).
 * @return 0, or -1 with a message naming the crack in @p err.
 */
int growth_insert(Sim *sim, Xefg *x, Growth *g, int c, int end, double px,
                  double py, char *err, size_t errlen);

/**
 * @brief Does the new segment from @p a (the tip at end @p end of crack
 *        @p c) to @p b meet a crack: another crack's line, or its own away
 *        from the segment it continues, within 1e-9 @p h (touching or
 *        crossing)? @return the crack it meets, its segment in @p seg, or
 *        -1. Two cracks meeting would need Rabczuk and Zi's junction
 *        enrichment (their eq. 10), which XEFG here lacks: the caller
 *        stops the run (growth_after_step()).
 */
int growth_meets(const Xefg *x, double h, int c, int end, const double a[2],
                 const double b[2], int *seg);

/** Room one more row must find in reserved rows (entries). */
#define ROW_ROOM 2048

/** @brief Make room in place for rows of lengths @p len (none shorter
 *  than it was), moving the entries from the last row down (no
 *  allocation). @return 0, or -1 when a row would shrink or no room. */
int growth_rows_expand(ShapeRows *R, const int *len, int grad);

/** @brief Copy the values of row @p k of @p S into row @p r of @p R,
 *  whose room is made (growth_rows_expand()). */
void growth_copy_row(ShapeRows *R, int r, const ShapeRows *S, int k);

/** @brief Distance from (@p px, @p py) to the segment from @p a to @p b. */
double growth_segment_distance(const double a[2], const double b[2], double px,
                               double py);

/**
 * @brief The parameters the nodes whose supports meet the new segment
 *        from @p a to @p b of crack @p c lack with the longer line (a step
 *        one where it now cuts a support through, branch ones about the
 *        new tip), added at zero after each node's own, the others
 *        renumbered in place; their masses are left to the caller
 *        (Growth::add holds how many each node gained).
 * @return how many were added, or -1 with a message when the room is full.
 */
int growth_add_parameters(Xefg *x, Growth *g, int c, const double a[2],
                      const double b[2], char *err, size_t errlen);

/**
 * @brief The Gauss points and rows near the new segment from @p a to @p b:
 *        the cells it cuts get new quadrature points (their state carried
 *        from the nearest old point of the cell on the same side, plus the
 *        law's response to the difference of strain), the rows of the
 *        points within 2 d of it are made again; then the rows at the nodes
 *        and the lumped masses of the new parameters.
 * @return 0, or -1 with a message.
 */
int growth_rows(Sim *sim, Xefg *x, Growth *g, int c, const double a[2],
                const double b[2], char *err, size_t errlen);

/**
 * @brief The cohesive points of the new segment (segment @p seg of crack
 *        @p c), with their history at zero (closed, on the elastic
 *        branch), and the jump rows of the points within 2 d of the
 *        segment from @p a to @p b made again (they gain the new
 *        parameters). @return 0, or -1 with a message.
 */
int growth_cohesive(Sim *sim, Xefg *x, Growth *g, int c, int seg,
                    const double a[2], const double b[2], char *err,
                    size_t errlen);

/**
 * @brief The checkpoint section of a scene whose cracks grow (SEAM_CHECKPOINT,
 *        subscribed when the first `growth` group is read, so that it
 *        comes before the parameters' section): the events and the steps
 *        waited; at restore the cracks (restored grown by stage 2) are
 *        taken back to their set-up points and the events replayed
 *        (growth_insert() at each event's step and time) into the
 *        discretisation as set up, which the later sections then fill.
 * @return 0, or -1 when the file is cut short, holds more events than the
 *         room, or an event does not continue its crack's tip.
 */
int growth_checkpoint(Sim *sim, void *state, FILE *f, int save);

/** @brief The history columns and report of a scene whose cracks grow.
 *  @return 0, or -1 when a seam is full. */
int growth_subscribe(Sim *sim, Growth *g);

#endif
