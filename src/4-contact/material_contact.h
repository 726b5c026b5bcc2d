/**
 * @file material_contact.h
 * @brief Contact between bodies (Bardenhagen et al., CMES 2001, as the
 *        paper's Fig. 4 uses it): each contact group gets its own velocity
 *        field at the nodes where groups meet, and a contact law adjusts
 *        the momenta of two groups' fields there at Tasks 2, 4 and 6.
 *
 * A body's contact group is its material's name, or the name its
 * contact_group key gives. The scene's "contact" section lists pairs of
 * groups with a law; only the groups it names get fields of their own.
 * Groups no pair names share field 0, and two groups that meet with no
 * pair between them are bonded: they move as one field would.
 */
#ifndef MPM_MATERIAL_CONTACT_H
#define MPM_MATERIAL_CONTACT_H

#include <stdio.h>

#include "contact_decision.h"
#include "contact_settings.h"
#include "sim.h"

struct SceneReader;

/** Candidate directions of an interface at a node: the outward normal
 *  of its field of largest area, the inward normal of the next, and their
 *  average (contact_interface_normal()), or, with contact.normal =
 *  "regression", the normal of the line fitted between the two fields'
 *  points in its place (contact_regression.h). */
#define CONTACT_AXES 3

/** Most contact groups a scene may name in its pairs (the group's part of
 *  the field key is 5 bits; group 0 is every group no pair names). */
#define CONTACT_GROUPS_MAX 31

/** The normal of two bodies at a node (the pairs' contact.normal). */
typedef enum ContactNormal {
    NORMAL_GRADIENTS,     /**< the candidates from the mass gradients */
    NORMAL_REGRESSION     /**< the line fitted between the two clouds of
                               points (contact_regression.h) */
} ContactNormal;

/// [material_contact_state]
/** Stage 4's state for contact between bodies. */
typedef struct MaterialContact {
    int ngroups;          /**< groups named by pairs: indices 1 .. ngroups */
    char (*name)[64];     /**< per group index (0: "the others") */
    char (*body_group)[64]; /**< per body: its contact_group, "" for none */
    int nbody_group;      /**< entries of body_group */
    int *group_of_body;   /**< per body: its group index (0: no pair) */
    ContactLaw *law;      /**< (ngroups + 1)^2: law of groups i, j */
    int shift;            /**< the group's lowest bit in the field key */
    unsigned group_mask;  /**< the group's bits, shifted down */
    unsigned side_mask;   /**< the crack side's bits of the key (0: none) */
    unsigned *cell_groups; /**< per cell (by its lower-left node): bit g
                               set when a point of group g is in it */
    unsigned char *mixed; /**< per node: points of several groups reach it */
    unsigned char *mixed_cell; /**< per cell (by its lower-left node): a
                               corner is mixed (linear stencils) */
    unsigned char *near;  /**< per cell: a corner has several fields */
    unsigned char *keyed; /**< per point: bit a set when Task 1 keys its
                               corner a with its group (found on threads,
                               keyed on one in point order) */
    int *keyed_list;      /**< per point: the points that key a corner,
                               each thread's share of the points listing
                               its own from the share's first index on */
    int *keyed_end;       /**< per thread (Sim::threads): one past its
                               last entry in keyed_list */
    int *near_list;       /**< 2 per point: the points near a node with
                               several fields, strip by strip (Task 2) */
    int *near_end;        /**< per strip (one on one thread): one past its
                               last entry in near_list */
    double *node_work;    /**< per touched node (FieldTable::touched
                               order): the work of its pairs at Task 4,
                               added to @c work in node order */
    double *gx;           /**< per slot: mass gradient x (at nodes with
                               several fields) */
    double *gy;           /**< per slot: mass gradient y */
    double *va;           /**< per slot: area sum_p A_p S_ip (A_p: the
                               point's current volume / thickness) */
    double *lo;           /**< per slot, CONTACT_AXES at a time: lowest
                               reach of its points along each candidate
                               direction (x_p . c - r_p) */
    double *hi;           /**< per slot, likewise: highest reach */
    double *cx;           /**< per node, CONTACT_AXES at a time: the
                               candidate directions c, x */
    double *cy;           /**< per node: the candidates, y */
    double *area;         /**< per node: sum over its fields of va */
    int reach;            /**< a pair detects by a gap: the candidates and
                               reaches are found (else the normal is
                               contact_interface_normal()'s) */
    ContactNormal normal; /**< the scene's normal (one for all pairs) */
    int normal_line;      /**< line of the first pair's normal (0: none) */
    double *fit;          /**< NORMAL_REGRESSION: per node,
                               REGRESSION_DOUBLES: the fit and its sums */
    int *fit_pair;        /**< NORMAL_REGRESSION: per node, the slots of
                               the two fields fitted (labels 0 and 1) */
    ContactDecision decision; /**< the pairs in contact at Task 4 */
    long geometry_step;   /**< the step whose geometry is found (-1: none) */
    int cap;              /**< slots of gx, gy, va, lo, hi */
    int nodes;            /**< nodes in contact at this step's decision (Task 4) */
    int task_nodes;       /**< nodes adjusted at the current task */
    double work;          /**< work done by material contact (mJ) */
} MaterialContact;
/// [material_contact_state]

/** @brief Read bodies.[index].contact_group (a name). */
int material_group_read(Sim *sim, const config_setting_t *s, int index,
                        struct SceneReader *r);

/** The keys of an entry of the "contact" section (NULL-ended). */
extern const char *const material_contact_keys[];

/** @brief Read the "contact" section (pairs of groups and their laws) and
 *         subscribe stage 4's material-contact hooks. */
int material_contact_read(Sim *sim, const config_setting_t *s, int index,
                          struct SceneReader *r);

/** @brief The law between groups @p i and @p j. */
static inline const ContactLaw *material_law(const MaterialContact *M, int i,
                                             int j)
{
    return &M->law[i * (M->ngroups + 1) + j];
}

/** @brief Set-up: the field table, per-node arrays, the crack side's
 *         bits. */
int material_contact_prepare(Sim *sim, void *state, char *err, size_t errlen);

/**
 * @brief Task 1: at every node that points of more than one group reach,
 *        key each pair with its point's group, so that each group
 *        extrapolates to its own field there (inside its crack field when
 *        a crack is there too). A node one group reaches keeps one field.
 */
int material_key_fields(Sim *sim, void *state, Seam seam);

/**
 * @brief Tasks 2, 4 and 6: at every node where two groups' fields (on the
 *        same side of any crack) have mass, find the normal from their
 *        mass gradients, detect contact and adjust their momenta by the
 *        pair's law.
 */
int material_contact_task(Sim *sim, void *state, Seam seam);

/** @brief history.csv columns material_contact_nodes and
 *         material_contact_work. */
int material_contact_history(const Sim *sim, void *state, FILE *f, int header);

/** @brief SEAM_ENERGY: the energy contact between bodies has dissipated
 *         (friction), named "contact between bodies". */
double material_contact_energy(const Sim *sim, void *state, const char **name);

/** @brief Save or restore the contact's work and node count
 *         (SEAM_CHECKPOINT). */
int material_contact_checkpoint(Sim *sim, void *state, FILE *f, int save);

/** @brief Release the state. */
void material_contact_release(void *state);

#endif
