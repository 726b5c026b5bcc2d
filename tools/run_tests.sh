#!/bin/bash
# Run groups of test programs and print one summary line "N passed, N failed".
# Each argument is "NAME:MPM_BINARY:PROGRAM PROGRAM ..."; a program written
# !PROGRAM must fail (an exercise stub shows that its tests can fail);
# ?PROGRAM is an exercise's test built with an empty solution: it must fail
# to link (make builds it here) or, if it links, fail.
#
# The programs run JOBS at a time (the environment's JOBS, else the number of
# processors; make check passes its own JOBS).  What makes that safe:
#
# * Many tests write to fixed paths such as build/test-out/... or
#   build/test-restart, and the same test runs once per stage, so two of them
#   at once would overwrite each other's files.  Each program therefore runs
#   in a folder of its own, build/test-run/N (N: its place in the list),
#   which looks like the repository: its folders (tests, figures, tools,
#   src, ...) copied as folders whose files are symbolic links to the
#   repository's (cp -rs), and a real folder build/ holding links to the
#   entries of the real build/ (stage1, asan, exercises, ...) but not to its
#   test-* folders.  What a test reads (tests/..., build/stage2/mpm) is found
#   through the links; what it writes under build/ lands in its own folder.
#   The program and MPM_BIN are relative paths such as build/stage3/mpm,
#   which mean the same there as in the repository.  (The folders are real
#   folders, not links, because `find .` does not enter a linked folder:
#   scene_same_numbers lists the repository's scenes that way.)
#   A program that passed has its folder removed; a failed one's is kept for
#   a look at what it wrote (build/test-run/ is emptied at the next run).
# * The ?PROGRAM entries run make (in the repository, as before).  They wait
#   until every other program has finished and then run one after another,
#   so that make never builds while a test runs, nor two makes at once.
#
# The results are printed in the order of the list, under each group's
# "== NAME" line, whatever order the programs finish in: a program's line is
# printed once it and every program before it have finished, so the output
# is the same from run to run.  Logs: build/test-logs/GROUP-PROGRAM.log.
set -u
root=$PWD
jobs_max=${JOBS:-$(nproc 2>/dev/null || echo 2)}
[ "$jobs_max" -ge 1 ] 2>/dev/null || jobs_max=1
run_dir=build/test-run          # the programs' own folders, and results/
results=$run_dir/results        # N.out: lines to print, N.count, N.failure
rm -rf "$run_dir"
mkdir -p "$results" build/test-logs

# ---- the list of programs --------------------------------------------------
# Job N (0, 1, ...) is one program: its group's name and MPM_BIN, the program,
# and what it must do: pass, fail (!PROGRAM) or not link (?PROGRAM).
# header[N] is set on a group's first program: its "== NAME" line.
job_name=(); job_bin=(); job_prog=(); job_kind=(); header=()
n=0
for group in "$@"; do
  name=${group%%:*}
  rest=${group#*:}
  bin=${rest%%:*}
  progs=${rest#*:}
  [ -z "${progs// }" ] && continue
  header[$n]=$name
  for prog in $progs; do
    kind=pass
    if [[ $prog == !* ]]; then kind=fail; prog=${prog#!}; fi
    if [[ $prog == \?* ]]; then kind=link; prog=${prog#?}; fi
    job_name[$n]=$name; job_bin[$n]=$bin; job_prog[$n]=$prog; job_kind[$n]=$kind
    n=$((n + 1))
  done
done

# ---- running one program -----------------------------------------------------
# make_folder DIR: DIR made to look like the repository (see the top).
make_folder() {
  local dir=$1 entry
  mkdir -p "$dir/build"
  for entry in "$root"/*; do                     # tests, src, Makefile, ...
    case ${entry##*/} in
      build) ;;                                  # below
      *) cp -rs "$entry" "$dir/" ;;              # a file: one link; a folder:
    esac                                         # folders of links
  done
  for entry in "$root"/build/*; do               # stage1, asan, exercises, ...
    case ${entry##*/} in
      test-*) ;;                                 # test outputs: the folder's own
      *) ln -s "$entry" "$dir/build/" ;;
    esac
  done
}

