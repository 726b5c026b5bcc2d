#!/usr/bin/env bash
# Check the built book (make docs runs it after doxygen) for what a reader
# would see broken; each fault is named with its page:
#   - a Markdown table that did not render: a paragraph starting with "|"
#     (a "|" inside a formula in a table row splits the row);
#   - a formula macro that the book's MathJax does not know: the names are
#     read from the TeX input jax shipped in html/mathjax (its macros,
#     symbols and delimiters; extensions that load themselves count), so a
#     macro of an extension the config does not load (\tfrac, \lvert of
#     AMSmath) fails;
#   - a figure wider than MAX_IMG px (default 640) with neither a width nor
#     a linked stylesheet that caps images at max-width: 100%;
#   - a symlink under html/ (the book must work when moved or copied);
#   - any line in doxygen's warnings (its stderr, which make docs keeps).
# Usage: bash tools/check_html.sh [html dir] [warning log]
set -u
HTML=${1:-build/docs/html}
LOG=${2:-build/docs/warnings.log}
MAX_IMG=${MAX_IMG:-640}
JAX=$HTML/mathjax/jax/input/TeX/jax.js
[ -d "$HTML" ] || { echo "check_html: no $HTML (run doxygen first)" >&2; exit 1; }
faults=$(mktemp)
known=$(mktemp)
trap 'rm -f "$faults" "$known"' EXIT
bad() { echo "check_html: $*" >>"$faults"; }

if [ -s "$LOG" ]; then
    bad "doxygen warnings in $LOG:"
    sed 's/^/    /' "$LOG" >>"$faults"
fi

find "$HTML" -type l | while read -r l; do bad "symlink $l"; done

# raw table rows
grep -n -E '<p[^>]*>[[:space:]]*\|' "$HTML"/*.html | cut -c1-150 |
    while IFS= read -r l; do bad "raw Markdown table row: ${l#"$HTML"/}"; done

# formula macros against the TeX jax's tables
if [ ! -f "$JAX" ]; then
    bad "no $JAX: MathJax is not in the book"
else
    # the keys of mathchar0mi ... macros (the tables before environment:{)
    perl -0777 -ne 'if (/mathchar0mi:\{(.*?)environment:\{/s) {
            my $t = $1; print "$1\n" while $t =~ /[{,]"?(?:\\\\)?([A-Za-z]+)"?:/g }' \
        "$JAX" | sort -u >"$known"
    [ "$(wc -l <"$known")" -gt 300 ] || bad "could not read the macro tables of $JAX"
    for f in "$HTML"/*.html; do
        # the formulas, \( \) and \[ \], outside code fragments
        perl -0777 -ne 's/<div class="line">.*?<\/div>//g;
            while (/\\\((.*?)\\\)|\\\[(.*?)\\\]/gs) { my $m = defined $1 ? $1 : $2;
                print "$1\n" while $m =~ /\\([A-Za-z]+)/g }' "$f" | sort -u |
            comm -23 - "$known" | while read -r m; do
                bad "${f#"$HTML"/}: formula macro \\$m is unknown to MathJax's TeX input"
            done
    done
fi

# wide images (the PNG's width from its header)
capped() {  # capped PAGE: a stylesheet it links sets img { max-width: 100% }
    local css
    for css in $(grep -o '<link href="[^"]*\.css"' "$1" | sed 's/<link href="//; s/"$//'); do
        [ -f "$HTML/$css" ] && tr -d '\n' <"$HTML/$css" |
            grep -q -E '(^|[},[:space:]])img[^{]*\{[^}]*max-width:[[:space:]]*100%' && return 0
    done
    return 1
}
for f in "$HTML"/*.html; do
    grep -o '<img [^>]*>' "$f" | grep -v ' width=' | sed -n 's/.*src="\([^"]*\.png\)".*/\1/p' |
        while read -r img; do
            [ -f "$HTML/$img" ] || continue
            w=$(od -An -tu1 -j16 -N4 "$HTML/$img" | awk '{ print (($1 * 256 + $2) * 256 + $3) * 256 + $4 }')
            if [ "$w" -gt "$MAX_IMG" ] && ! capped "$f"; then
                bad "${f#"$HTML"/}: $img is $w px wide, with no width and no max-width"
            fi
        done
done

if [ -s "$faults" ]; then
    cat "$faults" >&2
    echo "check_html: $(grep -c '^check_html' "$faults") fault(s) in $HTML" >&2
    exit 1
fi
echo "check_html: $HTML clean"
