/**
 * @file scene_step_allocation.c
 * @brief A time step allocates no memory: the house rule, counted.
 *
 * The program sizes its arrays at set-up, and a step only reuses them
 * (chapter 1, "the data"; appendix "the program"). This test replaces
 * malloc(), calloc(), realloc(), free() and the aligned forms for the whole
 * process (glibc lets a program define them: "Replacing malloc" in its
 * manual), forwards each to glibc's own (__libc_malloc(), ...), and counts
 * the allocating calls made while sim_advance() runs (free() is not
 * counted: it releases what a counted call allocated, and as a tail call
 * it would be charged to the wrong caller), by who made them: libgomp (the
 * OpenMP runtime: the caller's address lies in it) or the program (any
 * other caller: our code, and the libraries it calls, such as LAPACKE).
 *
 * Each scene is loaded, stepped WARM steps (a growing list may reach its
 * size there: the first steps of a contact or a crack), and then counted
 * over COUNTED steps, on 1 and on 2 threads (run.threads). Bounds:
 *  - the program's own calls in the counted steps: 0, on any thread count;
 *  - libgomp's on 2 threads: 0. libgomp keeps the team of the last
 *    parallel region of two or more threads and reuses it for the next of
 *    the same size (team.c, gomp_new_team()), so a step whose regions all
 *    use sim->threads allocates nothing there; a region opened with a
 *    different count (an if() clause that turns it to one thread, a strip
 *    count below the threads) frees that team and makes a new one.
 *  - libgomp's on 1 thread is printed, not bounded: it allocates and frees
 *    a team for every region it runs on one thread, whatever the if()
 *    clause says (gomp_new_team(1) has no cache), which the program cannot
 *    avoid without opening no region at all.
 * The growing cracks are counted in steps where they do not grow (an
 * event uses the room reserved at set-up, chapter 6b). A scene that this
 * build refuses (a crack before stage 2, XEFG before stage 6, ...) is
 * skipped with a line; every stage runs this test (later_stages).
 */
#define _GNU_SOURCE
#include "testkit.h"

#include <dlfcn.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim.h"

void *memalign(size_t align, size_t n);

/* glibc's allocator, which the replacements below forward to */
extern void *__libc_malloc(size_t n);
extern void *__libc_calloc(size_t k, size_t n);
extern void *__libc_realloc(void *p, size_t n);
extern void __libc_free(void *p);
extern void *__libc_memalign(size_t align, size_t n);

/* The counters: the one mutable state a replaced malloc() cannot do
   without (it has no argument to carry it), and only in this test. */
static atomic_int counting;
static atomic_long calls_program, calls_gomp;

/** Count a call made from @p caller (a return address) while counting. */
static void count_call(const void *caller)
{
    if (!atomic_load_explicit(&counting, memory_order_relaxed))
        return;
    Dl_info info;
    if (dladdr(caller, &info) && info.dli_fname && strstr(info.dli_fname, "libgomp"))
        atomic_fetch_add(&calls_gomp, 1);
    else
        atomic_fetch_add(&calls_program, 1);
}

void *malloc(size_t n)
{
    count_call(__builtin_return_address(0));
    return __libc_malloc(n);
}

void *calloc(size_t k, size_t n)
{
    count_call(__builtin_return_address(0));
    return __libc_calloc(k, n);
}

void *realloc(void *p, size_t n)
{
    count_call(__builtin_return_address(0));
    return __libc_realloc(p, n);
}

void free(void *p)             /* not counted: it can be a tail call (the
                                   caller's caller's address), and it
                                   frees what a counted call allocated */
{
    __libc_free(p);
}

void *memalign(size_t align, size_t n)
{
    count_call(__builtin_return_address(0));
    return __libc_memalign(align, n);
}

void *aligned_alloc(size_t align, size_t n)
{
    count_call(__builtin_return_address(0));
    return __libc_memalign(align, n);
}

int posix_memalign(void **p, size_t align, size_t n)
{
    count_call(__builtin_return_address(0));
    void *q = __libc_memalign(align, n);
    if (!q)
        return 12;                              /* ENOMEM */
    *p = q;
    return 0;
}

#define WARM 5
#define COUNTED 20
#define MAXOV 6

typedef struct Case {
    const char *scene;
    const char *ov[MAXOV];  /* overrides; the run.threads one is added */
} Case;

