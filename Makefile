# The staged MPM book: `make stageN` builds build/stageN/mpm from the source
# folders src/1-* .. src/N-*, with include paths for those folders only, so a
# stage-1 file that reached for a later stage's header would not compile.
#
#   make stage1 ... stage5   one solver per chapter
#   make check               every stage's tests, sanitizer builds, exercises
#   make docs                the book (Doxygen, warnings are errors)
#   make figures | figN      the paper's figures, full size (build/figures)
#   make bench               particle-steps per second and memory per point
#   make same-numbers BASE=rev  every scene, scheme and stage byte for byte
#                            against the build of another commit
#   make exercise EX=1-mpm/shape-functions SOLUTION=my_shape.c

SHELL := /bin/bash
CC ?= cc
WARN := -std=c11 -Wall -Wextra -Werror -Wshadow -Wmissing-prototypes -Wundef \
        -D_POSIX_C_SOURCE=200809L
CFLAGS_release := $(WARN) -O2 -g
CFLAGS_asan := $(WARN) -O1 -g -fno-omit-frame-pointer \
               -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all
LDFLAGS_release :=
LDFLAGS_asan := -fsanitize=address,undefined,float-cast-overflow
LIBS := -lconfig -lm
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
# tests link cmocka and LAPACKE (the reference finite element solver)
TEST_LIBS := -lcmocka -llapacke $(LIBS)

STAGE_DIRS := $(sort $(wildcard src/[1-9]-*))
stage_num = $(firstword $(subst -, ,$(notdir $(1))))
STAGES := $(foreach d,$(STAGE_DIRS),$(call stage_num,$(d)))
# folders of stages 1..N
upto = $(foreach d,$(1),$(if $(filter $(call stage_num,$(d)),$(wordlist 1,$(2),1 2 3 4 5 6 7 8 9)),$(d)))
dirs_upto = $(call upto,$(STAGE_DIRS),$(1))
tests_upto = $(call upto,$(sort $(wildcard tests/[1-9]-*)),$(1))

