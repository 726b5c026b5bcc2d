/**
 * @file step.h
 * @brief The pieces of one MPM time step (the paper's Tasks 0-8), each a
 *        loop over points or over grid slots.
 */
#ifndef MPM_STEP_H
#define MPM_STEP_H

#include "shape.h"
#include "sim.h"
#include "stencil.h"

/** extrapolate(): masses and momenta (eq. 26). */
#define EXTRAP_MASS 1u
/** extrapolate(): momenta only, with the stored shape data (eq. 31). */
#define EXTRAP_MOMENTUM 2u
/** extrapolate(): internal and external forces (eq. 28). */
#define EXTRAP_FORCE 4u

/** @brief Task 0: each point's cell and local coordinates for this step. */
void locate_points(Sim *sim);

/** @brief Task 1: the stages key each pair's field (SEAM_TASK1_FIELDS),
 *         the field table gives it a slot. A scene whose stages key
 *         nothing skips it: one field at every node. @return 0 or -1. */
int assign_fields(Sim *sim);

/** @brief The force on each loaded point of @p L at time @p t (the total
 *         force shared by its points, ramped from zero over L->ramp). */
void load_point_force(const Load *L, double t, double *fx, double *fy);

/** @brief Tasks 1 and 3: scatter point data to the grid slots of each pair. */
void extrapolate(Sim *sim, unsigned what);

/** @brief Task 2: boundary conditions on momenta, then v = p / m (eq. 34). */
void grid_velocities(Sim *sim);

/** @brief Tasks 3-4: total forces (eq. 4, 28), fixed directions, p += dt f
 *         (eq. 29), and the velocities and accelerations Task 5 reads. */
void grid_momentum_update(Sim *sim);

/**
 * @brief The contact contract: run the subscribers of contact seam @p seam
 *        (Task 2, 4 or 6), which change nodal momenta only (with a field
 *        table, only at the nodes it gave several fields: contact is
 *        between two fields), then derive again what later tasks read
 *        there: fixed directions, v = p / m, and at Task 4 the force
 *        f += (p - p_before) / dt and a = f / m.
 * @return 0, or non-zero when a subscriber stopped the run.
 */
int grid_contact(Sim *sim, Seam seam);

/**
 * @brief Hold the nodes of moving boundaries at their prescribed velocity
 *        (every field of the node), after the grid task of @p seam and its
 *        contact: at Task 2 the velocity of time t, at Tasks 4 and 6 that
 *        of t + dt, and at Task 4 the force m dv/dt that gets there.
 *        Nothing when the scene prescribes none.
 */
void grid_prescribe(Sim *sim, Seam seam);

/** @brief Task 5: point velocities and positions (eq. 30); 0 or -1 on
 *         instability (Sim::fail filled). */
int update_points(Sim *sim);

/** @brief Stress and strain from the nodal velocities (eq. 34-36) over
 *         dt_star; 0 or -1 on a non-finite stress (Sim::fail filled). */
int update_stress(Sim *sim, double dt_star);

/// [elastic_stress_increment]
/**
 * @brief Elastic stress increment of Hooke's law in the plane (chapter 1,
 *        exercise "Hooke's law" replaces this function's file).
 * @param mat  material with its plane stiffnesses prepared
 * @param dexx strain increment xx
 * @param deyy strain increment yy
 * @param dexy tensor shear strain increment xy
 * @param s    in/out: stress xx, yy, xy
 */
void elastic_stress_increment(const Material *mat, double dexx, double deyy,
                              double dexy, double s[3]);
/// [elastic_stress_increment]

/** @brief Record an instability of this step in Sim::fail: of several in
 *         one loop, the one of the lowest point index is kept, whatever
 *         order the loop ran in. @return -1. */
int step_fail(Sim *sim, int p, const char *quantity, double value);

/** @brief Record in Sim::fail that a rule, not an instability, ends the
 *         run at this step (a crack out of room to grow, a tip meeting
 *         another crack): as step_fail(), with Failure::stop set, so that
 *         the run says "stopped" with the reason. @return -1. */
int step_stop(Sim *sim, int p, const char *reason, double value);

#endif
