/**
 * @file test_scene_text.c
 * @brief The scan of a scene's text for integers libconfig 1.5 would wrap:
 *        found at the int and int64 limits, never in names, reals,
 *        strings or comments, and named by their setting.
 */
#include "testkit.h"

#include <string.h>

#include "scene_text.h"

/** Scan @p text line by line; the first literal found (or "") into @p bad,
 *  its setting into @p key. */
static void scan(const char *text, char *bad, char *key)
{
    TextScan s = {TEXT_CODE, ""};
    bad[0] = key[0] = '\0';
    for (const char *p = text; *p;) {
        const char *nl = strchr(p, '\n'), *end = nl ? nl + 1 : p + strlen(p);
        const char *at;
        int len;
        if (scene_text_scan(p, end, &s, &at, &len)) {
            snprintf(bad, 64, "%.*s", len, at);
            snprintf(key, 64, "%s", s.key);
            return;
        }
        p = end;
    }
}

static void integers_beyond_their_type_are_found(void **state)
{
    (void)state;
    static const char *const cases[][3] = {     /* text, found, setting */
        {"a = 2147483647; b = -2147483648;", "", ""},
        {"a = 2147483648;", "2147483648", "a"},
        {"a = -2147483649;", "-2147483649", "a"},
        {"cells = [99999999999999999999, 20];", "99999999999999999999", "cells"},
        {"a = 9223372036854775807L; b = 3000000000L;", "", ""},
        {"big = 9223372036854775808L;", "9223372036854775808L", "big"},
        {"x = 1e99999999999; y = 99999999999.0; z = .5e3; w = 5e+12;", "", ""},
        {"h = 0xFFFFFFFFFFFF;", "", ""},       /* hexadecimal: refused later */
        {"x99999999999 = 1; a-99999999999 = 2;", "", ""},
        {"s = \"99999999999\"; # 99999999999\n// 99999999999\n", "", ""},
        {"s = \"a \\\" 99999999999\n 99999999999\"; t = 1;", "", ""},
        {"/* 99999999999\n 99999999999 */ n = 3000000000;", "3000000000", "n"},
        {"p = ( [1.0, 2.0],\n  [3.0, 4.0] );\nq = ( 1,\n  4294967296 );", "4294967296", "q"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char bad[64], key[64];
        scan(cases[k][0], bad, key);
        if (strcmp(bad, cases[k][1]) != 0 || strcmp(key, cases[k][2]) != 0)
            fail_msg("%s: found \"%s\" in \"%s\", expected \"%s\" in \"%s\"",
                     cases[k][0], bad, key, cases[k][1], cases[k][2]);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(integers_beyond_their_type_are_found),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
