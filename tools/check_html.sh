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
#   - raw markup in a page's text: a Doxygen command that did not run
#     (\section, \subpage, \verbatim, \ref, \image, ... in either @ or \
#     form; \f$, \f[, \f] of a formula) or an HTML table shown as text
#     (&lt;table), an escaped inline tag (&lt;tt&gt;: a code span in a
#     heading), a bold's ** left as they are, or a backquote that did not
#     make inline code (a span
#     split over lines, or one that starts with a quote). Code blocks are skipped (<pre> and the lines of a
#     <div class="fragment">: they quote files and output as they are);
#     inline code is not (the book shows no Doxygen syntax as code, and a
#     formula in backquotes shows raw);
#   - a quoted file that showed nothing: an empty code block (\dontinclude's
#     \skip, \until or \line found no line with its pattern, say after a
#     figure script changed what it prints, or \verbinclude read an empty
#     file), which Doxygen does not warn about;
#   - a page of chapters/ missing from the side tree (navtreedata.js), out
#     of book order (the front page's \subpage list, then any other page,
#     before every other entry), or listed under another title than its
#     page's;
#   - a code line cut off: longer than MAX_CODE characters (default 79)
#     in a box that the page's stylesheets do not wrap. At the book's width
#     (a 1280 px window, the side tree at its 250 px) the text column is
#     990 px wide and 715 px beside the contents box: 79 characters of the
#     14.7 px monospace of a <pre> block (DejaVu Sans Mono, 0.6 em each),
#     91 of the 13 px of a fragment line. A box wraps when the last rule
#     that names it (pre.fragment, div.line; pre.X or pre for another
#     <pre>) sets white-space: pre-wrap and overflow-wrap (or word-wrap):
#     anywhere or break-word; chapters/book.css does for both;
#   - a figure wider than MAX_IMG px (default 640) with neither a width nor
#     a linked stylesheet that caps images at max-width: 100%;
#   - a symlink under html/ (the book must work when moved or copied);
#   - a control character in chapters/*.md (a script's "\ref" or "\f$"
#     written as CR or form feed);
#   - any line in doxygen's warnings (its stderr, which make docs keeps).
# Usage: bash tools/check_html.sh [html dir] [warning log] [chapters dir]
set -u
HTML=${1:-build/docs/html}
LOG=${2:-build/docs/warnings.log}
CHAPTERS=${3:-chapters}
MAX_IMG=${MAX_IMG:-640}
MAX_CODE=${MAX_CODE:-79}
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

# control characters in the chapters' source: a \r, \f, \b or \v that a
# script's string escape made of \ref, \f$, \begin, \vec (a CR read back
# in text mode turns into a line break, and the command into plain text)
grep -n -P '[\x00-\x08\x0b-\x1f\x7f]' "$CHAPTERS"/*.md 2>/dev/null | cut -c1-150 |
    while IFS= read -r l; do bad "control character in a chapter's source: $l"; done

# raw table rows
grep -n -E '<p[^>]*>[[:space:]]*\|' "$HTML"/*.html | cut -c1-150 |
    while IFS= read -r l; do bad "raw Markdown table row: ${l#"$HTML"/}"; done

# empty code blocks: an include that selected no line
grep -n -o -E '<div class="fragment">[[:space:]]*</div>|<pre class="fragment">[[:space:]]*</pre>' "$HTML"/*.html |
    while IFS= read -r l; do bad "empty code block (an include of a missing or empty file, or whose patterns matched no line): ${l#"$HTML"/}"; done

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

# raw markup in the text, outside scripts, comments and code blocks
for f in "$HTML"/*.html; do
    perl -0777 -ne 's/<script\b.*?<\/script>|<!--.*?-->|<pre\b.*?<\/pre>|<div class="line">.*?<\/div>//gs;
        s/<[^>]*>//g; s/\s+/ /g;
        while (/\\f\$.*?\\f\$|\\f\[.*?\\f\]|\\f[\$\[\]]|&lt;table|&lt;\/?(?:tt|code|em|b|i|strong)&gt;|`|[\\@](?:section|subsection|subsubsection|page|subpage|mainpage|ref|verbatim|endverbatim|code|endcode|snippet|image)\b/g) {
            my $at = $-[0] < 30 ? 0 : $-[0] - 30; print substr($_, $at, 80), "\n" }' "$f" |
        while IFS= read -r l; do bad "${f#"$HTML"/}: raw markup in the text: ...$l..."; done
done
# a bold's ** left as they are, in the book's pages (the code's pages, and
# the declarations in a page's tooltips, show C's pointers to pointers)
for f in "$HTML"/*.html; do
    case ${f##*/} in *_8*|struct*|union*|dir_*|globals*|functions*|files*|annotated*|classes*) continue ;; esac
    perl -0777 -ne 's/<script\b.*?<\/script>|<!--.*?-->|<pre\b.*?<\/pre>|<div class="line">.*?<\/div>|<div class="ttdeci">.*?<\/div>//gs;
        s/<[^>]*>//g; s/\s+/ /g;
        while (/\*\*/g) { my $at = $-[0] < 30 ? 0 : $-[0] - 30; print substr($_, $at, 80), "\n" }' "$f" |
        while IFS= read -r l; do bad "${f#"$HTML"/}: bold markup left as text: ...$l..."; done
done

# the side tree lists every page of chapters/, in book order, first
if [ ! -d "$CHAPTERS" ]; then
    bad "no $CHAPTERS: cannot check the side tree"
