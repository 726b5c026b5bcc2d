/**
 * @file testkit.c
 * @brief Helpers shared by the test programs.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "stages.h"
#include "testkit.h"

Sim *tk_load(const char *text)
{
    Sim *sim = malloc(sizeof *sim);
    assert_non_null(sim);
    sim_init(sim);
    mpm_install_stages(&sim->hooks);
    char err[1024];
    if (sim_load_string(sim, text, "scene", err, sizeof err))
        fail_msg("scene refused: %s", err);
    return sim;
}

Sim *tk_load_with(const char *text, void (*plugin)(Hooks *h, void *arg),
                  void *arg, char *err, size_t errlen)
{
    Sim *sim = malloc(sizeof *sim);
    assert_non_null(sim);
    sim_init(sim);
    mpm_install_stages(&sim->hooks);
    if (plugin)
        plugin(&sim->hooks, arg);
    if (sim_load_string(sim, text, "scene", err, errlen)) {
        tk_free(sim);
        return NULL;
    }
    return sim;
}

Sim *tk_load_file(const char *path, const char *const *overrides)
{
    Sim *sim = malloc(sizeof *sim);
    assert_non_null(sim);
    sim_init(sim);
    mpm_install_stages(&sim->hooks);
    int n = 0;
    while (overrides && overrides[n])
        n++;
    char err[1024];
    if (sim_load_file(sim, path, n, (char *const *)overrides, err, sizeof err))
        fail_msg("scene refused: %s", err);
    return sim;
}

int tk_try_file(const char *path, char *err, size_t errlen)
{
    Sim sim;
    sim_init(&sim);
    mpm_install_stages(&sim.hooks);
    int rc = sim_load_file(&sim, path, 0, NULL, err, errlen);
    sim_free(&sim);
    return rc;
}

void tk_free(Sim *sim)
{
    sim_free(sim);
    free(sim);
}

int tk_run_mpm(const char *args, char *out, size_t outlen)
{
    const char *bin = getenv("MPM_BIN");
    if (!bin || !*bin)
        fail_msg("MPM_BIN is not set (run the tests through make check)");
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "%s %s 2>&1", bin, args);
    FILE *p = popen(cmd, "r");
    assert_non_null(p);
    size_t used = fread(out, 1, outlen - 1, p);
    out[used] = '\0';
    int status = pclose(p);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

void tk_steps(Sim *sim, long n)
{
    for (long k = 0; k < n; k++)
        if (sim_advance(sim))
            fail_msg("unstable at step %ld: particle %d %s = %g", sim->fail.step,
                     sim->fail.particle, sim->fail.quantity, sim->fail.value);
}

char *tk_slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        fail_msg("cannot read %s", path);
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = malloc((size_t)n + 1);
    assert_non_null(buf);
    assert_int_equal(fread(buf, 1, (size_t)n, f), (size_t)n);
    buf[n] = '\0';
    fclose(f);
    if (len)
        *len = (size_t)n;
    return buf;
}
