#!/bin/bash
# Fuzz the scene reader (make fuzz): seeds from the repository's small
# scenes, libFuzzer for FUZZ_SECONDS in FUZZ_JOBS forked workers, new
# inputs into build/fuzz/corpus, crashes into build/fuzz/crashes; then the
# executions, the coverage (libFuzzer's cov and ft) and the crash count.
set -u
secs=${FUZZ_SECONDS:-600}
jobs=${FUZZ_JOBS:-2}
bin=build/fuzz/fuzz_scene
log=build/fuzz/fuzz.log
mkdir -p build/fuzz/seeds build/fuzz/corpus build/fuzz/crashes

# every scene under 8 kB of the tests, figures and benchmarks, bad ones too
find tests figures tools/bench -name '*.cfg' -size -8k | while read -r f; do
  cp "$f" "build/fuzz/seeds/$(echo "$f" | tr / _)"
done
before=$(find build/fuzz/crashes -type f | wc -l)

# -fork: workers that survive a crash (the input is kept, the run goes on)
dirs=(build/fuzz/corpus build/fuzz/seeds)
for d in tests/fuzz/corpus tests/fuzz/regressions; do [ -d $d ] && dirs+=($d); done
"$bin" "${dirs[@]}" \
  -dict=tests/fuzz/scene.dict -max_total_time="$secs" -fork="$jobs" \
  -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 -timeout=10 \
  -max_len=8192 -artifact_prefix=build/fuzz/crashes/ 2>&1 | tee "$log" |
  grep --line-buffered -E '^#[0-9]+: |INFO: (fuzzed|exiting)|CRASH|ERROR:'

last=$(grep -E '^#[0-9]+: cov:' "$log" | tail -1)
execs=$(echo "$last" | sed -E 's/^#([0-9]+):.*/\1/')
cov=$(echo "$last" | sed -E 's/.* cov: ([0-9]+).*/\1/')
ft=$(echo "$last" | sed -E 's/.* ft: ([0-9]+).*/\1/')
crashes=$(( $(find build/fuzz/crashes -type f | wc -l) - before ))
echo
echo "fuzz: ${execs:-0} executions in ${secs} s (${jobs} jobs), cov ${cov:-?}, ft ${ft:-?}," \
     "corpus $(find build/fuzz/corpus -type f | wc -l) inputs, ${crashes} new crashes" \
     "($(find build/fuzz/crashes -type f | wc -l) in build/fuzz/crashes)"
[ "$crashes" -eq 0 ]
