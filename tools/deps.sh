#!/bin/sh
# Bring the Debian packages a job needs, or say exactly which are missing.
#   sh tools/deps.sh test      compiler, make, libconfig, cmocka, LAPACKE
#   sh tools/deps.sh figures   the above, gnuplot and valgrind (fig-crossing
#                              counts instructions)
#   sh tools/deps.sh docs      doxygen, MathJax, and what the figures need
#   sh tools/deps.sh fuzz      the above test packages, clang and libFuzzer's
#                              runtime (make fuzz)
set -u
job=${1:-test}
base="gcc make libc6-dev libconfig-dev libcmocka-dev liblapacke-dev"
case "$job" in
  test) want="$base" ;;
  figures) want="$base gnuplot-nox valgrind" ;;
  docs) want="doxygen libjs-mathjax gnuplot-nox valgrind $base" ;;
  fuzz) want="$base clang libclang-rt-14-dev libomp-14-dev" ;;
  all) want="$base gnuplot-nox valgrind doxygen libjs-mathjax clang libclang-rt-14-dev libomp-14-dev" ;;
  *) echo "usage: sh tools/deps.sh test|figures|docs|fuzz|all" >&2; exit 2 ;;
esac

if ! command -v dpkg-query >/dev/null 2>&1; then
  echo "tools/deps.sh: not a Debian system; make sure these (Debian names) are installed: $want" >&2
  exit 0
fi
missing=""
for p in $want; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" ||
    missing="$missing $p"
done
[ -z "$missing" ] && exit 0

if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
  echo "tools/deps.sh: installing$missing" >&2
  export DEBIAN_FRONTEND=noninteractive
  if apt-get update -qq && apt-get install -y -qq --no-install-recommends $missing >/dev/null; then
    exit 0
  fi
  echo "tools/deps.sh: apt-get could not install$missing" >&2
fi
echo "tools/deps.sh: missing Debian packages:$missing" >&2
echo "  install them with:  sudo apt-get install$missing" >&2
exit 1
