/**
 * @file cracks.h
 * @brief Explicit cracks (polylines of massless points) and the velocity
 *        fields they create at grid nodes (paper's section 2.1, Tasks 1
 *        and 7).
 */
#ifndef MPM_CRACKS_H
#define MPM_CRACKS_H

#include "sim.h"

/** One crack: a polyline whose end points are massless material points. */
typedef struct Crack {
    int n;          /**< number of points (segments + 1) */
    double *x;      /**< point x */
    double *y;      /**< point y */
    double xmin;    /**< extent of the points (Appendix, subtask 1) */
    double xmax;    /**< extent */
    double ymin;    /**< extent */
    double ymax;    /**< extent */
    int line;       /**< line of the scene text, for messages
                         (scene_lines_at() names its file) */
} Crack;

/** One crossing of a particle-node line with a crack segment. */
typedef struct CrackHit {
    int crack;      /**< which crack */
    int segment;    /**< which segment of it (points segment, segment + 1) */
    int side;       /**< +1: the particle is above it, -1: below */
} CrackHit;

/** Most crossings one particle-node line may have (more stops the run). */
#define CROSSINGS_MAX 64

/** The crossings of one line, in the order a search found them. */
typedef struct Crossings {
    int n;                        /**< how many */
    int lost;                     /**< crossings beyond CROSSINGS_MAX */
    CrackHit hit[CROSSINGS_MAX];  /**< the crossings */
} Crossings;

struct Cracks;

/// [crossing_search]
/** A row of the crossing-search table (run.crack_search): which segments
 *  Task 1 tests for a particle-node line. Every row must give the same
 *  fields; crossings_result() does not depend on the order of visits.
 *  A point's lines to its nodes lie in its grid cell and the
 *  Cracks::reach cells around it, so a search may answer per cell. */
typedef struct CrossingSearch {
    const char *name;    /**< value of run.crack_search */
    /** Test the segments the line from (px, py) to (nx, ny), inside cell
     *  @p cell or Cracks::reach cells around it, may cross with
     *  crossings_test(), in any order. */
    void (*visit)(const struct Cracks *C, int cell, double px, double py,
                  double nx, double ny, Crossings *x);
    /** Bring the search's own data, and Cracks::near_cell if it keeps
     *  one, up to date with the cracks on grid @p g (before the first step
     *  and after the cracks move, Task 7); NULL when it has none.
     *  @return 0, or -1 to stop the run. */
    int (*update)(struct Cracks *C, const Grid *g);
    /** Free the search's own data (Cracks::search_state); NULL when none. */
    void (*release)(struct Cracks *C);
    /** As @c visit, for the lines from (px, py) to the @p n nodes (nx[a],
     *  ny[a]) of one point at once, line a's crossings into x[a], each in
     *  the order @c visit finds them: one call a point instead of one a
     *  pair. NULL: Task 1 calls @c visit line by line. */
    void (*visit_lines)(const struct Cracks *C, int cell, double px, double py,
                        int n, const double *nx, const double *ny, Crossings *x);
} CrossingSearch;
/// [crossing_search]

/** How many later stages may subscribe to Task 1's crossings. */
#define CRACKS_CROSSED_MAX 4

struct Cracks;

/** A later stage's subscriber to the crossings of Task 1 (chapter 4's
 *  crack normals): called for every pair (point @p p, corner @p a) that
 *  Task 1 keys across a crack, after fields_key(), with the crossing that
 *  decided its field and the subscriber's own @p state. @return 0, or -1
 *  to stop the run (Sim::fail filled). */
typedef int (*CrossedHook)(Sim *sim, const struct Cracks *C, int p, int a,
                           const CrackHit *hit, void *state);

