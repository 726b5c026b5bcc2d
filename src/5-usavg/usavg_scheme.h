/**
 * @file usavg_scheme.h
 * @brief The paper's averaged stress update, USAVG, as a row of the table
 *        of update schemes.
 */
#ifndef MPM_USAVG_SCHEME_H
#define MPM_USAVG_SCHEME_H

#include "scene.h"

/// [usavg_scheme]
/** @brief USAVG: which shares of the strain increment are taken at Task 2
 *         and at Task 6, and whether Task 6 re-extrapolates first. */
UpdateScheme usavg_scheme(void);
/// [usavg_scheme]

#endif
