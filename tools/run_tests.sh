#!/bin/bash
# Run groups of test programs and print one summary line "N passed, N failed".
# Each argument is "NAME:MPM_BINARY:PROGRAM PROGRAM ..."; a program written
# !PROGRAM must fail (an exercise stub shows that its tests can fail);
# ?PROGRAM is an exercise's test built with an empty solution: it must fail
# to link (make builds it here) or, if it links, fail.
set -u
passed=0
failed=0
failures=()
mkdir -p build/test-logs
for group in "$@"; do
  name=${group%%:*}
  rest=${group#*:}
  bin=${rest%%:*}
  progs=${rest#*:}
  [ -z "${progs// }" ] && continue
  echo "== $name"
  for prog in $progs; do
    expect_fail=0
    if [[ $prog == !* ]]; then expect_fail=1; prog=${prog#!}; fi
    log="build/test-logs/$(echo "$name-$prog" | tr '/ ' '__').log"
    if [[ $prog == \?* ]]; then
      prog=${prog#?}
      if ! make --no-print-directory -s "$prog" >"$log" 2>&1; then
        missing=$(grep -Eo "undefined reference to [^ ]*" "$log" | sort -u | tr '\n' ' ')
        if [ -n "$missing" ]; then
          passed=$((passed + 1)); echo "  ok    $prog: an empty file does not link (${missing% })"
        else
          failed=$((failed + 1)); failures+=("$prog (failed to build, not for a missing definition)")
          echo "  FAIL  $prog: did not build, and not for a missing definition; log: $log"
        fi
        continue
      fi
      expect_fail=1
    fi
    start=$(date +%s)
    MPM_BIN=$bin "$prog" >"$log" 2>&1
    rc=$?
    secs=$(( $(date +%s) - start ))
    if [ $expect_fail = 1 ]; then
      if [ $rc -ne 0 ]; then
        passed=$((passed + 1)); echo "  ok    $prog fails, as a stub (or an empty file) must (${secs}s)"
      else
        failed=$((failed + 1)); failures+=("$prog (stub or empty file passed its tests)")
        echo "  FAIL  $prog: a stub or an empty file passes its tests, so they cannot fail"
      fi
      continue
    fi
    n_ok=$(grep -Eo '\[  PASSED  \] [0-9]+' "$log" | grep -Eo '[0-9]+$' | tail -1)
    n_bad=$(grep -Eo '\[  FAILED  \] [0-9]+' "$log" | grep -Eo '[0-9]+$' | tail -1)
    n_ok=${n_ok:-0}; n_bad=${n_bad:-0}
    if [ $rc -eq 0 ] && [ "$n_bad" = 0 ]; then
      passed=$((passed + n_ok)); echo "  ok    $prog ($n_ok tests, ${secs}s)"
    else
      [ "$n_bad" = 0 ] && n_bad=1
      passed=$((passed + n_ok)); failed=$((failed + n_bad))
      failures+=("$prog")
      echo "  FAIL  $prog (exit $rc); log: $log"
      sed -n '1,60p' "$log" | grep -Ev '^\[ (RUN|       OK) ' | sed 's/^/        /' | head -40
    fi
  done
done
echo
for f in "${failures[@]+"${failures[@]}"}"; do echo "failed: $f"; done
echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
