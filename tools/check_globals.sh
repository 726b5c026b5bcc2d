#!/usr/bin/env bash
# make check: no global mutable state in the solver (the house rule). Lists
# every object's symbols that live in writable sections (.data, .bss, their
# thread-local forms, and common symbols; not .data.rel.ro, which is read-only
# once the program is loaded) and fails, naming object and symbol, for any
# but two, which C and OpenMP leave no other place for:
#   - stop_signal (src/0-base/main.c): the flag the SIGINT / SIGTERM handler
#     sets, a volatile sig_atomic_t at file scope (C11 7.14.1.1);
#   - .gomp_critical_user_NAME: the lock GCC makes for a named
#     "#pragma omp critical (NAME)".
# Usage: bash tools/check_globals.sh OBJECT... (make check passes the release
# objects of src/).
set -u
[ $# -gt 0 ] || { echo "check_globals: no objects given" >&2; exit 1; }
command -v objdump >/dev/null 2>&1 || { echo "check_globals: objdump not found (binutils)" >&2; exit 1; }
bad=0
for o in "$@"; do
    [ -f "$o" ] || { echo "check_globals: $o: no such object" >&2; exit 1; }
    # objdump -t: VALUE FLAGS SECTION SIZE NAME; a section's own symbol
    # (flag d) bears the section's name
    found=$(objdump -t "$o" | awk '
        {
            for (i = 2; i < NF; i++)
                if ($i ~ /^(\.data|\.bss|\.tdata|\.tbss)(\.|$)/ || $i == "*COM*") {
                    if ($i ~ /^\.data\.rel\.ro/ || $NF == $i) next
                    print $i, $NF; next
                }
        }' | grep -Ev ' (stop_signal|\.gomp_critical_user_[A-Za-z0-9_]+)$')
    if [ -n "$found" ]; then
        while read -r sec sym; do
            echo "check_globals: $o: $sym is mutable state at file scope (section $sec)"
        done <<<"$found"
        bad=1
    fi
done
[ $bad = 0 ] || { echo "check_globals: the solver keeps no global mutable state: pass it in a struct (Sim, a stage's state)"; exit 1; }
echo "check_globals: $# objects, no global mutable state"
