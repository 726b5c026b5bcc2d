/**
 * @file stage4.h
 * @brief Installer of stage 4: crack-surface contact.
 */
#ifndef MPM_STAGE4_H
#define MPM_STAGE4_H

#include "hooks.h"

/** @brief Register the key "contact" of a crack; its parser subscribes
 *         to the contact seams (Tasks 2, 4, 6) when a crack has contact. */
void stage4_install(Hooks *h);

#endif