# run_job N: runs job N and prints its result line(s) (ok / FAIL, with the
# log's first lines on a failure) on stdout; writes its counts, "PASSED
# FAILED", to $results/N.count and what the final "failed:" line names to
# $results/N.failure.  Called with stdout going to $results/N.out.
run_job() {
  local id=$1
  local name=${job_name[$id]} bin=${job_bin[$id]} prog=${job_prog[$id]}
  local kind=${job_kind[$id]} dir=$run_dir/$id
  local log="build/test-logs/$(echo "$name-$prog" | tr '/ ' '__').log"
  local ok=0 bad=0 failure="" missing
  if [ "$kind" = link ]; then
    # make, in the repository: the caller makes sure nothing else runs now
    if ! make --no-print-directory -s "$prog" >"$log" 2>&1; then
      missing=$(grep -Eo "undefined reference to [^ ]*" "$log" | sort -u | tr '\n' ' ')
      if [ -n "$missing" ]; then
        ok=1; echo "  ok    $prog: an empty file does not link (${missing% })"
      else
        bad=1; failure="$prog (failed to build, not for a missing definition)"
        echo "  FAIL  $prog: did not build, and not for a missing definition; log: $log"
      fi
      finish_job "$id" $ok $bad "$failure"
      return
    fi
    kind=fail                  # it linked: its tests must fail then
  fi
  make_folder "$dir"
  local start rc secs
  start=$(date +%s)
  # a subshell, so that cd applies to this program alone; JOBS programs
  # share the cores, so each runs one thread unless the caller says
  # otherwise (a scene's run.threads still wins), and threads that wait
  # sleep rather than spin
  (cd "$dir" && OMP_NUM_THREADS=${OMP_NUM_THREADS:-1} \
      OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive} MPM_BIN=$bin exec "$prog") \
      >"$log" 2>&1 </dev/null
  rc=$?
  secs=$(( $(date +%s) - start ))
  if [ $kind = fail ]; then
    if [ $rc -ne 0 ]; then
      ok=1; echo "  ok    $prog fails, as a stub (or an empty file) must (${secs}s)"
    else
      bad=1; failure="$prog (stub or empty file passed its tests)"
      echo "  FAIL  $prog: a stub or an empty file passes its tests, so they cannot fail"
    fi
  else
    local n_ok n_bad
    n_ok=$(grep -Eo '\[  PASSED  \] [0-9]+' "$log" | grep -Eo '[0-9]+$' | tail -1)
    n_bad=$(grep -Eo '\[  FAILED  \] [0-9]+' "$log" | grep -Eo '[0-9]+$' | tail -1)
    n_ok=${n_ok:-0}; n_bad=${n_bad:-0}
    if [ $rc -eq 0 ] && [ "$n_bad" = 0 ]; then
      ok=$n_ok; echo "  ok    $prog ($n_ok tests, ${secs}s)"
    else
      [ "$n_bad" = 0 ] && n_bad=1
      ok=$n_ok; bad=$n_bad; failure=$prog
      echo "  FAIL  $prog (exit $rc); log: $log"
      sed -n '1,60p' "$log" | grep -Ev '^\[ (RUN|       OK) ' | sed 's/^/        /' | head -40
    fi
  fi
  if [ $bad = 0 ]; then
    rm -rf "$dir"
  else                                  # a failed program's files are kept
    echo "(run_tests.sh: this program ran in $dir; its files are there)" >>"$log"
  fi
  finish_job "$id" $ok $bad "$failure"
}

# finish_job N PASSED FAILED FAILURE: the files that say job N is done.  The
# counts are written last, under another name and then renamed, so that
# $results/N.count exists only once everything about job N is written.
finish_job() {
  printf '%s' "$4" >"$results/$1.failure"
  echo "$2 $3" >"$results/$1.tmp"
  mv "$results/$1.tmp" "$results/$1.count"
}

# ---- printing the results in order -------------------------------------------
passed=0
failed=0
failures=()
next=0          # the first job whose result has not been printed yet
print_done() {
  local ok bad
  while [ $next -lt $n ] && [ -f "$results/$next.count" ]; do
    [ -n "${header[$next]:-}" ] && echo "== ${header[$next]}"
    cat "$results/$next.out"
    read -r ok bad <"$results/$next.count"
    passed=$((passed + ok)); failed=$((failed + bad))
    [ -s "$results/$next.failure" ] && failures+=("$(cat "$results/$next.failure")")
    next=$((next + 1))
  done
}

# Ctrl-C or a kill: the programs running in the background would go on
# (background commands of a script ignore Ctrl-C), so stop them: each
# running job (a subshell running run_job), after its children (the test
# program; pkill -P picks processes by their parent's id).
stop_jobs() {
  local pid
  for pid in $(jobs -p); do
    pkill -TERM -P "$pid" 2>/dev/null
    kill -TERM "$pid" 2>/dev/null
  done
  echo "run_tests.sh: stopped; $passed passed, $failed failed so far"
  exit 130
}
trap stop_jobs INT TERM

# ---- the runs ------------------------------------------------------------------
# Start the programs in the order of the list, at most jobs_max at a time:
# while that many are running, wait for one to end (wait -n) and print what
# can be printed.  `jobs -rp` lists the running background jobs, one a line.
for ((id = 0; id < n; id++)); do
  [ "${job_kind[$id]}" = link ] && continue      # later, one by one
  while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do
    wait -n
    print_done
  done
  run_job "$id" >"$results/$id.out" &
done
wait
# a program whose job left no result (its shell killed, say) counts as failed,
# so that the lines after it are printed and the summary stays honest
for ((id = 0; id < n; id++)); do
  if [ "${job_kind[$id]}" != link ] && [ ! -f "$results/$id.count" ]; then
    echo "  FAIL  ${job_prog[$id]}: no result (was the runner's job killed?)" >"$results/$id.out"
    finish_job "$id" 0 1 "${job_prog[$id]} (no result)"
  fi
done
print_done
# the ?PROGRAM entries, which run make: one at a time, nothing else running
for ((id = 0; id < n; id++)); do
  if [ "${job_kind[$id]}" = link ]; then
    run_job "$id" >"$results/$id.out"
    print_done
  fi
done

rm -rf "$results"
echo
for f in "${failures[@]+"${failures[@]}"}"; do echo "failed: $f"; done
echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
