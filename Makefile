# The staged MPM book: `make stageN` builds build/stageN/mpm from the base
# floor src/0-base (the program around the method: scene reader, outputs,
# checkpoint, run loop, main) and the stage folders src/1-* .. src/N-*, with
# include paths for those folders only, so a stage-1 file that reached for a
# later stage's header would not compile.
#
#   make stage1 ... stage8   one solver per chapter
#   make check               every stage's tests, sanitizer builds, exercises
#                            (and no global mutable state in the objects)
#   make docs                the book (Doxygen, warnings are errors)
#   make figures | figN      the paper's figures, full size (build/figures/figN.png,
#                            redrawn when a file it reads changes; REDRAW=1
#                            redraws anyway, say with other environment settings)
#   make bench               particle-steps per second and memory per point
#   make tsan                the threaded tests under ThreadSanitizer (clang)
#   make fuzz                the scene reader under libFuzzer (clang), for
#                            FUZZ_SECONDS (600) in FUZZ_JOBS (2) workers
#   make same-numbers BASE=rev  every scene, scheme and stage byte for byte
#                            against the build of another commit
#   make exercise EX=1-mpm/shape-functions SOLUTION=my_shape.c

SHELL := /bin/bash
CC ?= cc
WARN := -std=c11 -Wall -Wextra -Werror -Wshadow -Wmissing-prototypes -Wundef \
        -D_POSIX_C_SOURCE=200809L
# OpenMP (GCC's libgomp) for the loops that run on several threads
OMP := -fopenmp
CFLAGS_release := $(WARN) $(OMP) -O2 -g
CFLAGS_asan := $(WARN) $(OMP) -O1 -g -fno-omit-frame-pointer \
               -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all
LDFLAGS_release :=
LDFLAGS_asan := -fsanitize=address,undefined,float-cast-overflow
# make tsan: ThreadSanitizer on the threaded tests, built with clang and
# LLVM's OpenMP runtime, whose Archer tool (libarcher, loaded by libomp
# through OMPT) tells TSan where OpenMP's barriers and forks order the
# threads; GCC's libgomp is not instrumented, so TSan sees no order at its
# barriers and reports races in our loops that cannot happen (tools/tsan.sh)
LLVM_LIB := /usr/lib/llvm-14/lib
CC_release := $(CC)
CC_asan := $(CC)
CC_tsan := clang
CFLAGS_tsan := $(WARN) $(OMP) -O1 -g -fno-omit-frame-pointer -fsanitize=thread
LDFLAGS_tsan := -fsanitize=thread -Wl,-rpath,$(LLVM_LIB)
LIBS := -lconfig -lm $(OMP)
# a stage's folder names the libraries its code needs in a file `libs`
# (src/6-xefg/libs: LAPACKE, for small dense systems); stage N links those
# of folders 1..N
stage_libs = $(foreach d,$(call dirs_upto,$(1)),$(shell cat $(d)/libs 2>/dev/null)) $(LIBS)
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
# tests link cmocka and LAPACKE (the reference finite element solver)
TEST_LIBS := -lcmocka -llapacke $(LIBS)

STAGE_DIRS := $(sort $(wildcard src/[1-9]-*))
stage_num = $(firstword $(subst -, ,$(notdir $(1))))
STAGES := $(foreach d,$(STAGE_DIRS),$(call stage_num,$(d)))
# folders of stages 1..N; every stage compiles the base floor too
BASE_DIR := src/0-base
upto = $(foreach d,$(1),$(if $(filter $(call stage_num,$(d)),$(wordlist 1,$(2),1 2 3 4 5 6 7 8 9)),$(d)))
dirs_upto = $(BASE_DIR) $(call upto,$(STAGE_DIRS),$(1))
# Each thing is tested once: chapter K's tests run on stage K, the release
# and the sanitizer build.  A later stage runs the same code on the same
# scenes, and scene_same_numbers proves that its outputs are the same bytes.
# A test that checks what later stages change runs there too: a folder's
# file `later_stages` names its tests that every later stage runs, and its
# file `also` the earlier chapters' tests that its own stage runs.
TEST_DIRS := $(sort $(wildcard tests/[1-9]-*))
listed = $(shell sed 's/\#.*//' $(1) 2>/dev/null)
named = $(foreach f,$(2),$(if $(filter $(1),$(notdir $(f))),$(f)))
tests_of = $(sort $(wildcard tests/$(1)-*/test_*.c tests/$(1)-*/scene_*.c) \
             $(foreach d,$(call upto,$(TEST_DIRS),$(1)),$(patsubst %,$(d)/%.c,$(call listed,$(d)/later_stages))) \
             $(foreach d,$(wildcard tests/$(1)-*),$(patsubst %,tests/%.c,$(call listed,$(d)/also))))

