/**
 * @file contact_decision.h
 * @brief The step's contact decision, kept per node: which pairs of fields
 *        Task 4 found in contact, and at which step. Task 6 keeps that
 *        decision; the next step's stress update (USF, USAVG) starts from
 *        it where the law still finds contact. Shared by crack contact
 *        and contact between bodies.
 */
#ifndef CONTACT_DECISION_H
#define CONTACT_DECISION_H

#include <stdio.h>


/** @brief Per node: bit k of @c pairs set when the node's k-th pair of
 *         fields was in contact at Task 4 of step @c step. */
typedef struct ContactDecision {
    unsigned *pairs;      /**< per node: the pairs in contact */
    long *step;           /**< per node: the step that decided (-1: none) */
    int nnodes;           /**< nodes of the grid */
} ContactDecision;

/** @brief Allocate for @p nnodes nodes, none decided. @return 0 or -1. */
int contact_decision_alloc(ContactDecision *d, int nnodes);

/** @brief Free what contact_decision_alloc() took. */
void contact_decision_free(ContactDecision *d);

/** @brief Task 4 of step @p step at @p node: forget the last decision. */
static inline void contact_decision_begin(ContactDecision *d, int node, long step)
{
    d->pairs[node] = 0;
    d->step[node] = step;
}

/** @brief Task 4: the pair @p bit of @p node is in contact. */
static inline void contact_decision_hold(ContactDecision *d, int node, unsigned bit)
{
    d->pairs[node] |= bit;
}

/** @brief Was the pair @p bit of @p node in contact at Task 4 of step
 *         @p step? (Task 6 asks for this step, Task 2 for the last.) */
static inline int contact_decision_held(const ContactDecision *d, int node,
                                        unsigned bit, long step)
{
    return d->step[node] == step && (d->pairs[node] & bit);
}

/** @brief Save (@p save 1) or restore the decision, so that a restart
 *         starts its first step from it. @return 0 or -1. */
int contact_decision_checkpoint(ContactDecision *d, FILE *f, int save);

#endif
