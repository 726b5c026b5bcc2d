/**
 * @file contact_regression.h
 * @brief The contact normal of two bodies at a node by logistic regression
 *        of their two clouds of points (Nairn, Hammerquist and Smith,
 *        CMAME 362 (2020) 112859, section 3): the line that best separates
 *        them, fitted by Newton steps on sums that one pass over the points
 *        builds.
 *
 * A point at x_p of the node's first field has the label 0, one of its
 * second field 1. With xi = ((x_p - x_i) / h, 1), the model is
 * P(1 | x_p) = sigma(w . xi), and w minimises the weighted, regularised
 * cross-entropy
 *   L(w) = sum_p S_ip [-y_p log sigma - (1 - y_p) log(1 - sigma)]
 *          + REGRESSION_LAMBDA / 2 (sum_p S_ip) (w_0^2 + w_1^2),
 * which is convex, so Newton's steps converge from w = 0. The normal from
 * the first field to the second is (w_0, w_1) / |(w_0, w_1)|.
 */
#ifndef MPM_CONTACT_REGRESSION_H
#define MPM_CONTACT_REGRESSION_H

/** Newton steps per contact step, each one pass over the points near the
 *  contact nodes, from w = 0 (test_contact_regression: the last one moves
 *  the normal by under 1e-5 of |w| on a body's corners). */
#define REGRESSION_NEWTON 6

/** The regularisation of (w_0, w_1) per unit weight (the offset w_2 gets
 *  1e-6 of it, only to keep the step defined): it keeps |w| finite for two
 *  clouds a line separates (there the unregularised fit runs off to
 *  infinity); with 2 x 2 points a cell, |w| settles near 5 per cell. */
#define REGRESSION_LAMBDA 1e-2

/** Doubles per node: the fit w (3), then the sums of a pass: the
 *  gradient (3), the Hessian's upper triangle (6), the weight (1). */
#define REGRESSION_DOUBLES 13

/**
 * @brief Add a point to a node's sums for a Newton step.
 * @param r     the node's REGRESSION_DOUBLES (the fit r[0..2] is read)
 * @param xi    (x_p - x_i) / h
 * @param eta   (y_p - y_i) / h
 * @param S     the point's weight, its shape function S_ip
 * @param label 0: a point of the first field, 1: of the second
 */
void regression_add(double r[REGRESSION_DOUBLES], double xi, double eta,
                    double S, int label);

/** @brief Clear a node's sums (not its fit) before a pass. */
void regression_clear(double r[REGRESSION_DOUBLES]);

/**
 * @brief One Newton step on a node's fit from the sums of a pass:
 *        w -= (H + lambda W D)^-1 (g + lambda W D w), D = diag(1, 1, 1e-6).
 * @return 0, or -1 when the node had no weight (the fit is left alone).
 */
int regression_newton(double r[REGRESSION_DOUBLES]);

/**
 * @brief The unit normal of a node's fit, from its first field to its
 *        second. @return 0 when the fit has no direction (w_0 = w_1 = 0).
 */
int regression_normal(const double r[REGRESSION_DOUBLES], double n[2]);

#endif