# Objects are compiled once and shared by every stage that links them: a
# file of folder src/K-* (or tests/K-*) is compiled with the include paths
# of stages 1..K only, so a stage-K file that reached for a later stage's
# header still does not compile, and since only stages.c is compiled with
# -DMPM_STAGE=N, the object is the same bytes in every stage (stages 1-8
# once had eight copies of each; cmp found them identical). The base floor
# is compiled as stage 1 compiles it (main.c runs a Sim). stages.o is each
# stage's own. Objects: build/shared/ (build/asan/shared/, build/tsan/shared/).
# $(1) = release | asan | tsan
V_release := build/shared
V_asan := build/asan/shared
V_tsan := build/tsan/shared
folder_stage = $(or $(if $(filter fuzz,$(1)),$(LAST)),$(filter 1 2 3 4 5 6 7 8 9,$(call stage_num,$(1))),1)

# $(1) = release | asan | tsan, $(2) = a folder of src/ or tests/
define FOLDER_RULES
$$(V_$(1))/$(patsubst src/%,obj/%,$(2))/%.o: $(2)/%.c
	@mkdir -p $$(@D)
	$$(CC_$(1)) $$(CFLAGS_$(1)) $$(addprefix -I,$$(call dirs_upto,$$(call folder_stage,$(notdir $(2))))) \
	    $(if $(filter tests/%,$(2)),-Itests/support) -MMD -MP -c $$< -o $$@
-include $$(wildcard $$(V_$(1))/$(patsubst src/%,obj/%,$(2))/*.d)
endef
# tests/support is compiled as stage 1 compiles it; tests/fuzz as the last
# stage does (it loads any scene with that build)
SHARED_DIRS := $(BASE_DIR) $(STAGE_DIRS) $(TEST_DIRS) tests/support tests/fuzz
$(foreach v,release asan tsan,$(foreach d,$(SHARED_DIRS),$(eval $(call FOLDER_RULES,$(v),$(d)))))

# $(1) = release | asan | tsan, $(2) = stage number
define STAGE_RULES
B_$(1)_$(2) := build/$(if $(filter-out release,$(1)),$(1)/)stage$(2)
INC_$(1)_$(2) := $$(addprefix -I,$$(call dirs_upto,$(2)))
SRC_$(2) := $$(foreach d,$$(call dirs_upto,$(2)),$$(wildcard $$(d)/*.c))
OBJ_$(1)_$(2) := $$(patsubst src/%.c,$$(V_$(1))/obj/%.o,$$(filter-out %/stages.c,$$(SRC_$(2)))) \
                 $$(B_$(1)_$(2))/obj/0-base/stages.o
UNIT_$(1)_$(2) := $$(call named,test_%,$$(call tests_of,$(2)))
SCENE_$(1)_$(2) := $$(if $$(filter release,$(1)),$$(call named,scene_%,$$(call tests_of,$(2))))
SUPPORT_$(1) := $$(patsubst tests/support/%.c,$$(V_$(1))/tests/support/%.o,$$(wildcard tests/support/*.c))
TESTS_$(1)_$(2) := $$(patsubst tests/%.c,$$(B_$(1)_$(2))/tests/%,$$(UNIT_$(1)_$(2)) $$(SCENE_$(1)_$(2)))

$$(B_$(1)_$(2))/obj/0-base/stages.o: src/0-base/stages.c
	@mkdir -p $$(@D)
	$$(CC_$(1)) $$(CFLAGS_$(1)) -DMPM_STAGE=$(2) $$(INC_$(1)_$(2)) -MMD -MP -c $$< -o $$@

$$(B_$(1)_$(2))/libmpm.a: $$(filter-out %/main.o,$$(OBJ_$(1)_$(2)))
	@rm -f $$@
	ar rcs $$@ $$^

$$(B_$(1)_$(2))/mpm: $$(V_$(1))/obj/0-base/main.o $$(B_$(1)_$(2))/libmpm.a
	$$(CC_$(1)) $$(LDFLAGS_$(1)) $$^ $$(call stage_libs,$(2)) -o $$@

$$(B_$(1)_$(2))/tests/%: $$(V_$(1))/tests/%.o $$(SUPPORT_$(1)) $$(B_$(1)_$(2))/libmpm.a
	@mkdir -p $$(@D)
	$$(CC_$(1)) $$(LDFLAGS_$(1)) $$^ $$(TEST_LIBS) -o $$@

-include $$(wildcard $$(B_$(1)_$(2))/obj/0-base/stages.d)
endef

$(foreach s,$(STAGES),$(eval $(call STAGE_RULES,release,$(s))))
$(foreach s,$(STAGES),$(eval $(call STAGE_RULES,asan,$(s))))
$(foreach s,$(STAGES),$(eval $(call STAGE_RULES,tsan,$(s))))

.PHONY: all deps $(addprefix stage,$(STAGES)) check check-release check-asan \
        check-exercises exercise docs figures bench same-numbers fuzz tsan clean
.SECONDARY:
.PHONY: FORCE
FORCE:

all: $(addprefix stage,$(STAGES))

deps:
	@sh tools/deps.sh test

$(foreach s,$(STAGES),$(eval stage$(s): deps build/stage$(s)/mpm))

# ---- exercises -------------------------------------------------------------
# exercises/N-name/EX/ holds README.md, stub.c, `replaces` (the src file the
# solution stands in for) and `tests` (test programs of tests/N-name/).
EXERCISES := $(patsubst exercises/%/replaces,%,$(wildcard exercises/*/*/replaces))
ex_stage = $(call stage_num,$(firstword $(subst /, ,$(1))))
ex_tests = $(foreach t,$(shell cat exercises/$(1)/tests),build/exercises/$(1)/$(2)/$(t))
EXERCISE_BINS := $(foreach e,$(EXERCISES),$(call ex_tests,$(e),reference) $(call ex_tests,$(e),stub))
EXERCISE_CHECKS := $(foreach e,$(EXERCISES),$(call ex_tests,$(e),reference) $(addprefix !,$(call ex_tests,$(e),stub)))