elif [ ! -f "$HTML/navtreedata.js" ]; then
    bad "no $HTML/navtreedata.js: the book has no side tree"
else
    # the book's order: the main page's \subpage list, then the other pages
    order=$(perl -ne 'BEGIN { @ARGV = sort { ($b =~ /index\.md$/) <=> ($a =~ /index\.md$/) || $a cmp $b } @ARGV }
        push @p, $1 if $. == 1 && /\{#(\w+)\}/ || /^\s*[\\@]page\s+(\w+)/;
        push @p, $1 while /[\\@]subpage\s+(\w+)/g; close ARGV if eof;
        END { my %s; print "$_\n" for grep { $_ ne "mainpage" && !$s{$_}++ } @p }' "$CHAPTERS"/*.md)
    # the tree's entries below the root, but for the main page: file, title
    tree=$(perl -0777 -ne '/var NAVTREE =(.*?)\n\];/s or exit; my $t = $1;
        while ($t =~ /\[ "((?:[^"\\]|\\.)*)", "([^"#]*)[^"]*"/g) { my ($n, $u) = ($1, $2);
            $n =~ s/\\(.)/$1/g; print "$u\t$n\n" unless $u eq "index.html" }' "$HTML/navtreedata.js" | awk -F'\t' '!seen[$1]++')
    n=$(echo "$order" | wc -w); last=0; prev=
    for p in $order; do
        if [ ! -f "$HTML/$p.html" ]; then bad "side tree: no page $p.html for $p of $CHAPTERS"; continue; fi
        title=$(perl -0777 -ne 'print $1 if /<div class="title">(.*?)<\/div>/s' "$HTML/$p.html" |
            sed 's/<[^>]*>//g; s/&amp;/\&/g; s/&lt;/</g; s/&gt;/>/g; s/&quot;/"/g; s/&#39;/'\''/g; s/^ *//; s/ *$//')
        at=$(printf '%s\n' "$tree" | awk -F'\t' -v u="$p.html" '$1 == u { print NR "\t" $2; exit }')
        k=${at%%$'\t'*}
        if [ -z "$at" ]; then
            bad "side tree: $p.html (\"$title\") is not in $HTML/navtreedata.js (LAYOUT_FILE)"
            continue
        elif [ "$k" -gt "$n" ]; then
            bad "side tree: $p.html is entry $k, after entries that are not chapters"
        elif [ "$k" -lt "$last" ]; then
            bad "side tree: $p.html comes before $prev.html, against the book's order"
        fi
        [ "${at#*$'\t'}" = "$title" ] ||
            bad "side tree: $p.html is listed as \"${at#*$'\t'}\", its page is titled \"$title\""
        last=$k; prev=$p
    done
fi

# code lines longer than MAX_CODE in boxes that do not wrap
for f in "$HTML"/*.html; do
    css=$(grep -o '<link href="[^"]*\.css"' "$f" | sed 's/<link href="//; s/"$//' |
        while read -r c; do [ -f "$HTML/$c" ] && echo "$HTML/$c"; done)
    # shellcheck disable=SC2086
    MAX_CODE=$MAX_CODE perl -0777 -e 'binmode STDOUT, ":utf8";
        my (%ws, %ow);  # the last white-space and overflow-wrap set for a selector
        for my $c (@ARGV[1..$#ARGV]) { open my $h, "<", $c or next; local $/; my $t = <$h>;
            $t =~ s/\/\*.*?\*\///gs;
            while ($t =~ /([^{}]+)\{([^}]*)\}/g) { my ($sel, $d) = ($1, $2);
                for my $s (map { s/^\s+|\s+$//gr } split /,/, $sel) {
                    $ws{$s} = $1 while $d =~ /(?:^|;)\s*white-space\s*:\s*([-\w]+)/g;
                    $ow{$s} = $1 while $d =~ /(?:^|;)\s*(?:overflow-wrap|word-wrap)\s*:\s*([-\w]+)/g } } }
        my $wraps = sub { my $s = shift; ($ws{$s} // "") =~ /^(pre-wrap|break-spaces)$/
            && ($ow{$s} // "") =~ /^(anywhere|break-word)$/ };
        open my $h, "<:utf8", $ARGV[0] or die; local $/; my $t = <$h>;
        my @lines;
        while ($t =~ /<pre\b([^>]*)>(.*?)<\/pre>/gs) { my ($a, $b) = ($1, $2);
            my $k = $a =~ /class="(\w+)/ ? "pre.$1" : "pre"; push @lines, map { [$k, $_] } split /\n/, $b }
        push @lines, ["div.line", $1] while $t =~ /<div class="line">(.*?)<\/div>/gs;
        for (@lines) { my ($k, $s) = @$_; next if $wraps->($k);
            $s =~ s/<[^>]*>//g; $s =~ s/&lt;/</g; $s =~ s/&gt;/>/g; $s =~ s/&quot;/"/g;
            $s =~ s/&#(\d+);/chr $1/ge; $s =~ s/&amp;/&/g; $s =~ s/\s+$//;
            printf "%d characters in %s: %s...\n", length $s, $k, substr($s, 0, 50)
                if length $s > $ENV{MAX_CODE} }' "$f" $css |
        while IFS= read -r l; do bad "${f#"$HTML"/}: code line cut off (over $MAX_CODE characters, in a box that does not wrap): $l"; done
done

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
