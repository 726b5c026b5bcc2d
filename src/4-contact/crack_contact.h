/**
 * @file crack_contact.h
 * @brief Crack-surface contact (section 2.2): per-crack settings read from
 *        the scene, and the adjustment of nodal momenta at Tasks 2, 4 and 6
 *        wherever the two sides of a crack meet at a node.
 */
#ifndef MPM_CRACK_CONTACT_H
#define MPM_CRACK_CONTACT_H

#include "contact_decision.h"
#include "contact_settings.h"
#include "crack_normals.h"
#include "cracks.h"

/// [crack_contact_settings]
/** Contact settings of one crack (scene: cracks.[k].contact). */
typedef struct CrackContact {
    ContactLaw law;      /**< kind CONTACT_NONE: the crack has no contact */
    double vcell;        /**< undeformed cell volume dx dy t (eq. 10) */
    int line;            /**< line of the settings in the scene text
                              (scene_lines_at() names its file) */
} CrackContact;
/// [crack_contact_settings]

/** Stage 4's state for crack contact: the settings and the statistics. */
typedef struct ContactState {
    int ncracks;          /**< entries of crack */
    CrackContact *crack;  /**< per crack */
    CrackNormals normals; /**< the crack's normal per extra slot (Task 1) */
    double *vnode;        /**< per node: volume V_i (eq. 8), at touched nodes */
    int opening;          /**< a crack detects by its opening: x0, y0, ux,
                               uy are kept */
    double *x0;           /**< per point: its position at the start */
    double *y0;           /**< per point: y at the start */
    double *ux;           /**< per slot: sum_p m_p S_ip u_p, x (u_p = x_p -
                               x0_p, at touched nodes) */
    double *uy;           /**< per slot: the same, y */
    int cap;              /**< slots of ux, uy */
    ContactDecision decision; /**< the pairs in contact at Task 4 */
    long volumes_step;    /**< the step whose normals and node volumes are
                               found (-1: none) */
    double *node_work;    /**< per touched node (FieldTable::touched
                               order): the work of its pairs at Task 4,
                               added to @c work in node order */
    int nodes;            /**< nodes in contact at this step's decision (Task 4) */
    int task_nodes;       /**< nodes adjusted at the current task */
    double work;          /**< work done by contact since the start (mJ) */
} ContactState;

/** The keys of cracks.[index].contact (NULL-ended). */
extern const char *const crack_contact_keys[];

/** @brief Parse cracks.[index].contact and subscribe stage 4's hooks. */
int crack_contact_read(Sim *sim, const config_setting_t *s, int index,
                       struct SceneReader *r);

/** @brief Subscribe the crack normals to stage 2's crossings; room for
 *         them and for nodal volumes; cell volumes per crack. */
int crack_contact_prepare(Sim *sim, void *state, char *err, size_t errlen);

/**
 * @brief Tasks 2, 4 and 6: at every node where the two sides of a crack
 *        with contact both have mass, detect contact (eq. 10-12) and
 *        adjust the momenta (eq. 13-19). Only nodes the field table gave
 *        extra fields are visited.
 */
int crack_contact_task(Sim *sim, void *state, Seam seam);

/** @brief history.csv columns contact_nodes and contact_work. */
int crack_contact_history(const Sim *sim, void *state, FILE *f, int header);

/** @brief SEAM_ENERGY: the energy crack contact has dissipated (friction),
 *         named "crack contact". */
double crack_contact_energy(const Sim *sim, void *state, const char **name);

/** @brief Save or restore the contact's work and node count, and the
 *         points' start positions of the opening rule (SEAM_CHECKPOINT). */
int crack_contact_checkpoint(Sim *sim, void *state, FILE *f, int save);

/** @brief Release stage 4's crack-contact state. */
void crack_contact_release(void *state);

#endif