# $(1) = release | asan, $(2) = stage number
define STAGE_RULES
B_$(1)_$(2) := build/$(if $(filter asan,$(1)),asan/)stage$(2)
INC_$(1)_$(2) := $$(addprefix -I,$$(call dirs_upto,$(2)))
OBJ_$(1)_$(2) := $$(patsubst src/%.c,$$(B_$(1)_$(2))/obj/%.o,\
                   $$(foreach d,$$(call dirs_upto,$(2)),$$(wildcard $$(d)/*.c)))
UNIT_$(1)_$(2) := $$(foreach d,$$(call tests_upto,$(2)),$$(wildcard $$(d)/test_*.c))
SCENE_$(1)_$(2) := $$(if $$(filter release,$(1)),$$(foreach d,$$(call tests_upto,$(2)),$$(wildcard $$(d)/scene_*.c)))
SUPPORT_$(1)_$(2) := $$(patsubst tests/support/%.c,$$(B_$(1)_$(2))/tests/support/%.o,$$(wildcard tests/support/*.c))
TESTS_$(1)_$(2) := $$(patsubst tests/%.c,$$(B_$(1)_$(2))/tests/%,$$(UNIT_$(1)_$(2)) $$(SCENE_$(1)_$(2)))

$$(B_$(1)_$(2))/obj/%.o: src/%.c
	@mkdir -p $$(@D)
	$$(CC) $$(CFLAGS_$(1)) $$(if $$(filter %/stages.c,$$<),-DMPM_STAGE=$(2)) $$(INC_$(1)_$(2)) -MMD -MP -c $$< -o $$@

$$(B_$(1)_$(2))/libmpm.a: $$(filter-out %/main.o,$$(OBJ_$(1)_$(2)))
	@rm -f $$@
	ar rcs $$@ $$^

$$(B_$(1)_$(2))/mpm: $$(B_$(1)_$(2))/obj/1-mpm/main.o $$(B_$(1)_$(2))/libmpm.a
	$$(CC) $$(LDFLAGS_$(1)) $$^ $$(LIBS) -o $$@

$$(B_$(1)_$(2))/tests/support/%.o: tests/support/%.c
	@mkdir -p $$(@D)
	$$(CC) $$(CFLAGS_$(1)) $$(INC_$(1)_$(2)) -Itests/support -MMD -MP -c $$< -o $$@

$$(B_$(1)_$(2))/tests/%.o: tests/%.c
	@mkdir -p $$(@D)
	$$(CC) $$(CFLAGS_$(1)) $$(INC_$(1)_$(2)) -Itests/support -MMD -MP -c $$< -o $$@

$$(B_$(1)_$(2))/tests/%: $$(B_$(1)_$(2))/tests/%.o $$(SUPPORT_$(1)_$(2)) $$(B_$(1)_$(2))/libmpm.a
	$$(CC) $$(LDFLAGS_$(1)) $$^ $$(TEST_LIBS) -o $$@

-include $$(OBJ_$(1)_$(2):.o=.d) $$(wildcard $$(B_$(1)_$(2))/tests/*/*.d)
endef

$(foreach s,$(STAGES),$(eval $(call STAGE_RULES,release,$(s))))
$(foreach s,$(STAGES),$(eval $(call STAGE_RULES,asan,$(s))))

.PHONY: all deps $(addprefix stage,$(STAGES)) check check-release check-asan \
        check-exercises exercise docs figures bench same-numbers clean
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
ex_replaced = $(patsubst src/%.c,build/stage$(call ex_stage,$(1))/obj/%.o,$(shell cat exercises/$(1)/replaces))
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
build/exercises/$(1)/$(2)/%: build/stage$(call ex_stage,$(1))/tests/$(firstword $(subst /, ,$(1)))/%.o \
        build/exercises/$(1)/$(2)/solution.o $$(SUPPORT_release_$(call ex_stage,$(1))) \
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
	@bash tools/run_tests.sh "exercise $(EX)::$(call ex_tests,$(EX),student)"

# ---- tests -----------------------------------------------------------------
# Every stage runs the tests of its own and all earlier chapters.
check: deps
	@$(MAKE) --no-print-directory -j$(JOBS) check-build
	@bash tools/run_tests.sh $(foreach s,$(STAGES),"stage$(s):build/stage$(s)/mpm:$(TESTS_release_$(s))" "asan-stage$(s):build/asan/stage$(s)/mpm:$(TESTS_asan_$(s))") \
	    "exercises::$(EXERCISE_CHECKS)" \
	    "empty solutions::$(foreach e,$(EXERCISES),$(addprefix ?,$(call ex_tests,$(e),empty)))"

check-build: $(foreach s,$(STAGES),build/stage$(s)/mpm $(TESTS_release_$(s)) build/asan/stage$(s)/mpm $(TESTS_asan_$(s))) \
             $(EXERCISE_BINS)

# ---- book, figures, bench ----------------------------------------------------
# the chapters show these figures (about twenty-two minutes to draw)
DOC_FIGURES := $(filter fig1 fig1b fig2 fig-patch fig3 fig4 fig5 fig6 fig6-onefield fig-crossing fig-tip fig-tradeoff fig-stability,$(notdir $(wildcard figures/fig*)))
docs:
	@sh tools/deps.sh docs
	@$(MAKE) --no-print-directory $(DOC_FIGURES)
	@mkdir -p build/docs
	doxygen Doxyfile
	@ln -sfn /usr/share/javascript/mathjax build/docs/html/mathjax
	@echo "docs: build/docs/html/index.html"

FIGURES := $(notdir $(wildcard figures/fig*))
figures: $(FIGURES)
$(FIGURES): %: deps
	@sh tools/deps.sh figures
	@$(MAKE) --no-print-directory $(foreach s,$(STAGES),build/stage$(s)/mpm)
	@bash figures/$@/make.sh

bench: deps
	@$(MAKE) --no-print-directory $(foreach s,$(STAGES),build/stage$(s)/mpm)
	@bash tools/bench.sh

same-numbers: deps
	@test -n "$(BASE)" || { echo "usage: make same-numbers BASE=<git revision>"; exit 1; }
	@STAGES="$(STAGES)" bash tools/same_numbers.sh $(BASE)

clean:
	rm -rf build
