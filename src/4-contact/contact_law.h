/**
 * @file contact_law.h
 * @brief Contact at one node between two velocity fields (section 2.2,
 *        eq. 10-19): when the fields are in contact, and how their momenta
 *        change. Written for crack faces; the same functions serve any two
 *        fields that must not pass through each other.
 */
#ifndef MPM_CONTACT_LAW_H
#define MPM_CONTACT_LAW_H

/**
 * @brief Are two fields at a node in contact (eq. 10-12)?
 * @param vrel     relative nodal volume V_i / V_cell (eq. 8-10)
 * @param vsep     below it the fields are separated
 * @param vcontact above it they are in contact
 * @param dvn      approach velocity (v_a - v_b) . n, n from a to b
 * @return 1 in contact, 0 separated; between @p vsep and @p vcontact, in
 *         contact only when the fields approach (@p dvn > 0).
 */
int contact_detected(double vrel, double vsep, double vcontact, double dvn);

/**
 * @brief Stick (eq. 13): the change of field a's momentum that gives both
 *        fields the centre-of-mass velocity; field b's change is -dp.
 * @param ma mass of field a (> 0)
 * @param pa momentum of field a
 * @param mb mass of field b (> 0)
 * @param pb momentum of field b
 * @param dp out: the change of p_a
 */
void contact_stick(double ma, const double pa[2], double mb, const double pb[2],
                   double dp[2]);

/**
 * @brief Frictional sliding (eq. 14-19, derived in chapter 4): the change
 *        of field a's momentum (field b's is -dp) that removes the normal
 *        relative velocity and reduces the tangential one by Coulomb
 *        friction; when friction can stop the sliding, exactly the stick
 *        change of contact_stick().
 * @param ma mass of field a (> 0)
 * @param pa momentum of field a
 * @param mb mass of field b (> 0)
 * @param pb momentum of field b
 * @param n  unit normal from field a to field b
 * @param mu coefficient of friction (>= 0; 0 is frictionless)
 * @param dp out: the change of p_a
 */
void contact_friction(double ma, const double pa[2], double mb,
                      const double pb[2], const double n[2], double mu,
                      double dp[2]);

/// [contact_interface_normal]
/**
 * @brief The unit normal from body a's field to body b's at a node, from
 *        the mass gradients grad m = sum_p m_p grad S_ip of the two fields:
 *        the direction of g_a/|g_a| - g_b/|g_b| (either alone when the
 *        other is zero).
 * @param ga mass gradient of field a at the node (points out of body a)
 * @param gb mass gradient of field b (points out of body b)
 * @param n  out: the unit normal, from a to b
 * @return 1, or 0 when the gradients give no direction.
 */
int contact_interface_normal(const double ga[2], const double gb[2], double n[2]);
/// [contact_interface_normal]

#endif
