/**
 * @file replay.c
 * @brief Replay fuzz inputs through the fuzz target without libFuzzer: a
 *        cmocka test for tests/fuzz/corpus/ and one for
 *        tests/fuzz/regressions/, or one for the files named on the
 *        command line (`replay crash-1234` reruns one).
 *
 * Every input runs in a child process, so that one that aborts or that a
 * sanitizer stops (the target's checks, a memory error, a leak) fails its
 * test, naming the file, and the others still run. Built with the
 * compiler of make check against the release and the sanitizer build of
 * the last stage.
 */
#include <dirent.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cmocka.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/** Most files of one test. */
#define REPLAY_MAX 4096

/** Files to replay: those of a folder, or those named. */
typedef struct Inputs {
    const char *dir;     /**< folder, or NULL: the named files */
    char **names;        /**< the named files */
    int count;           /**< how many */
} Inputs;

/** Give the contents of @p path to the target; in the child, which exits. */
static void run_input(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "replay: cannot read %s\n", path);
        exit(2);
    }
    size_t cap = 4096, n = 0;
    unsigned char *buf = malloc(cap);
    for (size_t got; buf && (got = fread(buf + n, 1, cap - n, f)) > 0;) {
        n += got;
        if (n == cap) {
            unsigned char *more = realloc(buf, cap *= 2);
            if (!more)
                free(buf);
            buf = more;
        }
    }
    fclose(f);
    if (!buf)
        exit(2);
    int rc = LLVMFuzzerTestOneInput(buf, n);
    free(buf);
    exit(rc == 0 ? 0 : 1);
}

/** Replay @p path in a child. @return 0 when it exited cleanly. */
static int replay_file(const char *path)
{
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid == 0)
        run_input(path);
    int status;
    if (pid < 0 || waitpid(pid, &status, 0) != pid)
        return -1;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
        return 0;
    printf("  FAILED %s (%s %d)\n", path, WIFSIGNALED(status) ? "signal" : "exit",
           WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
    return -1;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/** The regular files of @p dir, hidden ones skipped, sorted, into @p
 *  paths (the caller frees each). @return how many. */
static int list_dir(const char *dir, char **paths)
{
    DIR *d = opendir(dir);
    if (!d)
        fail_msg("cannot open %s (run from the repository root)", dir);
    int n = 0;
    const struct dirent *e;
    while ((e = readdir(d)) != NULL && n < REPLAY_MAX) {
        if (e->d_name[0] == '.')
            continue;
        size_t len = strlen(dir) + strlen(e->d_name) + 2;
        paths[n] = malloc(len);
        assert_non_null(paths[n]);
        snprintf(paths[n++], len, "%s/%s", dir, e->d_name);
    }
    closedir(d);
    qsort(paths, (size_t)n, sizeof *paths, by_name);
    return n;
}

/** One test: every input of *state; fails naming those that failed. */
static void replay_inputs(void **state)
{
    const Inputs *in = *state;
    static char *listed[REPLAY_MAX];
    char **paths = in->dir ? listed : in->names;
    int n = in->dir ? list_dir(in->dir, listed) : in->count, bad = 0;
    for (int k = 0; k < n; k++)
        bad += replay_file(paths[k]) != 0;
    printf("  %d inputs of %s replayed, %d failed\n", n,
           in->dir ? in->dir : "the command line", bad);
    for (int k = 0; in->dir && k < n; k++)
        free(listed[k]);
    if (bad)
        fail_msg("%d of %d inputs failed (listed above)", bad, n);
    assert_true(n > 0);
}

int main(int argc, char **argv)
{
    Inputs named = {NULL, argv + 1, argc - 1};
    Inputs corpus = {"tests/fuzz/corpus", NULL, 0};
    Inputs regressions = {"tests/fuzz/regressions", NULL, 0};
    const struct CMUnitTest folders[] = {
        {"tests/fuzz/corpus", replay_inputs, NULL, NULL, &corpus},
        {"tests/fuzz/regressions", replay_inputs, NULL, NULL, &regressions},
    };
    const struct CMUnitTest files[] = {
        {"named inputs", replay_inputs, NULL, NULL, &named},
    };
    if (argc > 1)
        return cmocka_run_group_tests(files, NULL, NULL);
    return cmocka_run_group_tests(folders, NULL, NULL);
}
