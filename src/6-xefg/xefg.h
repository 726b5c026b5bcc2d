/**
 * @file xefg.h
 * @brief The XEFG discretisation of a scene (Rabczuk and Zi, eq. 1-2 and
 *        31-32): the material points are the EFG nodes, each carries a
 *        standard vector parameter and, near a crack, step or branch
 *        parameters; background cells (each point's own square) carry the
 *        Gauss points, with the shape functions stored once (a stationary
 *        crack, total Lagrangian small strain).
 */
#ifndef MPM_XEFG_H
#define MPM_XEFG_H

#include <stdio.h>

#include "branch.h"
#include "cell_list.h"
#include "crack_line.h"
#include "sim.h"

struct Cohesive;
struct Growth;
struct XefgGather;

/** The scene's `xefg` section. */
typedef struct XefgSettings {
    double support;   /**< support radius over point spacing, d / h (2) */
    int gauss;        /**< Gauss points per direction in a cell (4) */
    BranchKind tip;   /**< branch functions at tips (cohesive, eq. 6) */
    double m;         /**< exponent m of eq. 6 (1) */
    int line;         /**< line of the section, for messages (0: absent) */
} XefgSettings;

/** What a parameter multiplies Phi_I by: 1, H or a branch function. */
enum { DOF_STANDARD = 0, DOF_STEP = 1, DOF_BRANCH = 2 };

/** Shape functions of some parameters at one place: dof[k] with value
 *  N[k] and gradient (Nx[k], Ny[k]), k in [start[i], start[i + 1]). */
typedef struct ShapeRows {
    int n;          /**< places */
    int *start;     /**< n + 1 offsets */
    int *dof;       /**< parameter of each entry */
    double *N;      /**< its shape function */
    double *Nx;     /**< d/dx (NULL for rows without gradients) */
    double *Ny;     /**< d/dy */
    int len;        /**< entries used */
    int cap;        /**< entries allocated */
    int ncap;       /**< rows allocated (start holds ncap + 1) */
} ShapeRows;

/** The velocity constraints of one direction (eq. 22: essential
 *  conditions by Lagrange multipliers, on velocities). */
typedef struct Constraints {
    int n;          /**< constrained places */
    int *node;      /**< the node each holds */
    const Hold **hold; /**< the scene's hold of each */
    ShapeRows rows; /**< G: the shape functions at each place */
    double *S;      /**< G M^-1 G^T, factored: its lower Cholesky factor,
                         column-major (n x n) */
    double *r;      /**< scratch: residual and multipliers (n) */
} Constraints;

