/**
 * @file scene_reference.c
 * @brief The book's scene reference (chapters/scene-reference.md) lists
 *        exactly the keys this build accepts: every key `mpm --keys`
 *        prints is in one of its tables with the same stage, and every key
 *        its tables give for this stage or an earlier one is printed.
 *        `mpm --help` names the page and this build's sections.
 *
 * The page's types, units, defaults and ranges are written by hand; this
 * test keeps its set of keys and their stages honest, in every stage.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stages.h"
#include "testkit.h"

#define PAGE "chapters/scene-reference.md"

/** Most keys of either list. */
enum { MAX_KEYS = 512 };

/** A key's path ("bodies.disk.radius", "run.update=usf") and its stage. */
typedef struct Key {
    char path[96];
    int stage;
} Key;

/** A set of keys. */
typedef struct Keys {
    Key at[MAX_KEYS];
    int n;
} Keys;

static char out[65536];

static void add_key(Keys *k, const char *path, size_t len, int stage)
{
    if (k->n == MAX_KEYS || len == 0 || len >= sizeof k->at[0].path)
        fail_msg("key list: too many keys, or a path of %zu characters", len);
    memcpy(k->at[k->n].path, path, len);
    k->at[k->n].path[len] = '\0';
    k->at[k->n++].stage = stage;
}

static const Key *find_key(const Keys *k, const char *path)
{
    for (int j = 0; j < k->n; j++)
        if (strcmp(k->at[j].path, path) == 0)
            return &k->at[j];
    return NULL;
}

/** The keys `mpm --keys` prints, and the stage its first line names. */
static int printed_keys(Keys *k)
{
    int rc = tk_run_mpm("--keys", out, sizeof out), stage = 0;
    if (rc != 0)
        fail_msg("mpm --keys: exit %d\n%s", rc, out);
    if (sscanf(out, "# mpm stage %d", &stage) != 1)
        fail_msg("mpm --keys: the first line does not name the stage:\n%s", out);
    k->n = 0;
    for (char *line = strchr(out, '\n'); line && line[1]; line = strchr(line, '\n')) {
        line++;
        char *sp = strchr(line, ' '), *end;
        if (!sp)
            fail_msg("mpm --keys: \"%.60s\" is not \"path stage\"", line);
        long s = strtol(sp + 1, &end, 10);
        if (end == sp + 1 || (*end != '\n' && *end != '\0') || s < 1 || s > stage)
            fail_msg("mpm --keys: \"%.60s\" has no stage in 1..%d", line, stage);
        add_key(k, line, (size_t)(sp - line), (int)s);
    }
    return stage;
}

/** The keys of the page's tables: rows "| `path` | ... | N |". */
static void page_keys(Keys *k)
{
    char *page = tk_slurp(PAGE, NULL);
    k->n = 0;
    for (char *line = page, *nl; line && *line; line = nl ? nl + 1 : NULL) {
        nl = strchr(line, '\n');
        if (strncmp(line, "| `", 3) != 0)
            continue;
        char *close = strchr(line + 3, '`');
        size_t len = nl ? (size_t)(nl - line) : strlen(line);
        char row[1024];
        if (!close || len >= sizeof row)
            fail_msg(PAGE ": a row that opens with a key has no key: %.60s", line);
        memcpy(row, line, len);
        row[len] = '\0';
        char *last = strrchr(row, '|');          /* "| N |": the stage */
        *last = '\0';
        char *cell = strrchr(row, '|'), *end;
        long s = strtol(cell + 1, &end, 10);
        while (*end == ' ')
            end++;
        if (end == cell + 1 || *end || s < 1 || s > 9)
            fail_msg(PAGE ": the row of %.*s does not end in its stage",
                     (int)(close - line - 3), line + 3);
        add_key(k, line + 3, (size_t)(close - line - 3), (int)s);
    }
    free(page);
}

static void printed_keys_are_on_the_page(void **state)
{
    static Keys printed, page;
    (void)state;
    int stage = printed_keys(&printed);
    assert_int_equal(stage, mpm_stage());
    page_keys(&page);
    printf("stage %d: %d keys and values printed, %d rows on the page\n", stage,
           printed.n, page.n);
    assert_true(printed.n > 50);
    int bad = 0;
    for (int j = 0; j < printed.n; j++) {
        const Key *p = &printed.at[j], *on = find_key(&page, p->path);
        if (!on) {
            printf("  %s (stage %d) is not on " PAGE "\n", p->path, p->stage);
            bad++;
        } else if (on->stage != p->stage) {
            printf("  %s: the page says stage %d, the build %d\n", p->path,
                   on->stage, p->stage);
            bad++;
        }
    }
    for (int j = 0; j < page.n; j++) {
        const Key *q = &page.at[j];
        if (q->stage <= stage && !find_key(&printed, q->path)) {
            printf("  " PAGE " lists %s for stage %d; this build does not "
                   "accept it\n", q->path, q->stage);
            bad++;
        }
        for (int i = 0; i < j; i++)
            if (strcmp(page.at[i].path, q->path) == 0) {
                printf("  " PAGE " lists %s twice\n", q->path);
                bad++;
            }
    }
    assert_int_equal(bad, 0);
}

static void help_names_the_page_and_the_sections(void **state)
{
    static Keys printed;
    (void)state;
    printed_keys(&printed);
    int rc = tk_run_mpm("--help", out, sizeof out);
    assert_int_equal(rc, 0);
    assert_non_null(strstr(out, PAGE));
    /* the crack files come with the cracks section */
    assert_true(!find_key(&printed, "cracks") == !strstr(out, "cracks.pvd"));
    /* "Scene sections of this build:\n  grid, run, ..., cracks.\n" */
    char *list = strstr(out, "Scene sections of this build:"), *end;
    assert_non_null(list);
    list = strchr(list, '\n') + 1;
    end = strchr(list, '.');
    assert_non_null(end);
    *end = '\0';
    int sections = 0, listed = 0;
    for (int j = 0; j < printed.n; j++)
        sections += !strpbrk(printed.at[j].path, ".=");   /* a section */
    for (char *w = strtok(list, ", "); w; w = strtok(NULL, ", ")) {
        const Key *k = find_key(&printed, w);
        if (!k)
            fail_msg("--help lists \"%s\", which --keys does not print", w);
        listed++;
    }
    printf("--help lists %d sections; --keys prints %d\n", listed, sections);
    assert_true(sections >= 7);
    assert_int_equal(listed, sections);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(printed_keys_are_on_the_page),
        cmocka_unit_test(help_names_the_page_and_the_sections),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