# The stage's library less the object the exercise replaces, so that the
# solution is the only definition of what it must define: a file that lacks
# a function fails to link, naming it.
ex_replaced = $(patsubst src/%.c,$(V_release)/obj/%.o,$(shell cat exercises/$(1)/replaces))
define EXERCISE_LIB
build/exercises/$(1)/libmpm.a: $$(filter-out %/main.o $(call ex_replaced,$(1)),$$(OBJ_release_$(call ex_stage,$(1))))
	@mkdir -p $$(@D)
	@rm -f $$@
	ar rcs $$@ $$^
endef
$(foreach e,$(EXERCISES),$(eval $(call EXERCISE_LIB,$(e))))

# $(1) = exercise, $(2) = reference | stub | empty | student, $(3) = solution
# $(4) = FORCE for a student's file: SOLUTION may name another file each time
define EXERCISE_RULES
build/exercises/$(1)/$(2)/solution.o: $(3) $(4)
	@mkdir -p $$(@D)
	$$(CC) $$(CFLAGS_release) $$(INC_release_$(call ex_stage,$(1))) -MMD -MP -c $$< -o $$@
-include build/exercises/$(1)/$(2)/solution.d
build/exercises/$(1)/$(2)/%: $(V_release)/tests/$(firstword $(subst /, ,$(1)))/%.o \
        build/exercises/$(1)/$(2)/solution.o $$(SUPPORT_release) \
        build/exercises/$(1)/libmpm.a
	$$(CC) $$^ $$(TEST_LIBS) -o $$@
endef
$(foreach e,$(EXERCISES),$(eval $(call EXERCISE_RULES,$(e),reference,$(shell cat exercises/$(e)/replaces))))
$(foreach e,$(EXERCISES),$(eval $(call EXERCISE_RULES,$(e),stub,exercises/$(e)/stub.c)))
$(foreach e,$(EXERCISES),$(eval $(call EXERCISE_RULES,$(e),empty,tools/empty_solution.c)))
ifdef EX
ifdef SOLUTION
$(eval $(call EXERCISE_RULES,$(EX),student,$(SOLUTION),FORCE))
endif
endif

