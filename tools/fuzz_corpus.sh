#!/bin/bash
# Refresh tests/fuzz/corpus, the inputs make check replays, from what make
# fuzz found: merge build/fuzz/corpus and the seeds by coverage edges, then
# keep the N (default 60) inputs that, taken greedily, cover the most edges.
set -u
n=${1:-60}
bin=build/fuzz/fuzz_scene
tmp=build/fuzz/pick
[ -x $bin ] || { echo "tools/fuzz_corpus.sh: run make fuzz first" >&2; exit 1; }
rm -rf $tmp && mkdir -p $tmp/merged $tmp/again
$bin -merge=1 -use_counters=0 $tmp/merged build/fuzz/corpus build/fuzz/seeds \
  >$tmp/merge.log 2>&1 || { tail $tmp/merge.log; exit 1; }
# the control file lists the files, then "COV i edge edge ..." per file
$bin -merge=1 -use_counters=0 -merge_control_file=$tmp/control $tmp/again \
  $tmp/merged >>$tmp/merge.log 2>&1 || { tail $tmp/merge.log; exit 1; }
awk -v n="$n" '
  NR == 1 { nf = $1; next }
  NR == 2 { next }
  NR <= nf + 2 { file[NR - 3] = $0; next }
  $1 == "COV" { for (k = 3; k <= NF; k++) { has[$2, $k] = 1; edges[$2] = edges[$2] " " $k } }
  END {
    for (pick = 0; pick < n; pick++) {
      best = -1; gain = 0
      for (i in edges) {
        g = 0; m = split(edges[i], e, " ")
        for (k = 1; k <= m; k++) if (!(e[k] in got)) g++
        if (g > gain) { gain = g; best = i }
      }
      if (best < 0) break
      m = split(edges[best], e, " ")
      for (k = 1; k <= m; k++) got[e[k]] = 1
      print file[best]; delete edges[best]
    }
    for (x in got) covered++
    print covered >"'$tmp/covered'"
  }' $tmp/control >$tmp/picked
rm -rf tests/fuzz/corpus && mkdir -p tests/fuzz/corpus
while read -r f; do cp "$f" tests/fuzz/corpus/; done <$tmp/picked
total=$(grep -c . <(awk '$1 == "COV" { for (k = 3; k <= NF; k++) print $k }' $tmp/control | sort -u))
echo "tests/fuzz/corpus: $(wc -l <$tmp/picked) inputs of $(ls $tmp/merged | wc -l) merged," \
     "covering $(cat $tmp/covered) of their $total edges"
