#!/usr/bin/env bash
# make fig-crossing: what Task 1 (the crossing step) costs with each crossing
# search of stage 3, in instructions per particle-step (callgrind, so the
# figure is the same on every machine), on the DCB of chapter 2 at three
# refinements with the crack 50 mm long throughout; and the whole step with
# the crack over the same points without it.
#
# Writes build/figures/fig-crossing.png and build/figures/fig-crossing.csv
# (points, search, whole step, Task 1). About two minutes.
. "$(dirname "$0")/../lib.sh"
fig_mpm 3
fig_need valgrind valgrind
csv=$OUT/fig-crossing.csv
echo "points,search,whole,task1" >"$csv"
for scene in figures/fig1/dcb_full.cfg tools/bench/dcb_crack_2x.cfg tools/bench/dcb_crack.cfg; do
    for search in plain screened indexed; do
        read -r pts whole t1 < <(bash tools/task1_cost.sh "$MPM" "$scene" "$search") || exit 1
        echo "$pts,$search,$whole,$t1" >>"$csv"
        echo "fig-crossing: $scene $search: $pts points, Task 1 $t1, whole step $whole"
    done
done
# one block per search (gnuplot's index), two blank lines apart
dat=$OUT/fig-crossing.dat
for search in plain screened indexed; do
    awk -F, -v s="$search" '$2 == s' "$csv"
    printf '\n\n'
done >"$dat"
fig_need_gnuplot "$csv written, no plot"
gnuplot -e "data='$dat'; out='$OUT/fig-crossing.png'" figures/fig-crossing/plot.gp || exit 1
echo "fig-crossing: wrote $OUT/fig-crossing.png and $csv"
