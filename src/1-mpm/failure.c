/**
 * @file failure.c
 * @brief Recording the step, point and quantity of an instability, or
 *        the reason a rule stopped the run.
 */
#include "step.h"

int step_fail(Sim *sim, int p, const char *quantity, double value)
{
    Failure *f = &sim->fail;
    /* the lowest point of the step, so that a loop may run in any order,
       on any number of threads (one at a time in here) */
#pragma omp critical(step_fail)
    if (!f->quantity || (f->step == sim->step && p < f->particle)) {
        f->step = sim->step;
        f->time = sim->t;
        f->particle = p;
        f->quantity = quantity;
        f->value = value;
    }
    return -1;
}

int step_stop(Sim *sim, int p, const char *reason, double value)
{
    step_fail(sim, p, reason, value);
    if (sim->fail.quantity == reason)
        sim->fail.stop = 1;
    return -1;
}
