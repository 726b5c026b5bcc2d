/**
 * @file testkit.h
 * @brief Helpers shared by the test programs: load a scene with the stages
 *        of this build, run the mpm program and capture what it says.
 */
#ifndef MPM_TESTKIT_H
#define MPM_TESTKIT_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>

#include "scene_load.h"

/** Fail the test unless |a - b| <= tol (cmocka 1.1 has no double compare). */
#define assert_close(a, b, tol)                                                \
    do {                                                                       \
        double a_ = (a), b_ = (b), t_ = (tol);                                 \
        if (!(fabs(a_ - b_) <= t_))                                            \
            fail_msg("%s = %.17g, expected %.17g within %g", #a, a_, b_, t_);  \
    } while (0)

/** @brief Load a scene given as text; fail the test with the message if it
 *         is refused. The caller frees with tk_free(). */
Sim *tk_load(const char *text);

/**
 * @brief Load a scene given as text with this build's stages and then a
 *        test's plug-in: @p plugin (may be NULL) registers or subscribes
 *        what it adds, as a later stage's installer would.
 * @return the simulation, or NULL with the refusal in @p err.
 */
Sim *tk_load_with(const char *text, void (*plugin)(Hooks *h, void *arg),
                  void *arg, char *err, size_t errlen);

/** @brief Load a scene file with "key=value" overrides (NULL-ended list). */
Sim *tk_load_file(const char *path, const char *const *overrides);

/** @brief As tk_load_file(), but a refused scene gives NULL and the reason
 *         in @p err instead of failing the test. */
Sim *tk_try_load_file(const char *path, const char *const *overrides, char *err,
                      size_t errlen);

/** The bounds a benchmark test checked, and how many failed: every bound
 *  is checked and printed before the test fails, so one run shows them
 *  all. */
typedef struct TkBounds {
    int run;     /**< bounds checked */
    int failed;  /**< of them failed */
} TkBounds;

/** @brief Count a bound; print "FAIL: ..." (after @p indent spaces) when
 *         @p ok is 0. */
void tk_bound(TkBounds *b, int indent, int ok, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/** @brief Print how many bounds failed; fail the test if any did. */
void tk_bounds_finish(const TkBounds *b);

/** @brief Try to load a scene file; return 0 or non-zero, message in err. */
int tk_try_file(const char *path, char *err, size_t errlen);

/** @brief Release a simulation made by tk_load(). */
void tk_free(Sim *sim);

/** @brief Run "$MPM_BIN args" through the shell, capture stdout and stderr
 *         into out, and return the exit status. */
int tk_run_mpm(const char *args, char *out, size_t outlen);

/** @brief tk_run_mpm() that fails the test, with the command and its
 *         output, unless the program exits 0. */
void tk_run_mpm_ok(const char *args, char *out, size_t outlen);

/** @brief The program under test ($MPM_BIN); fails the test when unset. */
const char *tk_mpm_bin(void);

/** @brief Run @p command through the shell, capture stdout and stderr into
 *         out, and return the exit status (128 when it did not exit). */
int tk_shell(const char *command, char *out, size_t outlen);

/** @brief Fail unless directories @p a and @p b hold the same files with
 *         the same bytes (a file named @p skip, if not NULL, is ignored). */
void tk_assert_same_outputs(const char *a, const char *b, const char *skip);

/** @brief Fail unless every output file in @p dir is whole: no ".part"
 *         file, ParaView files end with \</VTKFile\>, CSV rows are whole.
 *  @return the number of files. */
int tk_assert_outputs_whole(const char *dir);

/** @brief Read a whole file into a new NUL-terminated buffer (the caller
 *         frees it); its length in *len when @p len is not NULL. Fails the
 *         test when the file cannot be read. */
char *tk_slurp(const char *path, size_t *len);

/** @brief Take @p n steps; fail the test if the run goes unstable. */
void tk_steps(Sim *sim, long n);

/** @brief Run @p sim to its end (failing the test if it goes unstable) and
 *         return the largest |E/E0 - 1| over its steps, E = kinetic +
 *         strain; the largest strain energy over E0 in @p umax (or NULL). */
double tk_energy_drift(Sim *sim, double *umax);

#endif