exercise: deps
	@test -n "$(EX)" || { echo "usage: make exercise EX=<one of: $(EXERCISES)> SOLUTION=file.c"; exit 1; }
	@test -f "exercises/$(EX)/replaces" || { echo "EX=$(EX) is not an exercise (one of: $(EXERCISES))"; exit 1; }
	@test -n "$(SOLUTION)" || { echo "give SOLUTION=your_file.c (start from exercises/$(EX)/stub.c)"; exit 1; }
	@test -f "$(SOLUTION)" || { echo "SOLUTION=$(SOLUTION): no such file"; exit 1; }
	@$(MAKE) --no-print-directory $(call ex_tests,$(EX),student) || { echo; echo "exercise $(EX): \
	$(SOLUTION) did not compile or link; \"undefined reference to X\" above means it does not define X \
	(the functions to write are in exercises/$(EX)/README.md)"; exit 1; }
	@JOBS=$(JOBS) bash tools/run_tests.sh "exercise $(EX)::$(call ex_tests,$(EX),student)"

# ---- fuzzing ---------------------------------------------------------------
# tests/fuzz/fuzz_scene.c loads any text with the last stage's build.  make
# fuzz compiles it and every source again with clang's libFuzzer; make check
# replays tests/fuzz/corpus and tests/fuzz/regressions through it with the
# usual compiler (tests/fuzz/replay.c), in the release and sanitizer builds.
LAST := $(lastword $(STAGES))
FUZZ_SECONDS ?= 600
FUZZ_JOBS ?= 2
FUZZ_CC := clang
FUZZ_SAN := -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all
CFLAGS_fuzz := $(WARN) $(OMP) -O1 -g -fno-omit-frame-pointer -fsanitize=fuzzer-no-link $(FUZZ_SAN)
FUZZ_OBJ := $(patsubst src/%.c,build/fuzz/obj/%.o,$(filter-out %/main.c,$(SRC_$(LAST))))
REPLAY := build/stage$(LAST)/tests/fuzz/replay build/asan/stage$(LAST)/tests/fuzz/replay

build/fuzz/obj/%.o: src/%.c
	@mkdir -p $(@D)
	$(FUZZ_CC) $(CFLAGS_fuzz) $(if $(filter %/stages.c,$<),-DMPM_STAGE=$(LAST)) $(INC_release_$(LAST)) -MMD -MP -c $< -o $@

build/fuzz/fuzz_scene.o: tests/fuzz/fuzz_scene.c
	@mkdir -p $(@D)
	$(FUZZ_CC) $(CFLAGS_fuzz) $(INC_release_$(LAST)) -MMD -MP -c $< -o $@

build/fuzz/fuzz_scene: build/fuzz/fuzz_scene.o $(FUZZ_OBJ)
	$(FUZZ_CC) -fsanitize=fuzzer $(FUZZ_SAN) $^ $(call stage_libs,$(LAST)) -o $@

-include $(FUZZ_OBJ:.o=.d) build/fuzz/fuzz_scene.d

# the replay links the target's object besides its own
build/stage$(LAST)/tests/fuzz/replay: $(V_release)/tests/fuzz/fuzz_scene.o
build/asan/stage$(LAST)/tests/fuzz/replay: $(V_asan)/tests/fuzz/fuzz_scene.o

fuzz:
	@sh tools/deps.sh fuzz
	@$(MAKE) --no-print-directory build/fuzz/fuzz_scene
	@FUZZ_SECONDS=$(FUZZ_SECONDS) FUZZ_JOBS=$(FUZZ_JOBS) bash tools/fuzz.sh

