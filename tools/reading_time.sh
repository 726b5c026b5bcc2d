#!/usr/bin/env bash
# Reading time of each page of the book: minutes = words / 180 + code lines
# / 15, the measure of issue 26 ("a chapter a student reads in one sitting,
# about 45 minutes").
#
#   bash tools/reading_time.sh [chapters dir]
#
# (default: chapters; a relative path is from the repository root).
#
# Prints one line per page of chapters/*.md in book order (the front page's
# \subpage list, then the other pages by file name): file, words, code
# lines, minutes, title; then the total.
#
# What counts:
#   - code lines are the lines of code the page shows:
#       \snippet FILE TAG     the lines between the two "/// [TAG]" markers
#                             of FILE, found in src/, chapters/, tests/ or
#                             build/figures/ (Doxyfile's EXAMPLE_PATH; a
#                             figure's table is there once it is drawn);
#       \verbinclude FILE     (and \include) every line of FILE;
#       \verbatim ... \endverbatim, \code ... \endcode, ``` or ~~~ fences;
#       an indented code block: a line indented 4 or more spaces beyond the
#       text of the list item it sits in (0 outside lists), after a blank
#       line or another such line, outside a \f[ ... \f] formula;
#   - words are the other lines' whitespace-separated tokens with a letter
#     or digit in them, once Doxygen's commands (\ref, \f$, ...), anchors
#     ({#...}, \anchor NAME) and link targets (...) are taken out; a
#     formula's tokens count as words, table rows too. Blank lines and
#     [TOC] count nothing.
# SHOW_CODE=1 prints the indented lines taken for code to stderr, to check.
# A snippet, file or marker that cannot be found is reported on stderr and
# makes the exit status 1.
set -u
cd "$(dirname "$0")/.." || exit 1
CHAPTERS=${1:-chapters}
[ -d "$CHAPTERS" ] || { echo "reading_time: no folder $CHAPTERS" >&2; exit 1; }