/** The discretisation and its state. */
typedef struct Xefg {
    XefgSettings set;   /**< the scene's settings */
    int nnode;          /**< nodes: the scene's material points */
    double *X;          /**< reference position x of each node */
    double *Y;          /**< reference position y */
    double *d;          /**< support radius */
    double *hx;         /**< half width of the node's cell (its square) */
    double *hy;         /**< half height */
    int ncrack;         /**< cracks (stage 2's, seen as lines) */
    CrackLine *crack;   /**< their lines */
    int ndof;           /**< vector parameters */
    int *node_dof;      /**< parameters of node I: node_dof[I] (standard),
                             then its enriched ones, up to node_dof[I + 1] */
    int *dof_node;      /**< node of each parameter */
    int *dof_kind;      /**< DOF_STANDARD, DOF_STEP or DOF_BRANCH + k */
    int *dof_crack;     /**< crack of an enriched parameter (-1: none) */
    int *dof_end;       /**< tip end (0 or 1) of a branch parameter */
    double *dof_frame;  /**< the tip of a branch parameter, fixed when the
                             parameter is made: tip x, y and unit direction
                             (4 per parameter; a crack that grows leaves
                             its old parameters their old tips) */
    int *dof_line;      /**< the part of its crack an enriched parameter
                             knows: its first point and how many (2 per
                             parameter); the whole line when it is made,
                             so that a crack that grows later changes no
                             parameter's function */
    int nstep;          /**< step (Heaviside) parameters */
    int nbranch;        /**< branch parameters */
    double *mass;       /**< lumped mass of each parameter (section 2.5) */
    double *load;       /**< int rho psi dV of each (gravity) */
    double *u;          /**< parameters' displacements (2 per) */
    double *v;          /**< their velocities (2 per) */
    double *a;          /**< their accelerations without damping (2 per) */
    double *f;          /**< scratch: increments (2 per) */
    int ngauss;         /**< Gauss points */
    double *gw;         /**< weight: area x thickness */
    double *gx;         /**< position x */
    double *gy;         /**< position y */
    int *gnode;         /**< the node whose cell holds it */
    double *gs;         /**< stress xx, yy, xy (3 per) */
    double *ge;         /**< strain xx, yy, tensor xy (3 per) */
    ShapeRows gauss;    /**< shape functions and gradients at Gauss points */
    ShapeRows at_node;  /**< shape functions at the nodes (output, loads) */
    double *cell_w;     /**< total Gauss weight of each node's cell */
    Constraints fix[2]; /**< held x and held y */
    double stable_step; /**< critical step 2 / omega_max (power iteration) */
    double omega_max;   /**< its highest frequency estimate */
    int power_iterations; /**< iterations it took */
    struct Cohesive *coh; /**< cohesive cracks (cohesive.h; NULL: none) */
    struct Growth *grow;  /**< cracks that grow (growth.h; NULL: none) */
    long rows_version;  /**< counts the changes of the Gauss rows */
    struct XefgGather *gather; /**< the rows by parameter, for threads
                                    (xefg_gather.h; NULL: one thread) */
    double w_held;      /**< work of the held places so far (counted when
                             a crack is cohesive) */
    double w_damped;    /**< work the damping (run.damping) took out so
                             far: the half kicks' exact share */
    double e0;          /**< kinetic + strain energy at the start */
} Xefg;

/** @brief The XEFG state of @p sim (NULL when the method is not xefg). */
static inline Xefg *xefg_of(const Sim *sim)
{
    return (Xefg *)sim_state(sim, "xefg");
}

/**
 * @brief Build the discretisation of a loaded scene: nodes, enrichment,
 *        parameters, Gauss points and their shape functions, lumped
 *        masses, constraints and the stable step.
 * @return 0, or -1 with a message naming the file and line in @p err.
 */
int xefg_build(Xefg *x, const Sim *sim, char *err, size_t errlen);

/** @brief Release what xefg_build() allocated. */
void xefg_free(Xefg *x);

/**
 * @brief The shape functions of every parameter whose function is not zero
 *        at (px, py), a place of body @p body, appended as one row to @p R
 *        (with gradients when @p grad = 1). A place on a crack counts as
 *        on its left (+1) side.
 * @return 0; -1 when too few nodes' supports hold the place for the linear
 *         basis; -2 out of memory; -3 when more than 512 do.
 */
int xefg_shape_row(const Xefg *x, const CellList *cl, const int *body_of,
                   int body, double px, double py, int grad, ShapeRows *R);

/**
 * @brief The enrichment E of parameter @p q at (px, py), H (eq. 3) or its
 *        branch function (eq. 5-6), and its gradient (0 for H off the
 *        crack); a place on the crack counts as on its left side.
 */
void xefg_enrichment(const Xefg *x, int q, double px, double py, double *E,
                     double *Ex, double *Ey);

/**
 * @brief Internal forces f = int B^T sigma dV (eq. 30) of the Gauss points'
 *        stresses @p gs into @p f (2 per parameter).
 */
void xefg_internal_force(const Xefg *x, const double *gs, double *f);

/**
 * @brief Strain increments at the Gauss points from parameter increments
 *        @p du (2 per parameter), then stress increments by each point's
 *        material law into @p gs, strains into @p ge (NULL: not kept).
 */
