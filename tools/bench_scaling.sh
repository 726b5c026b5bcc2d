#!/usr/bin/env bash
# The scaling curve of issue 29: the time loop on 1, 2, 4, 8, 12 and 16
# threads (THREAD_LIST), the same build, the runs of one round interleaved
# (1, 2, 4, ..., then again: a neighbour that slows one round slows all its
# counts).  Scenes:
#   disks 200k   build/stage1/mpm tools/bench/disks_200k.cfg (MUSL)
#   disks 2M     the same disks on a grid sqrt(10) finer (1417 x 1417 cells,
#                about 2.0 M points; written to WORK)
#   dcb crack    build/stage3/mpm tools/bench/dcb_crack.cfg, indexed search
#   touching     build/stage4/mpm tools/bench/disks_50k_touching.cfg
#   xefg plate   build/stage6/mpm, tests/6-xefg/scenes/plate_crack.cfg at
#                h = 0.25 mm (as tools/bench_threads.sh writes it)
#   disks gimp   build/stage8/mpm, the 200k disks with run.shape=gimp
#                (about three times the instructions per point of linear,
#                the same data: more arithmetic for each byte moved)
# Printed per scene and thread count: the best time loop of REPEAT rounds
# (the program's own "N steps in T s"), particle-steps per second, the
# speed-up over one thread and the parallel efficiency (speed-up / threads).
# The issue's goal: 12x or more at 16 threads for MPM on a 16-core machine.
# Meant for a machine with 16 cores (the device machine); on 2 cores run it
# with THREAD_LIST="1 2".  Environment: THREAD_LIST, REPEAT (default 2),
# SCENES (labels to run, default all), BIN (a folder holding stage1 ...
# stage8 binaries named mpm1 ... mpm8; default build/stageN/mpm), WORK.
set -u
cd "$(dirname "$0")/.." || exit 1
# shellcheck source=tools/bench_lib.sh
. tools/bench_lib.sh
THREAD_LIST=${THREAD_LIST:-1 2 4 8 12 16}
REPEAT=${REPEAT:-2}
SCENES=${SCENES:-disks_200k disks_2M dcb_crack touching xefg_plate disks_gimp}
if [ -z "${WORK:-}" ]; then
    WORK=$(mktemp -d "${TMPDIR:-/tmp}/mpm-scaling.XXXXXX")
    trap 'rm -rf "$WORK"' EXIT
fi
bin() { if [ -n "${BIN:-}" ]; then echo "$BIN/mpm$1"; else echo "build/stage$1/mpm"; fi; }

sed -E 's/cells = \[448, 448\]; cell_size = \[[0-9.]+, [0-9.]+\]/cells = [1417, 1417]; cell_size = [0.000705716302046577, 0.000705716302046577]/' \
    tools/bench/disks_200k.cfg >"$WORK/disks_2M.cfg"
grep -q 'cells = \[1417, 1417\]' "$WORK/disks_2M.cfg" || echo "scaling: the 2M scene's grid line did not change" >&2
sed -E 's/cells = \[14, 10\]; cell_size = \[1.0, 1.0\]/cells = [56, 40]; cell_size = [0.25, 0.25]/' \
    tests/6-xefg/scenes/plate_crack.cfg >"$WORK/xefg_plate.cfg"

# label | stage | scene | overrides | N steps
cases=(
    "disks_200k|1|tools/bench/disks_200k.cfg|run.update=musl|100"
    "disks_2M|1|$WORK/disks_2M.cfg|run.update=musl|20"
    "dcb_crack|3|tools/bench/dcb_crack.cfg|run.update=musl run.crack_search=indexed|300"
    "touching|4|tools/bench/disks_50k_touching.cfg|run.update=musl|200"
    "xefg_plate|6|$WORK/xefg_plate.cfg|run.snapshots=0|60"
    "disks_gimp|8|tools/bench/disks_200k.cfg|run.update=musl run.shape=gimp|40"
)

printf 'scaling: %s cores (%s), threads %s, best of %s rounds; load before: %s\n' \
    "$(getconf _NPROCESSORS_ONLN)" "$(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -1)" "$THREAD_LIST" \
    "$REPEAT" "$(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-11s %8s %4s %4s %9s %10s %7s %5s\n' scene points N thr "loop s" "p-steps/s" speedup eff
for c in "${cases[@]}"; do
    IFS='|' read -r label st scene extra n <<<"$c"
    case " $SCENES " in *" $label "*) ;; *) continue ;; esac
    mpm=$(bin "$st")
    if [ ! -x "$mpm" ]; then
        printf '%-11s %s not built: skipped\n' "$label" "$mpm"
        continue
    fi
    pts="" time=""
    # shellcheck disable=SC2086
    read -r pts time < <(scene_steps "$mpm" "$scene" "$n" "$WORK" $extra)
    if [ -z "$pts" ]; then
        printf '%-11s cannot read %s\n' "$label" "$scene"
        continue
    fi
    declare -A best=()
    for ((r = 0; r < REPEAT; r++)); do
        for th in $THREAD_LIST; do
            # shellcheck disable=SC2086
            s=$("$mpm" "$scene" -q -o "$WORK/run" run.time="$time" run.threads="$th" $extra 2>"$WORK/err" |
                sed -nE 's/.*steps in ([0-9.]+) s.*/\1/p')
            if [ -z "$s" ]; then
                printf '%-11s %d threads failed: %s\n' "$label" "$th" "$(tail -1 "$WORK/err")"
                continue
            fi
            if [ -z "${best[$th]:-}" ] || awk -v a="$s" -v b="${best[$th]}" 'BEGIN { exit !(a < b) }'; then
                best[$th]=$s
            fi
        done
    done
    t1=${best[1]:-}
    for th in $THREAD_LIST; do
        [ -n "${best[$th]:-}" ] || continue
        awk -v l="$label" -v p="$pts" -v n="$n" -v th="$th" -v s="${best[$th]}" -v t1="$t1" 'BEGIN {
            x = (t1 != "" && s > 0) ? t1 / s : 0
            printf "%-11s %8d %4d %4d %9.3f %10.3g %7.2f %5.2f\n", l, p, n, th, s,
                (s > 0 ? p * n / s : 0), x, x / th }'
    done
    unset best
done