static const Case cases[] = {
    {"tests/1-mpm/scenes/disks.cfg", {"run.update=usl"}},
    {"tests/1-mpm/scenes/disks.cfg", {"run.update=musl"}},
    {"tests/1-mpm/scenes/disks.cfg", {"run.update=usf"}},
    {"tests/1-mpm/scenes/disks.cfg", {"run.update=usavg"}},
    /* gravity, damping, held edges, loads, a moving disk */
    {"tests/1-mpm/scenes/loaded_block.cfg", {"run.update=musl"}},
    {"tests/1-mpm/scenes/loaded_block.cfg", {"run.update=usavg"}},
    /* a crack and its fields; through the index */
    {"figures/fig1/dcb_full.cfg", {"run.snapshots=0"}},
    {"tests/3-crossing/scenes/dcb_kinked.cfg",
     {"run.snapshots=0", "run.crack_search=\"indexed\""}},
    /* contact between bodies, started 10 steps before the count */
    {"tests/4-contact/scenes/disks_contact.cfg", {"run.time=1.7"}},
    {"tests/4-contact/scenes/slide.cfg",
     {"bodies.[1].velocity=[5.0,0.0]", "contact.[0].law=\"friction\"",
      "contact.[0].mu=0.3", "contact.[0].normal=\"regression\""}},
    /* crack contact */
    {"tests/4-contact/scenes/inclined_crack.cfg",
     {"cracks.[0].contact.law=\"friction\"", "cracks.[0].contact.mu=0.3"}},
    /* XEFG: the plate's crack */
    {"tests/6-xefg/scenes/plate_crack.cfg", {"run.snapshots=0"}},
    /* CRAMP with J and K at the tip */
    {"tests/7-fracture/scenes/dcb_j.cfg", {"run.snapshots=0"}},
    /* the wider stencils */
    {"tests/1-mpm/scenes/disks.cfg", {"run.shape=\"gimp\""}},
    {"tests/1-mpm/scenes/disks.cfg", {"run.shape=\"cpdi\""}},
    {"tests/7-fracture/scenes/dcb_growth.cfg", {"run.snapshots=0"}},
    {"tests/6-xefg/scenes/growth_bar.cfg", {"run.snapshots=0"}},
    {"tests/6-xefg/scenes/cohesive_bar.cfg", {"run.snapshots=0"}},
};
#define NCASES (int)(sizeof cases / sizeof cases[0])

/** Load case @p c on @p threads threads, step it WARM steps and count
 *  COUNTED: @return 0 run, 1 skipped (refused), with the counts. */
static int count_steps(const Case *c, int threads, long *prog, long *gomp, long *steps)
{
    char th[32], err[1024];
    snprintf(th, sizeof th, "run.threads=%d", threads);
    const char *ov[MAXOV + 2];
    int k = 0;
    for (; k < MAXOV && c->ov[k]; k++)
        ov[k] = c->ov[k];
    ov[k++] = th;
    ov[k] = NULL;
    Sim *sim = tk_try_load_file(c->scene, ov, err, sizeof err);
    if (!sim) {
        printf("  %s %s: skipped, this build refuses it (%.120s)\n", c->scene,
               c->ov[0] ? c->ov[0] : "", err);
        return 1;
    }
    int rc = 0;
    for (int s = 0; s < WARM && !rc; s++)
        rc = sim_advance(sim);
    assert_int_equal(rc, 0);
    atomic_store(&calls_program, 0);
    atomic_store(&calls_gomp, 0);
    atomic_store(&counting, 1);
    long s = 0;
    for (; s < COUNTED && !rc && sim->step < sim->nsteps; s++)
        rc = sim_advance(sim);
    atomic_store(&counting, 0);
    assert_int_equal(rc, 0);
    *prog = atomic_load(&calls_program);
    *gomp = atomic_load(&calls_gomp);
    *steps = s;
    tk_free(sim);
    return 0;
}

/** Every case on 1 and 2 threads: the bounds of the header. */
static void steps_allocate_nothing(void **state)
{
    (void)state;
    TkBounds b = {0, 0};
    for (int i = 0; i < NCASES; i++) {
        long p1, g1, n1, p2, g2, n2;
        if (count_steps(&cases[i], 1, &p1, &g1, &n1))
            continue;
        count_steps(&cases[i], 2, &p2, &g2, &n2);
        printf("  %s", cases[i].scene);
        for (int k = 0; k < MAXOV && cases[i].ov[k]; k++)
            printf(" %s", cases[i].ov[k]);
        printf(": %ld steps; calls to the allocator: 1 thread program %ld, libgomp %ld "
               "(%.1f a step); 2 threads program %ld, libgomp %ld\n", n1, p1, g1,
               n1 ? (double)g1 / (double)n1 : 0.0, p2, g2);
        assert_true(n1 > 0 && n2 > 0);
        tk_bound(&b, 4, p1 == 0 && p2 == 0, "the program allocates in a step");
        tk_bound(&b, 4, g2 == 0, "libgomp allocates in a step on 2 threads");
    }
    tk_bounds_finish(&b);
}

/** The counter sees an allocation: without it the bounds above prove
 *  nothing. */
static void the_counter_counts(void **state)
{
    (void)state;
    atomic_store(&calls_program, 0);
    atomic_store(&counting, 1);
    char *volatile p = malloc(64);
    free(p);
    atomic_store(&counting, 0);
    assert_int_equal(atomic_load(&calls_program), 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_counter_counts),
        cmocka_unit_test(steps_allocate_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
