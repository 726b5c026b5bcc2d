/**
 * @file scene.h
 * @brief What a scene file describes: grid, run settings, materials,
 *        bodies, grid boundary conditions and point loads.
 *
 * Units throughout: length mm, mass g, time ms; hence force N, stress MPa,
 * velocity m/s (= mm/ms), energy mJ and density g/mm^3.
 */
#ifndef MPM_SCENE_H
#define MPM_SCENE_H

#include "material.h"
#include "scene_include.h"
#include "units.h"

struct Sim;
struct Stencil;
struct ShapeFunctions;
struct Transfer;

/** Kind of region a body fills. */
typedef enum { SHAPE_RECTANGLE, SHAPE_DISK, SHAPE_POLYGON } ShapeKind;

/** A region of the plane: rectangle, disk or annulus, or polygon. */
typedef struct Shape {
    ShapeKind kind;  /**< which of the fields below apply */
    double xmin;     /**< bounding box, all kinds */
    double ymin;     /**< bounding box, all kinds */
    double xmax;     /**< bounding box, all kinds */
    double ymax;     /**< bounding box, all kinds */
    double cx;       /**< disk: centre x */
    double cy;       /**< disk: centre y */
    double r;        /**< disk: outer radius */
    double rin;      /**< disk: inner radius (annulus), 0 for a full disk */
    int nv;          /**< polygon: number of vertices */
    double *v;       /**< polygon: vertices x0, y0, x1, y1, ... */
} Shape;

/** One body: a shape filled with material points of one material. */
typedef struct Body {
    char name[64];     /**< name, used in history.csv columns */
    int material;      /**< index into Scene::mat */
    double thickness;  /**< out-of-plane thickness (default 1 mm in the
                            scene's units) */
    double vx;         /**< initial velocity x (at Body::cx, Body::cy) */
    double vy;         /**< initial velocity y (at Body::cx, Body::cy) */
    double L[4];       /**< initial velocity gradient: v = (vx, vy) +
                            [L0 L1; L2 L3] (x - cx, y - cy); an angular
                            velocity w adds [0 -w; w 0] */
    double cx;         /**< centre of the velocity field x */
    double cy;         /**< centre of the velocity field y */
    double stress[3];  /**< initial stress xx, yy, xy (MPa) */
    int ppc;           /**< k: k x k points per cell */
    Shape shape;       /**< region filled */
    int line;          /**< line of the scene text, for messages
                            (scene_lines_at() names its file) */
} Body;

/** A velocity held along x and/or y: constant, ramped in from zero, or
 *  a table in time. */
typedef struct Hold {
    unsigned fix;      /**< GRID_FIX_X | GRID_FIX_Y: the directions held */
    double vx;         /**< velocity held along x (if held in x) */
    double vy;         /**< velocity held along y (if held in y) */
    double ramp;       /**< time to reach full velocity; 0 = at once */
    int nrows;         /**< rows of the table; 0: no table */
    double *table;     /**< t, vx, vy per row, t increasing: linear between
                            rows, the first and last row's values outside */
} Hold;

/** Nodes inside a box whose velocity is held along x and/or y: at zero,
 *  or at a prescribed velocity. */
typedef struct Boundary {
    Shape region;      /**< rectangle: nodes in it (edges included) are held */
    Hold hold;         /**< the directions and the velocity */
    int moving;        /**< a velocity other than zero is prescribed */
    int line;          /**< line of the scene text, for messages
                            (scene_lines_at() names its file) */
} Boundary;

/** A force shared equally by the points inside a box. */
typedef struct Load {
    Shape region;      /**< rectangle selecting the loaded points */
    double fx;         /**< total force x (N) */
    double fy;         /**< total force y (N) */
    double ramp;       /**< time to reach full force (ms); 0 = constant */
    int count;         /**< number of points loaded */
    int *points;       /**< their indices */
    int line;          /**< line of the scene text, for messages
                            (scene_lines_at() names its file) */
} Load;

/** Points inside a box whose velocity is prescribed along x and/or y,
 *  ramped in from zero: the nodes they reach are held at it. */
typedef struct HeldPoints {
    Shape region;      /**< rectangle selecting the points at t = 0 */
    Hold hold;         /**< the directions and the velocity */
    int count;         /**< number of points held */
    int *points;       /**< their indices */
    int line;          /**< line of the scene text, for messages
                            (scene_lines_at() names its file) */
} HeldPoints;

/// [update_scheme]
/** A stress-update scheme: where in the step the stress is updated. */
typedef struct UpdateScheme {
    const char *name;   /**< name in the scene file (run.update) */
    double before;      /**< fraction of dt applied in Task 2 (USF-like) */
    double after;       /**< fraction of dt applied in Task 6 */
    int reextrapolate;  /**< Task 6c: re-extrapolate new velocities first */
} UpdateScheme;
/// [update_scheme]

