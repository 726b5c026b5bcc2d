/**
 * @file testkit.c
 * @brief Helpers shared by the test programs.
 */
#include <dirent.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
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

Sim *tk_try_load_file(const char *path, const char *const *overrides, char *err,
                      size_t errlen)
{
    Sim *sim = malloc(sizeof *sim);
    assert_non_null(sim);
    sim_init(sim);
    mpm_install_stages(&sim->hooks);
    int n = 0;
    while (overrides && overrides[n])
        n++;
    if (sim_load_file(sim, path, n, (char *const *)overrides, err, errlen)) {
        tk_free(sim);
        return NULL;
    }
    return sim;
}

Sim *tk_load_file(const char *path, const char *const *overrides)
{
    char err[1024];
    Sim *sim = tk_try_load_file(path, overrides, err, sizeof err);
    if (!sim)
        fail_msg("scene refused: %s", err);
    return sim;
}

void tk_bound(TkBounds *b, int indent, int ok, const char *fmt, ...)
{
    b->run++;
    if (ok)
        return;
    b->failed++;
    va_list ap;
    va_start(ap, fmt);
    printf("%*sFAIL: ", indent, "");
    vprintf(fmt, ap);
    printf("\n");
    va_end(ap);
}

void tk_bounds_finish(const TkBounds *b)
{
    printf("  %d of %d bounds failed\n", b->failed, b->run);
    fflush(stdout);
    if (b->failed)
        fail_msg("%d of %d bounds failed (FAIL lines above)", b->failed, b->run);
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

const char *tk_mpm_bin(void)
{
    const char *bin = getenv("MPM_BIN");
    if (!bin || !*bin)
        fail_msg("MPM_BIN is not set (run the tests through make check)");
    return bin;
}

int tk_run_mpm(const char *args, char *out, size_t outlen)
{
    char cmd[4096];
    if (snprintf(cmd, sizeof cmd, "exec %s %s", tk_mpm_bin(), args) >= (int)sizeof cmd)
        fail_msg("command too long: %s", args);
    return tk_shell(cmd, out, outlen);
}

void tk_run_mpm_ok(const char *args, char *out, size_t outlen)
{
    int rc = tk_run_mpm(args, out, outlen);
    if (rc != 0)
        fail_msg("mpm %s: exit %d\n%s", args, rc, out);
}

int tk_shell(const char *command, char *out, size_t outlen)
{
    size_t n = strlen(command) + 8;
    char *cmd = malloc(n);
    assert_non_null(cmd);
    snprintf(cmd, n, "%s 2>&1", command);
    FILE *p = popen(cmd, "r");
    free(cmd);
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

double tk_energy_drift(Sim *sim, double *umax)
{
    Totals t0 = sim_totals(sim);
    double e0 = t0.kinetic + t0.strain, worst = 0, u = 0;
    while (sim->step < sim->nsteps) {
        tk_steps(sim, 1);
        Totals t = sim_totals(sim);
        worst = fmax(worst, fabs((t.kinetic + t.strain) / e0 - 1));
        u = fmax(u, t.strain / e0);
    }
    if (umax)
        *umax = u;
    return worst;
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

/** Names of the plain files of @p dir, sorted; returns how many. */
static int dir_files(const char *dir, char (*names)[256], int max)
{
    DIR *d = opendir(dir);
    if (!d)
        fail_msg("cannot open the directory %s", dir);
    int n = 0;
    const struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.')
            continue;
        if (n == max)
            fail_msg("more than %d files in %s", max, dir);
        snprintf(names[n++], 256, "%s", e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)n, sizeof names[0],
          (int (*)(const void *, const void *))strcmp);
    return n;
}

/** "DIR/NAME" in a new string. */
static char *join(const char *dir, const char *name)
{
    size_t n = strlen(dir) + strlen(name) + 2;
    char *p = malloc(n);
    assert_non_null(p);
    snprintf(p, n, "%s/%s", dir, name);
    return p;
}

void tk_assert_same_outputs(const char *a, const char *b, const char *skip)
{
    static char na[512][256], nb[512][256];
    int ka = dir_files(a, na, 512), kb = dir_files(b, nb, 512), j = 0;
    for (int i = 0; i < ka; i++) {
        if (skip && strcmp(na[i], skip) == 0)
            continue;
        while (j < kb && skip && strcmp(nb[j], skip) == 0)
            j++;
        if (j == kb || strcmp(na[i], nb[j]) != 0)
            fail_msg("%s/%s has no twin in %s", a, na[i], b);
        char *pa = join(a, na[i]), *pb = join(b, nb[j++]);
        size_t la, lb;
        char *ca = tk_slurp(pa, &la), *cb = tk_slurp(pb, &lb);
        if (la != lb || memcmp(ca, cb, la) != 0)
            fail_msg("%s and %s differ", pa, pb);
        free(ca);
        free(cb);
        free(pa);
        free(pb);
    }
    while (j < kb && skip && strcmp(nb[j], skip) == 0)
        j++;
    if (j != kb)
        fail_msg("%s/%s has no twin in %s", b, nb[j], a);
}

int tk_assert_outputs_whole(const char *dir)
{
    static char names[512][256];
    int n = dir_files(dir, names, 512);
    for (int i = 0; i < n; i++) {
        const char *name = names[i];
        size_t l = strlen(name), len;
        if (l > 5 && strcmp(name + l - 5, ".part") == 0)
            fail_msg("%s/%s: a file left half written", dir, name);
        char *path = join(dir, name);
        struct stat st;
        if (stat(path, &st) != 0 || !S_ISREG(st.st_mode)) {
            free(path);                   /* a directory put in the way */
            continue;
        }
        char *text = tk_slurp(path, &len);
        const char *ext = strrchr(name, '.');
        if (ext && (!strcmp(ext, ".vtu") || !strcmp(ext, ".vtp") || !strcmp(ext, ".pvd"))) {
            if (len < 11 || strcmp(text + len - 11, "</VTKFile>\n") != 0)
                fail_msg("%s does not end with </VTKFile>", path);
        } else if (ext && !strcmp(ext, ".csv")) {
            /* every row ends, and has as many fields as the column names */
            if (len == 0 || text[len - 1] != '\n')
                fail_msg("%s ends in a cut row", path);
            int want = -1, row = 0;
            for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
                if (line[0] == '#')
                    continue;
                int commas = 0;
                for (const char *c = line; *c; c++)
                    commas += *c == ',';
                if (want < 0)
                    want = commas;
                else if (commas != want)
                    fail_msg("%s: row %d has %d fields, the header %d", path, row,
                             commas + 1, want + 1);
                row++;
            }
        }
        free(text);
        free(path);
    }
    return n;
}