# ---- tests -----------------------------------------------------------------
# Each stage runs its chapter's tests (tests_of, above), in the release and
# the sanitizer build, and the exercises run theirs; the test
# programs run JOBS at a time (tools/run_tests.sh says how they keep apart).
check: deps
	@$(MAKE) --no-print-directory -j$(JOBS) check-build
	@$(MAKE) -n --no-print-directory $(RESOLVED) >/dev/null || \
	    { echo "make check: make -n $(RESOLVED) fails: a target names a file no rule makes"; exit 1; }
	@bash tools/check_globals.sh $(OBJ_release_$(LAST))    # no global mutable state
	@rm -rf build/same-numbers-cache     # scene_same_numbers' copies: this run's own
	@JOBS=$(JOBS) bash tools/run_tests.sh $(foreach s,$(STAGES),"stage$(s):build/stage$(s)/mpm:$(TESTS_release_$(s))" "asan-stage$(s):build/asan/stage$(s)/mpm:$(TESTS_asan_$(s))") \
	    "fuzz replay::$(REPLAY)" \
	    "exercises::$(EXERCISE_CHECKS)" \
	    "empty solutions::$(foreach e,$(EXERCISES),$(addprefix ?,$(call ex_tests,$(e),empty)))"

# the targets make check does not run, resolved by make -n: in a fresh clone
# (CI) a prerequisite that no rule makes stops them (as a moved object once
# stopped make docs)
RESOLVED := figures docs bench tsan fuzz same-numbers

check-build: $(foreach s,$(STAGES),build/stage$(s)/mpm $(TESTS_release_$(s)) build/asan/stage$(s)/mpm $(TESTS_asan_$(s))) \
             $(REPLAY) $(EXERCISE_BINS)

# ---- ThreadSanitizer ---------------------------------------------------------
# make tsan: the tests that run the solver on 1 to 4 threads, solver and
# test built with clang -fsanitize=thread and LLVM's OpenMP with Archer
# (build/tsan/, tools/tsan.sh says why not GCC's libgomp), on the stages
# that add threaded code: stage 1 (the strips), 4 (contact's scatters),
# 6 (XEFG's Gauss points) and 8 (every feature, the wider stencils and APIC).
# Not part of make check (it takes minutes: the appendix's threads section).
TSAN_RUNS := 1:1-mpm/scene_threads 4:1-mpm/scene_threads 6:6-xefg/scene_xefg_threads \
             8:1-mpm/scene_threads
tsan_stage = $(firstword $(subst :, ,$(1)))
tsan_test = build/tsan/stage$(call tsan_stage,$(1))/tests/$(lastword $(subst :, ,$(1)))
tsan: deps
	@sh tools/deps.sh fuzz
	@$(MAKE) --no-print-directory -j$(JOBS) $(foreach r,$(TSAN_RUNS),\
	    build/tsan/stage$(call tsan_stage,$(r))/mpm $(call tsan_test,$(r)))
	@JOBS=$(JOBS) LLVM_LIB=$(LLVM_LIB) bash tools/tsan.sh $(foreach r,$(TSAN_RUNS),\
	    "tsan-stage$(call tsan_stage,$(r)):build/tsan/stage$(call tsan_stage,$(r))/mpm:$(call tsan_test,$(r))")

# ---- book, figures, bench ----------------------------------------------------
# the chapters show these figures (about thirty-two minutes to draw, and
# fig-growth's four to eight more, fig-kalthoff's four, fig-shapes'
# five, fig-k-edge's ten, on a shared two-core machine) and
# include the tables their scripts write (build/figures/*.txt, on doxygen's
# EXAMPLE_PATH: a missing one is a warning, so an error)
DOC_FIGURES := $(filter fig1 fig1b fig2 fig-patch fig3 fig4 fig5 fig6 fig6-onefield fig-crossing fig-tip fig-tradeoff fig-stability fig-xefg-k fig-xefg-dcb fig-petersson fig-slide fig-bars fig-growth fig-kalthoff fig-shapes fig-k-edge,$(notdir $(wildcard figures/fig*)))
# MathJax is copied into the book (not linked), so that it can be moved or
# served as it is; its sources (unpacked), tests and combined configurations
# are left out
MATHJAX ?= /usr/share/javascript/mathjax
MATHJAX_PARTS := MathJax.js extensions fonts jax localization
docs:
	@sh tools/deps.sh docs
	@$(MAKE) --no-print-directory $(DOC_FIGURES)
	@mkdir -p build/docs
	@rm -rf build/docs/warnings.log build/docs/html   # no page of an older book
	@echo doxygen Doxyfile; doxygen Doxyfile 2>build/docs/warnings.log; rc=$$?; \
	 rm -rf build/docs/html/mathjax && mkdir -p build/docs/html/mathjax && \
	 cp -RL $(addprefix $(MATHJAX)/,$(MATHJAX_PARTS)) build/docs/html/mathjax/ || exit 1; \
	 bash tools/check_html.sh build/docs/html build/docs/warnings.log && exit $$rc
	@echo "docs: build/docs/html/index.html"