/** Settings of the time integration and output. */
typedef struct RunSettings {
    double time;        /**< simulated time (ms) */
    double cfl;         /**< time step factor on the stable step */
    int allow_cfl_above_one; /**< the scene insists on cfl > 1 */
    double damping;     /**< kappa of eq. 4 (1/ms) */
    PlaneKind plane;    /**< plane stress or plane strain */
    double gx;          /**< body force per unit mass x (mm/ms^2) */
    double gy;          /**< body force per unit mass y (mm/ms^2) */
    double gravity_ramp; /**< time over which gravity grows linearly from
                              zero (ms; 0: all of it from the start) */
    const UpdateScheme *scheme; /**< stress-update scheme */
    const struct Method *method; /**< how a step is taken (run.method) */
    int snapshots;      /**< number of particle/grid snapshots after t = 0 */
    int history_every;  /**< steps between history rows (0 = automatic) */
    double energy_limit; /**< a run whose energy passes this many times
                              the energy put in stops as unstable (0:
                              never; energy_guard.h) */
    long checkpoint_every; /**< steps between checkpoints (0: only when a
                                run stops before its end) */
    const Units *units; /**< the scene's unit system (run.units) */
    int full_precision; /**< write 17 significant digits (run.precision =
                             "full"); 0: the usual 9 to 12 */
    int binary;         /**< snapshots and the final points as binary .vtu
                             (run.output = "binary"); 0: text ("ascii") */
    int threads;        /**< run.threads; 0: not given (OMP_NUM_THREADS,
                             or every core) */
    int objective;      /**< rotate stress and strain by each increment's
                             spin (run.stress_rate = "jaumann"); 0: the
                             paper's eq. 35-36, unrotated */
    const struct ShapeFunctions *shape; /**< the shape functions (run.shape,
                             a row of shape.h's table; NULL: linear) */
    /** The stencil function of run.shape, NULL for the paper's bilinear
     *  functions (computed inline by stencil_of_point()). */
    void (*stencil)(const struct Sim *sim, int p, struct Stencil *st);
    /** The transfer of run.transfer (chapter 8), NULL for the paper's
     *  (eq. 26 and 30); it runs through RunSettings::stencil. */
    const struct Transfer *transfer;
} RunSettings;

/** @brief The fraction of run.gravity acting at time @p t: t / ramp during
 *         the ramp, else exactly 1. */
static inline double gravity_scale(const RunSettings *run, double t)
{
    return t < run->gravity_ramp ? t / run->gravity_ramp : 1.0;
}

/** A complete scene. */
typedef struct Scene {
    const char *file;   /**< scene file name, for messages (the caller's
                             string, as given to sim_load_file()) */
    SceneLines *lines;  /**< where each line of the scene's text (with its
                             @@include files) came from: the lines kept
                             below (Body::line, ...) are lines of that
                             text; scene_lines_at() names them */
    double ox;          /**< grid origin x */
    double oy;          /**< grid origin y */
    double dx;          /**< cell width */
    double dy;          /**< cell height */
    int ncx;            /**< cells along x */
    int ncy;            /**< cells along y */
    RunSettings run;    /**< time integration and output */
    int nmat;           /**< number of materials */
    Material *mat;      /**< materials */
    int nbodies;        /**< number of bodies */
    Body *bodies;       /**< bodies */
    int nbc;            /**< number of boundary regions */
    Boundary *bc;       /**< grid boundary conditions */
    int nloads;         /**< number of point loads */
    Load *loads;        /**< point loads */
    int nheld;          /**< number of point_velocities entries */
    HeldPoints *held;   /**< points whose velocity is prescribed */
} Scene;

/** @brief The share of a load or prescribed velocity reached at time @p t
 *         when it is ramped in linearly over @p ramp (0: all at once). */
static inline double ramp_factor(double ramp, double t)
{
    return (ramp > 0.0 && t < ramp) ? t / ramp : 1.0;
}

/** @brief The velocity @p h holds at time @p t. */
static inline void hold_velocity(const Hold *h, double t, double v[2])
{
    const double *r = h->table;
    if (h->nrows == 0) {
        v[0] = ramp_factor(h->ramp, t) * h->vx;
        v[1] = ramp_factor(h->ramp, t) * h->vy;
        return;
    }
    int k = 0;                                 /* the row at or before t */
    while (k + 1 < h->nrows && r[3 * (k + 1)] <= t)
        k++;
    double w = 0.0;
    if (k + 1 < h->nrows && t > r[3 * k])
        w = (t - r[3 * k]) / (r[3 * (k + 1)] - r[3 * k]);
    const double *a = r + 3 * k, *b = k + 1 < h->nrows ? a + 3 : a;
    v[0] = (1.0 - w) * a[1] + w * b[1];
    v[1] = (1.0 - w) * a[2] + w * b[2];
}

/** @brief Release what the scene allocated. */
void scene_free(Scene *sc);

/** @brief Is (x, y) inside @p s (edges included)? */
int shape_contains(const Shape *s, double x, double y);

#endif