/// [cracks_state]
/** Stage 2's state: the cracks and how Task 1 searches them. */
typedef struct Cracks {
    int ncracks;                  /**< number of cracks */
    Crack *crack;                 /**< the cracks */
    int side_shift;               /**< where the side sits in the field key */
    /** Cells around a point's own that its lines to its nodes may cross:
     *  0 with the cell's four nodes (linear), 1 when run.shape reaches
     *  more (a domain at most a cell wide, 3 x 3 nodes: chapter 8). */
    int reach;
    /** Later stages' subscribers to Task 1's crossings, in the order
     *  they subscribed (cracks_on_crossed()); none in stages 2 and 3. */
    struct {
        CrossedHook fn;           /**< the subscriber */
        void *state;              /**< its own state */
    } crossed[CRACKS_CROSSED_MAX];
    int ncrossed;                 /**< how many */
    /** Per point, FieldTable::width at a time: the field of each pair
     *  (0, 1, 2; -1 for too many crossings), found on threads in Task 1
     *  (only the points it lists in @c keyed are read back). */
    signed char *pair_field;
    /** Likewise: the crossing that decided each keyed pair, kept for the
     *  subscribers (NULL while there are none). */
    CrackHit *pair_hit;
    /** Room for a list of points: Task 1 lists the points near a crack
     *  there, in point order, then, in place, those that key a pair. */
    int *keyed;
    /** Per thread (Sim::threads): where its part of @c keyed ends. */
    int *keyed_end;
    const CrossingSearch *search; /**< the scene's crossing search */
    void *search_state;           /**< the search's own data */
    /** Per grid cell (numbered by its lower-left node): negative when no
     *  crack reaches the cell, so that Task 1 skips its points; kept by
     *  the search, NULL when it keeps none (every point is tested). */
    const int *near_cell;
} Cracks;
/// [cracks_state]

/** @brief Stage 2's state of @p sim (NULL when the scene has no crack). */
static inline Cracks *cracks_of(const Sim *sim)
{
    return (Cracks *)sim_state(sim, "cracks");
}

/// [crossing_tests]
/**
 * @brief The crossing test of one segment: does the line from the
 *        particle (px, py) to the node (nx, ny) cross segment @p k of
 *        crack @p c (points k, k + 1)? +1 with the particle above the
 *        segment, -1 below, 0 not crossed (Appendix, eq. 33, subtask 3).
 */
int crack_segment_side(const Crack *c, int k, double px, double py, double nx,
                       double ny);

/**
 * @brief The crossing test against one crack: +1 above, -1 below, 0 not
 *        crossed. An even number of crossings counts as none (subtask 4);
 *        an odd number gives the sign of the sum of their sides, whatever
 *        order the segments are tested in.
 */
int crack_crossing(const Crack *c, double px, double py, double nx, double ny);
/// [crossing_tests]

/** @brief Record a crossing of segment @p k of crack @p crack with @p side
 *         (+1 or -1) in @p x. @return 0, or -1 when @p x is full. */
static inline int crossings_add(Crossings *x, int crack, int k, int side)
{
    if (x->n == CROSSINGS_MAX) {
        x->lost++;
        return -1;
    }
    x->hit[x->n++] = (CrackHit){crack, k, side};
    return 0;
}

/** @brief Test segment @p k of crack @p crack and record a crossing in
 *         @p x. @return 0, or -1 when @p x is full. */
static inline int crossings_test(const Cracks *C, int crack, int k, double px,
                                 double py, double nx, double ny, Crossings *x)
{
    int side = crack_segment_side(&C->crack[crack], k, px, py, nx, ny);
    return side ? crossings_add(x, crack, k, side) : 0;
}

/**
 * @brief The field of a line from its crossings, independent of their
 *        order: the crack of lowest index crossed an odd number of times
 *        decides; its side is the sign of the sum of the sides of its
 *        crossings, and the segment reported is the lowest-numbered one
 *        crossed with that side.
 * @return 0 (no crack crossed), 1 above, 2 below; @p hit filled when not 0.
 */
int crossings_result(const Crossings *x, CrackHit *hit);

/** @brief The field of a line from its crossings @p x, as crack_field()
 *         gives it: -1 when some were lost, 0 when there are none, else
 *         crossings_result() (@p hit, which may be NULL, filled). */
static inline __attribute__((always_inline)) int
crossings_field(const Crossings *x, CrackHit *hit)
{
    CrackHit h;
    if (x->lost)
        return -1;
    return x->n ? crossings_result(x, hit ? hit : &h) : 0;   /* none: field 0 */
}

/**
 * @brief Which field the pair (point, node) belongs to (eq. 2): 0 when
 *        the segment from the point to the node crosses no crack, 1 when
 *        it crosses one with the point above it, 2 below; the scene's
 *        crossing search finds the crossings. The line lies in grid cell
 *        @p cell (the point's; a search that needs no cell takes any). @p hit (may be NULL) gets
 *        the crack, segment and side. -1 when a line crosses more than
 *        CROSSINGS_MAX segments.
 */
static inline __attribute__((always_inline)) int
crack_field(const Cracks *C, int cell, double px, double py,
            double nx, double ny, CrackHit *hit)
{
    Crossings x;
    x.n = x.lost = 0;
    C->search->visit(C, cell, px, py, nx, ny, &x);
    return crossings_field(&x, hit);
}

