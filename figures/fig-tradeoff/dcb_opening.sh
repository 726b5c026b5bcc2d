#!/usr/bin/env bash
# Build figures/fig-tradeoff/dcb_opening.c against stage N's library and the
# tests' Q4 solver: bash figures/fig-tradeoff/dcb_opening.sh N OUTPUT.
# make fig-tradeoff (stage 5) and make fig-xefg-dcb (stage 6, where XEFG's
# scenes load) both call it.
set -u
n=$1 out=$2
make --no-print-directory build/stage$n/libmpm.a build/shared/tests/support/q4.o >/dev/null || exit 1
cc -std=c11 -Wall -Wextra -Werror -Wshadow -Wmissing-prototypes -Wundef \
    -D_POSIX_C_SOURCE=200809L -O2 $(printf -- '-I%s ' $(ls -d src/[0-9]-* | awk -F/ -v n="$n" '$2 + 0 <= n')) \
    -Itests/support figures/fig-tradeoff/dcb_opening.c build/shared/tests/support/q4.o \
    build/stage$n/libmpm.a -llapacke -lconfig -lm -fopenmp -o "$out"