# Each figure is a file, build/figures/ + the first of FIG_OUT_x, remade
# only when what it reads has changed: its folder (make.sh, plots, scenes),
# figures/lib.sh (what the scripts share), the programs it runs (FIG_RUN_x)
# and its other inputs (FIG_USES_x); the
# other files of FIG_OUT_x come with the first (a figure's table that a
# chapter includes is one of them). `make x` is the same.
# A figure folder not listed here: x.png, remade after any stage. REDRAW=1
# remakes the figures named whatever their age.
FIG_OUT_fig1 := fig1.png
FIG_RUN_fig1 := build/stage2/mpm
FIG_OUT_fig1b := fig1b.png
FIG_RUN_fig1b := build/stage1/mpm
FIG_OUT_fig2 := fig2.png fig2.txt
FIG_RUN_fig2 := build/stage2/tests/2-fields/scene_fig2
FIG_USES_fig2 := figures/fig1/dcb_full.cfg figures/fig1/dcb_half.cfg
FIG_OUT_fig-patch := fig-patch.png fig-patch.txt
FIG_RUN_fig-patch := build/stage2/mpm
FIG_USES_fig-patch := figures/fig1/dcb_full.cfg figures/fig1/dcb_half.cfg
FIG_OUT_fig3 := fig3.png fig3-openings.png fig3.txt
FIG_RUN_fig3 := build/stage4/mpm build/stage4/tests/4-contact/scene_fig3
FIG_OUT_fig4 := fig4.png fig4-contact.png fig4.txt
FIG_RUN_fig4 := build/stage4/mpm build/stage4/tests/4-contact/scene_fig4
FIG_OUT_fig5 := fig5.png fig5.txt
FIG_RUN_fig5 := build/stage4/mpm
FIG_USES_fig5 := figures/fig6/beam_impact.cfg
FIG_OUT_fig6 := fig6.png fig6_scene.png fig6.txt
FIG_RUN_fig6 := build/stage5/mpm
FIG_OUT_fig6-onefield := fig6_onefield.png fig6_onefield_scene.png fig6_onefield_summary.txt
FIG_RUN_fig6-onefield := build/stage1/mpm
FIG_USES_fig6-onefield := figures/fig6/beam_impact.cfg
FIG_OUT_fig-crossing := fig-crossing.png
FIG_RUN_fig-crossing := build/stage3/mpm
FIG_USES_fig-crossing := figures/fig1/dcb_full.cfg tools/task1_cost.sh \
    $(addprefix tools/bench/,dcb_crack_2x.cfg dcb_crack.cfg dcb_nocrack.cfg)
FIG_OUT_fig-stability := fig-stability.png fig-stability.txt
FIG_RUN_fig-stability := build/stage5/mpm
FIG_USES_fig-stability := figures/fig6/beam_supports.cfg
FIG_OUT_fig-tip := fig-tip.png fig-tip.txt
FIG_RUN_fig-tip := build/stage3/mpm build/stage3/tests/3-crossing/scene_tip_on_node
FIG_USES_fig-tip := $(wildcard tests/3-crossing/scenes/tip_*.cfg)
FIG_OUT_fig-tradeoff := fig-tradeoff-beam.png fig-tradeoff-dcb.png fig-tradeoff.txt
FIG_RUN_fig-tradeoff := build/stage5/mpm build/stage5/libmpm.a $(V_release)/tests/support/q4.o
FIG_USES_fig-tradeoff := figures/fig6/beam_supports.cfg figures/fig1/dcb_full.cfg tests/support/q4.h
FIG_OUT_fig-bars := fig-bars.png fig-bars.txt
FIG_RUN_fig-bars := build/stage5/mpm build/stage5/tests/4-contact/scene_bars
FIG_USES_fig-bars := tests/4-contact/scenes/bars_gap.cfg tests/4-contact/scenes/bars_one_field.cfg
FIG_OUT_fig-slide := fig-slide.png fig-slide.txt
FIG_RUN_fig-slide := build/stage4/mpm build/stage4/tests/4-contact/scene_slide
FIG_USES_fig-slide := tests/4-contact/scenes/slide.cfg
FIG_OUT_fig-xefg-k := fig-xefg-k.png fig-xefg-k.txt
FIG_RUN_fig-xefg-k := build/stage6/tests/6-xefg/scene_edge_crack
FIG_OUT_fig-xefg-dcb := fig-xefg-dcb.png fig-xefg-dcb.txt
FIG_RUN_fig-xefg-dcb := build/stage6/mpm build/stage6/libmpm.a $(V_release)/tests/support/q4.o
FIG_USES_fig-xefg-dcb := figures/fig1/dcb_full.cfg tests/support/q4.h \
    $(addprefix figures/fig-tradeoff/,dcb_opening.c dcb_opening.sh dcb_scene.sh)
