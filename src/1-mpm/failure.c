/**
 * @file failure.c
 * @brief Recording the step, point and quantity of an instability.
 */
#include "step.h"

int step_fail(Sim *sim, int p, const char *quantity, double value)
{
    if (!sim->fail.quantity) {
        sim->fail.step = sim->step;
        sim->fail.time = sim->t;
        sim->fail.particle = p;
        sim->fail.quantity = quantity;
        sim->fail.value = value;
    }
    return -1;
}
