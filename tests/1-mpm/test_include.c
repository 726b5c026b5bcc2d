/**
 * @file test_include.c
 * @brief @@include files: read relative to the file that names them (nested
 *        too) or by an absolute path, with the scene given with a folder;
 *        a directory, a missing file, a cycle or too deep a nesting is
 *        refused naming the @@include line and the file; an error inside
 *        an included file names that file, its line and the line that
 *        included it.
 *
 * Each test writes its scene files into a fresh folder under build/.
 */
#include "testkit.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>


/** The folder of the files a test writes. */
typedef struct Dir {
    char path[256];
} Dir;

static void make_dir(Dir *d)
{
    mkdir("build", 0777);
    snprintf(d->path, sizeof d->path, "build/test-include-XXXXXX");
    assert_non_null(mkdtemp(d->path));
}

/** Write @p text into @p d/@p rel, making its folders. */
static void put(const Dir *d, const char *rel, const char *text)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", d->path, rel);
    for (char *s = strchr(path + strlen(d->path) + 1, '/'); s; s = strchr(s + 1, '/')) {
        *s = '\0';
        mkdir(path, 0777);
        *s = '/';
    }
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static void remove_dir(const Dir *d)
{
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", d->path);
    assert_int_equal(system(cmd), 0);
}

/** Load @p d/scene.cfg; return 0 or -1 with the message in @p err. */
static int load(const Dir *d, char *err, size_t errlen)
{
    char path[300];
    snprintf(path, sizeof path, "%s/scene.cfg", d->path);
    return tk_try_file(path, err, errlen);
}

/** Load @p d/scene.cfg, which must be refused with a message holding each
 *  of the NULL-ended @p parts ("%s" in one stands for the folder). */
static void refused(const Dir *d, const char *const *parts)
{
    char err[2048];
    if (load(d, err, sizeof err) == 0)
        fail_msg("%s/scene.cfg was accepted", d->path);
    for (const char *const *p = parts; *p; p++) {
        char want[1024];
        snprintf(want, sizeof want, *p, d->path, d->path);
        if (!strstr(err, want))
            fail_msg("message lacks \"%s\": %s", want, err);
    }
}

#define GRID "grid = { origin = [0.0, 0.0]; cells = [10, 10]; cell_size = [1.0, 1.0]; };\n"
#define RUN "run = { time = 0.01; snapshots = 0; };\n"
#define MATERIALS "materials = ( { name = \"gel\"; E = 0.1; nu = 0.33; rho = 1.5e-3; } );\n"
#define BODIES "bodies = ( { name = \"block\"; material = \"gel\";\n" \
               "  rectangle = { min = [2.0, 2.0]; max = [8.0, 8.0]; }; } );\n"

/** Nested includes from a subfolder, each relative to the file naming it,
 *  and the scene named with its folder. */
static void nested_includes_from_a_subfolder(void **state)
{
    (void)state;
    Dir d;
    make_dir(&d);
    put(&d, "scene.cfg", "# a scene in parts\n@include \"parts/grid.cfg\"\n" RUN
        MATERIALS BODIES);
    put(&d, "parts/grid.cfg", "grid = {\n  @include \"origin.cfg\"\n"
        "  cells = [10, 10]; cell_size = [1.0, 1.0];\n};\n");
    put(&d, "parts/origin.cfg", "origin = [-1.0, 0.0];   // read from parts/\n");
    char path[300];
    snprintf(path, sizeof path, "%s/scene.cfg", d.path);
    Sim *sim = tk_load_file(path, NULL);
    assert_close(sim->scene.ox, -1.0, 0.0);        /* the innermost file's */
    assert_int_equal(sim->scene.ncx, 10);
    tk_free(sim);
    remove_dir(&d);
}

/** An absolute path is read as it is, wherever the scene lies. */
static void absolute_include(void **state)
{
    (void)state;
    Dir d;
    make_dir(&d);
    char cwd[1024], text[2048];
    assert_non_null(getcwd(cwd, sizeof cwd));
    put(&d, "lib/gel.cfg", MATERIALS);
    snprintf(text, sizeof text, GRID RUN "@include \"%s/%s/lib/gel.cfg\"\n" BODIES,
             cwd, d.path);
    put(&d, "scenes/scene.cfg", text);
    snprintf(text, sizeof text, "%s/scenes/scene.cfg", d.path);
    Sim *sim = tk_load_file(text, NULL);
    assert_int_equal(sim->scene.nmat, 1);
    assert_close(sim->scene.mat[0].E, 0.1, 0.0);
    tk_free(sim);
    remove_dir(&d);
}

/** A folder, a missing file, a cycle: refused at the @include line. */
static void bad_targets_name_the_include_line(void **state)
{
    (void)state;
    Dir d;
    make_dir(&d);
    put(&d, "parts/x.cfg", "");
    put(&d, "scene.cfg", GRID RUN "@include \"parts\"\n" MATERIALS BODIES);
    refused(&d, (const char *const[]){"%s/scene.cfg:3: @include \"parts\" "
                                      "(%s/parts): is a directory", NULL});
    char args[600], out[4096];                /* the program: one line, exit 1 */
    snprintf(args, sizeof args, "%s/scene.cfg -q -o %s/out", d.path, d.path);
    assert_int_equal(tk_run_mpm(args, out, sizeof out), 1);
    if (strncmp(out, "mpm: ", 5) != 0 || !strstr(out, "is a directory\n") ||
        strchr(out, '\n') != out + strlen(out) - 1)
        fail_msg("mpm %s: expected one line \"mpm: ... is a directory\": %s", args, out);
    put(&d, "scene.cfg", GRID "\n" RUN "@include \"gel.cfg\"  # the material\n"
        MATERIALS BODIES);
    refused(&d, (const char *const[]){"%s/scene.cfg:4: @include \"gel.cfg\" "
                                      "(%s/gel.cfg): No such file or directory", NULL});
    /* a cycle through a subfolder: scene -> parts/a -> ../scene */
    put(&d, "scene.cfg", GRID RUN "@include \"parts/a.cfg\"\n" MATERIALS BODIES);
    put(&d, "parts/a.cfg", "# a\n@include \"../scene.cfg\"\n");
    refused(&d, (const char *const[]){"%s/parts/a.cfg:2: @include \"../scene.cfg\" "
                                      "(%s/parts/../scene.cfg): a cycle",
                                      "(included from %s/scene.cfg:3)", NULL});
    /* a file that includes itself */
    put(&d, "parts/a.cfg", "@include \"a.cfg\"\n");
    refused(&d, (const char *const[]){"%s/parts/a.cfg:1: @include \"a.cfg\"", "a cycle",
                                      NULL});
    remove_dir(&d);
}