FIG_OUT_fig-petersson := fig-petersson.png fig-petersson.txt
FIG_RUN_fig-petersson := build/stage6/mpm
FIG_USES_fig-petersson := tests/6-xefg/scenes/petersson.cfg tests/6-xefg/scenes/petersson_grow.cfg
FIG_OUT_fig-k-edge := fig-k-edge.png fig-k-edge.txt
FIG_RUN_fig-k-edge := build/stage7/tests/7-fracture/scene_k_edge build/stage6/tests/6-xefg/scene_edge_crack
FIG_OUT_fig-growth := fig-growth.png fig-growth.txt
FIG_RUN_fig-growth := build/stage7/mpm $(V_release)/tests/support/q4.o
FIG_USES_fig-growth := tests/7-fracture/scenes/kalthoff_half.cfg tests/support/q4.h
FIG_OUT_fig-shapes := fig-shapes.png fig-shapes.txt
FIG_RUN_fig-shapes := build/stage8/mpm build/stage8/tests/8-shapes/scene_bar_crossing \
    build/stage8/libmpm.a $(V_release)/tests/support/q4.o
FIG_USES_fig-shapes := tests/8-shapes/scenes/bar_crossing.cfg tests/1-mpm/scenes/spinning_disk.cfg \
    tools/task1_cost.sh figures/fig1/dcb_full.cfg figures/fig6/beam_supports.cfg tests/support/q4.h \
    $(addprefix figures/fig-tradeoff/,dcb_opening.c dcb_opening.sh dcb_scene.sh)
FIG_OUT_fig-kalthoff := fig-kalthoff.png fig-kalthoff.txt
FIG_RUN_fig-kalthoff := build/stage6/mpm
FIG_USES_fig-kalthoff := figures/fig-growth/kalthoff_xefg.cfg \
    $(addprefix tests/6-xefg/scenes/,kalthoff_coarse.cfg kalthoff_h1_667.cfg)

FIGURES := $(notdir $(wildcard figures/fig*))
define FIGURE_RULES
FIG_FILES_$(1) := $$(addprefix build/figures/,$$(or $$(FIG_OUT_$(1)),$(1).png))
$$(firstword $$(FIG_FILES_$(1))): $$(wildcard figures/$(1)/*) figures/lib.sh $$(FIG_USES_$(1)) \
        $$(or $$(FIG_RUN_$(1)),$$(foreach s,$$(STAGES),build/stage$$(s)/mpm)) \
        $$(if $$(REDRAW),FORCE) | figure-deps
	@bash figures/$(1)/make.sh || { rm -f $$@; exit 1; }
$$(wordlist 2,9,$$(FIG_FILES_$(1))): $$(firstword $$(FIG_FILES_$(1))) ;
$(1): $$(FIG_FILES_$(1))
endef
$(foreach f,$(FIGURES),$(eval $(call FIGURE_RULES,$(f))))
.PHONY: $(FIGURES) figure-deps
figures: $(FIGURES)
figure-deps: deps
	@sh tools/deps.sh figures

bench: deps
	@$(MAKE) --no-print-directory $(foreach s,$(STAGES),build/stage$(s)/mpm)
	@bash tools/bench.sh

same-numbers: deps
	@test -n "$(BASE)" || { echo "usage: make same-numbers BASE=<git revision>"; exit 1; }
	@STAGES="$(STAGES)" bash tools/same_numbers.sh $(BASE)

clean:
	rm -rf build