/** @brief The plain search: every segment of every crack. */
extern const CrossingSearch crossing_plain;

/**
 * @brief Does crack @p c cross or touch itself (two segments that are not
 *        neighbours share a point)? The segments are binned on a grid of
 *        about as many cells as segments, so the check costs about n, not
 *        n^2, for a crack of n segments of similar length.
 * @return 1 with the first such pair (in the order i < j, then j) in *i,
 *         *j; 0 when none; -1 when memory is exhausted.
 */
int crack_self_crossing(const Crack *c, int *i, int *j);

/** @brief Do the closed segments (@p a, @p b) and (@p c, @p d), each
 *         point an {x, y} pair, share a point (cross, or touch)?
 *  @return 1 or 0. */
int crack_segments_meet(const double *a, const double *b, const double *c,
                        const double *d);

/** @brief Make room for @p n points in @p c (freeing any it had).
 *  @return 0, or -1 when memory is exhausted. */
int crack_alloc_points(Crack *c, int n);

/** @brief Make room for @p cap points in @p c, keeping its Crack::n
 *         points (a later stage that adds points reserves at set-up, so
 *         that a step allocates nothing). @return 0, or -1 when memory is
 *         exhausted (the points are kept). */
int crack_reserve_points(Crack *c, int cap);

/**
 * @brief Check a crack's points as the scene gave them under @p key of
 *        setting @p s: inside the grid, no segment of zero length, no
 *        self-crossing; then set its extent. Messages name @p s (or, for
 *        a list of the crack's points, the point's own line).
 * @return 0, or -1 with the message in @p r.
 */
int crack_check_points(struct SceneReader *r, const config_setting_t *s,
                       const char *key, const Scene *sc, Crack *c);

/** @brief Set the extent (Crack::xmin ...) of the crack's points. */
void crack_extent(Crack *c);

/** The keys of a crack of stage 2 (NULL-ended); later stages add keys to
 *  section "cracks". */
extern const char *const crack_keys[];

/** @brief Parse the "cracks" section and subscribe stage 2's hooks. */
int cracks_read(Sim *sim, const config_setting_t *s, int index,
                struct SceneReader *r);

/** @brief Parse run.crack_search, the row of the crossing-search table. */
int cracks_read_search(Sim *sim, const config_setting_t *s, int index,
                       struct SceneReader *r);

/** @brief Task 1: key every pair that crosses a crack with its side. */
int cracks_key_fields(Sim *sim, void *state, Seam seam);

/// [cracks_move]
/**
 * @brief Task 7: move every crack point with the centre-of-mass velocity
 *        of the nodes of its cell (all fields of a node together, eq. 7
 *        and 32), interpolated with the shape functions (eq. 6), and
 *        update each crack's extent.
 * @return 0, or the value of step_fail() for a point that leaves the grid.
 */
int cracks_move(Sim *sim);
/// [cracks_move]

/** @brief Task 7 as a subscriber: move the cracks, then bring the
 *         crossing search up to date. */
int cracks_task7(Sim *sim, void *state, Seam seam);

/** @brief Nodes that carry more than one velocity field this step. */
int cracks_multi_field_nodes(const Sim *sim);

/** @brief Write cracks_NNNNN.vtp and cracks_NNNNN.csv with the snapshot,
 *         and rewrite the series cracks.pvd to list snapshots 0 .. @p index
 *         at their @p times. */
int cracks_snapshot(const Sim *sim, void *state, const char *dir, int index,
                    const double *times);

/** @brief history.csv column: number of multi-field nodes. */
int cracks_history(const Sim *sim, void *state, FILE *f, int header);

/** @brief Set-up: add @p fn (with @p state) to the subscribers of Task
 *         1's crossings (the first gives Cracks::pair_hit its room, for the
 *         points and stencils of @p sim). @return 0, or -1 when
 *         CRACKS_CROSSED_MAX are taken or memory is exhausted. */
int cracks_on_crossed(const Sim *sim, Cracks *C, CrossedHook fn, void *state);

/** @brief Save or restore the cracks' points (SEAM_CHECKPOINT). */
int cracks_checkpoint(Sim *sim, void *state, FILE *f, int save);

/** @brief Check the cracks against the bodies; bring the search up to date. */
int cracks_prepare(Sim *sim, void *state, char *err, size_t errlen);

/** @brief Release stage 2's state. */
void cracks_release(void *state);

#endif