perl -e '
use strict; use warnings;
my $dir = shift;
my @files = sort glob("$dir/*.md");
my (%file_of, %title_of, @order, $fault);
for my $f (@files) {
    open my $h, "<", $f or die "$f: $!";
    my $first = <$h> // ""; close $h;
    my ($name) = $first =~ /\{#(\w+)\}/;
    ($name) = $first =~ /^\s*[\\@]page\s+(\w+)/ unless defined $name;
    $name //= $f;
    $file_of{$name} = $f;
    (my $t = $first) =~ s/^#\s*|\s*\{#\w+\}\s*$//g; $t =~ s/^\s*[\\@]page\s+\w+\s*//; chomp $t;
    $title_of{$f} = $t;
}
# book order: index.md (the main page), its \subpages, then the rest
my ($index) = grep { m{/index\.md$} } @files;
my %seen;
if ($index) {
    push @order, $index; $seen{$index} = 1;
    open my $h, "<", $index or die; local $/; my $t = <$h>; close $h;
    while ($t =~ /[\\@]subpage\s+(\w+)/g) {
        my $f = $file_of{$1} or next;
        push @order, $f unless $seen{$f}++;
    }
}
push @order, grep { !$seen{$_}++ } @files;

sub find_example {
    my $p = shift;
    for my $d ("src", "chapters", "tests", "build/figures") { return "$d/$p" if -f "$d/$p" }
    return undef;
}
sub snippet_lines {
    my ($where, $p, $tag) = @_;
    my $f = find_example($p);
    unless ($f) { warn "reading_time: $where: no file $p for \\snippet\n"; $fault = 1; return 0 }
    open my $h, "<", $f or die; my ($in, $n, $found) = (0, 0, 0);
    while (<$h>) {
        if (/^\s*\/\/\/\s*\[\Q$tag\E\]\s*$/) { $found++; $in = !$in; next }
        $n++ if $in;
    }
    close $h;
    if ($found < 2) { warn "reading_time: $where: no pair of markers [$tag] in $f\n"; $fault = 1 }
    return $n;
}
sub file_lines {
    my ($where, $p) = @_;
    my $f = find_example($p);
    unless ($f) { warn "reading_time: $where: no file $p\n"; $fault = 1; return 0 }
    open my $h, "<", $f or die; my $n = 0; $n++ while <$h>; close $h; return $n;
}

my ($tw, $tc, $tm) = (0, 0, 0);
printf "%-32s %6s %5s %7s  %s\n", "page", "words", "code", "minutes", "title";
for my $f (@order) {
    open my $h, "<", $f or die "$f: $!";
    my ($words, $code) = (0, 0);
    my ($block, $math, $indented, $prev_blank, $list) = ("", 0, 0, 1, 0);
    while (my $l = <$h>) {
        chomp $l; my $where = "$f:$.";
        if ($block) {
            if    ($block eq "verbatim" && $l =~ /[\\@]endverbatim/) { $block = "" }
            elsif ($block eq "code" && $l =~ /[\\@]endcode/)         { $block = "" }
            elsif ($block =~ /^[`~]/ && $l =~ /^\s*\Q$block\E/)      { $block = "" }
            else  { $code++ }
            next;
        }
        if ($l =~ /^\s*$/) { $prev_blank = 1; next }   # a code block goes on past it
        my ($ind) = map { length } $l =~ /^( *)/;
        # list items: their text starts after the marker
        if (!$math && $l =~ /^( *)([-*+]|\d+\.)( +)\S/ && !($indented && $ind >= $list + 4)) {
            $list = length($1) + length($2) + length($3);
        } elsif (!$math && $ind == 0) {
            $list = 0;
        }
        if (!$math && ($prev_blank || $indented) && $ind >= $list + 4
                && $l !~ /^\s*[\\@](snippet|verbinclude|include)\b/) {
            $code++; $indented = 1; $prev_blank = 0;
            print STDERR "$where: code: $l\n" if $ENV{SHOW_CODE}; next;
        }
        $indented = 0; $prev_blank = 0;
        if ($l =~ /^\s*[\\@]snippet(?:\{[^}]*\})?\s+(\S+)\s+(\S+)/) { $code += snippet_lines($where, $1, $2); next }
        if ($l =~ /^\s*[\\@](?:verbinclude|include)(?:\{[^}]*\})?\s+(\S+)/) { $code += file_lines($where, $1); next }
        if ($l =~ /^\s*[\\@]verbatim\b/) { $block = "verbatim"; next }
        if ($l =~ /^\s*[\\@]code\b/)     { $block = "code"; next }
        if ($l =~ /^\s*(```+|~~~+)/)     { $block = $1; next }
        # formulas: \f[ ... \f] may span lines
        my $t = $l;
        my $opens = () = $t =~ /\\f\[/g; my $closes = () = $t =~ /\\f\]/g;
        $math = 1 if $opens > $closes; $math = 0 if $closes > $opens;
        next if $t =~ /^\s*\[TOC\]\s*$/;
        $t =~ s/\{#[\w-]+\}//g;                 # anchors
        $t =~ s/\]\([^)]*\)/]/g;                # link targets
        $t =~ s/[\\@]anchor\s+\S+//g;         # an anchor is not read
        $t =~ s/[\\@](?:ref|subpage|page|snippet|image)\b//g;
        $t =~ s/\\f[\$\[\]]//g;                 # formula delimiters
        $t =~ s/<[^>]*>//g;                     # HTML tags
        $words += grep { /[A-Za-z0-9]/ } split " ", $t;
    }
    close $h;
    my $min = $words / 180 + $code / 15;
    ($tw, $tc, $tm) = ($tw + $words, $tc + $code, $tm + $min);
    (my $short = $f) =~ s{^.*/}{};
    printf "%-32s %6d %5d %7.0f  %s\n", $short, $words, $code, $min, $title_of{$f};
}
printf "%-32s %6d %5d %7.0f\n", "total", $tw, $tc, $tm;
exit($fault ? 1 : 0);
' "$CHAPTERS"