/** Ten nested files are read; an eleventh is refused. */
static void nesting_deeper_than_ten_is_refused(void **state)
{
    (void)state;
    Dir d;
    make_dir(&d);
    char name[64], text[128];
    put(&d, "scene.cfg", GRID RUN MATERIALS BODIES "@include \"n1.cfg\"\n");
    for (int k = 1; k <= 10; k++) {
        snprintf(name, sizeof name, "n%d.cfg", k);
        snprintf(text, sizeof text, "@include \"n%d.cfg\"\n", k + 1);
        put(&d, name, k < 10 ? text : "# the tenth\n");
    }
    char err[2048];
    if (load(&d, err, sizeof err))
        fail_msg("ten nested files refused: %s", err);
    put(&d, "n10.cfg", "@include \"n11.cfg\"\n");
    put(&d, "n11.cfg", "# the eleventh\n");
    refused(&d, (const char *const[]){"%s/n10.cfg:1: @include \"n11.cfg\" (%s/n11.cfg): "
                                      "more than 10 nested @include files",
                                      "(included from %s/n9.cfg:1,", NULL});
    remove_dir(&d);
}

/** Errors inside an included file name it, its line and the include. */
static void errors_inside_name_the_included_file(void **state)
{
    (void)state;
    Dir d;
    make_dir(&d);
    /* a setting given twice: libconfig sees it in the included file */
    put(&d, "scene.cfg", GRID RUN "@include \"more/run.cfg\"\n" MATERIALS BODIES);
    put(&d, "more/run.cfg", "# again\nrun = { time = 1.0; };\n");
    refused(&d, (const char *const[]){"%s/more/run.cfg:2: duplicate setting name "
                                      "(included from %s/scene.cfg:3)", NULL});
    /* a syntax error: that file and line, one "syntax error" */
    put(&d, "more/run.cfg", "# broken\n\nrun = { time = ; };\n");
    put(&d, "scene.cfg", GRID "@include \"more/run.cfg\"\n" MATERIALS BODIES);
    refused(&d, (const char *const[]){"%s/more/run.cfg:3: syntax error (included "
                                      "from %s/scene.cfg:2)", NULL});
    /* a value refused by the reader (scene_error) */
    put(&d, "scene.cfg", GRID RUN "@include \"more/gel.cfg\"\n" BODIES);
    put(&d, "more/gel.cfg", "materials = ( {\n  name = \"gel\";\n  E = -1.0;\n"
        "  nu = 0.33; rho = 1.5e-3; } );\n");
    refused(&d, (const char *const[]){"%s/more/gel.cfg:3: E: -1: Young's modulus",
                                      "(included from %s/scene.cfg:3)", NULL});
    /* a refusal after the points are made (a load that holds none) */
    put(&d, "more/gel.cfg", MATERIALS "loads = (\n  { rectangle = { min = [0.0, 0.0]; "
        "max = [1.0, 1.0]; }; force = [1.0, 0.0]; } );\n");
    refused(&d, (const char *const[]){"%s/more/gel.cfg:3: load: no material point", NULL});
    /* an integer libconfig would wrap */
    put(&d, "more/gel.cfg", "materials = ( { name = \"gel\"; E = 0.1; nu = 0.33;\n"
        "  rho = 1.5e-3; } );\nrun = { time = 4294967296; };\n");
    put(&d, "scene.cfg", GRID "@include \"more/gel.cfg\"\n" BODIES);
    refused(&d, (const char *const[]){"%s/more/gel.cfg:3: time: 4294967296 does not "
                                      "fit an integer", NULL});
    remove_dir(&d);
}

/** The scene's own lines keep their numbers after an included file, and
 *  an @include in a comment or a string is not read (as in libconfig). */
static void lines_after_an_include_and_includes_in_comments(void **state)
{
    (void)state;
    Dir d;
    make_dir(&d);
    put(&d, "grid.cfg", "# three\n# lines\n" GRID);
    put(&d, "scene.cfg", "@include \"grid.cfg\"\n/*\n@include \"nothing.cfg\"\n*/\n"
        RUN "materials = ( { name = \"gel\"; E = 0.1; nu = 0.6; rho = 1.5e-3; } );\n"
        BODIES);
    refused(&d, (const char *const[]){"%s/scene.cfg:6: nu: 0.6", NULL});
    remove_dir(&d);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(nested_includes_from_a_subfolder),
        cmocka_unit_test(absolute_include),
        cmocka_unit_test(bad_targets_name_the_include_line),
        cmocka_unit_test(nesting_deeper_than_ten_is_refused),
        cmocka_unit_test(errors_inside_name_the_included_file),
        cmocka_unit_test(lines_after_an_include_and_includes_in_comments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