void xefg_strain_update(const Xefg *x, const Sim *sim, const double *du,
                        double *gs, double *ge);

/**
 * @brief xefg_strain_update() and then xefg_internal_force() of the new
 *        stresses into @p f, in one pass over the Gauss points (each row
 *        read once a step).
 */
void xefg_update_and_force(const Xefg *x, const Sim *sim, const double *du,
                           double *f);

/**
 * @brief The highest frequency of M^-1 K by power iteration (section 2.5)
 *        and the critical step 2 / omega_max. @return 0, or -1 when it did
 *        not give a finite positive frequency or memory ran out.
 */
int xefg_power_iteration(Xefg *x, const Sim *sim);

/** @brief xefg_power_iteration() in the caller's room: @p z and @p kz of
 *         2 per parameter, @p gs of 3 per Gauss point (no allocation). */
int xefg_power_iteration_in(Xefg *x, const Sim *sim, double *z, double *kz,
                            double *gs);

/** @brief Set up the velocity constraints (boundaries and held points).
 *  @return 0, or -1 with a message. */
int xefg_constraints_build(Xefg *x, const Sim *sim, const CellList *cl,
                           const int *body_of, char *err, size_t errlen);

/** @brief S = G M^-1 G^T of @p c (column-major) and its lower Cholesky
 *         factor in place, as xefg_constraints_apply() solves with it; at
 *         set-up and after a growth event. @p w: x->ndof doubles of
 *         scratch, zero on entry and on return. @return 0, or -1 when S
 *         is not positive definite (dependent constraints). */
int xefg_constraints_factor(const Xefg *x, Constraints *c, double *w);

/** @brief Project the velocities onto the constraints at time @p t:
 *         v -= M^-1 G^T (G M^-1 G^T)^-1 (G v - vbar). */
void xefg_constraints_apply(Xefg *x, double t);

/** @brief One explicit central-difference step (section 2.5): the "xefg"
 *         row of the method table. @return 0, or -1 (Sim::fail filled). */
int xefg_step(Sim *sim);

/** @brief The accelerations a = M^-1 (f_ext(@p t) - f_int) from the
 *         Gauss points' stresses (before damping), into Xefg::a. */
void xefg_accelerations(Xefg *x, const Sim *sim, double t);

/** @brief As xefg_accelerations() with f_int already in Xefg::a. */
void xefg_accelerations_from(Xefg *x, const Sim *sim, double t);

/** @brief The material points' positions, velocities, stresses and strains
 *         from the parameters (for outputs and history). */
void xefg_to_points(const Xefg *x, Sim *sim);

/** @brief Kinetic energy 1/2 v^T M v of the parameters (mJ). */
double xefg_kinetic_energy(const Xefg *x);

/** @brief Strain energy of the Gauss points (mJ). */
double xefg_strain_energy(const Xefg *x, const Sim *sim);

/** @brief The part of its crack enriched parameter @p q knows
 *         (Xefg::dof_line), as a line of its own. */
static inline CrackLine xefg_line_of(const Xefg *x, int q)
{
    CrackLine c = x->crack[x->dof_crack[q]];
    c.x += x->dof_line[2 * q];
    c.y += x->dof_line[2 * q];
    c.n = x->dof_line[2 * q + 1];
    return c;
}

/** @brief Append one row to @p R of @p n entries (grown as needed): the
 *         entries are then written at R->start[R->n - 1] ...
 *  @return 0, or -1 out of memory. */
int shape_rows_add(ShapeRows *R, int n, int grad);

/** @brief Grow the array *@p p of entries of @p size bytes to @p cap
 *         entries (set-up only). @return 0, or -1 (*p kept) out of memory. */
int xefg_grow(void **p, size_t size, int cap);

/** @brief Release the rows. */
void shape_rows_free(ShapeRows *R);

#endif
