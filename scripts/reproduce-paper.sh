#!/usr/bin/env bash
# Reproduces the paper's ensembles (Maher, Stillinger & Torquato, Sec. III A and the appendix
# tables): sbgen packings at each p with sbgen's defaults (the paper's protocol, README
# "sbgen"), run in parallel over the cores, then one sbanalyze job over all of them (one
# ensemble per p), the table of ours beside the paper's (scripts/reproduction_table.py) and the
# figures (python3 -m sbpack.plot). Resumable: packings already written are kept, a run stopped
# by a signal continues from its checkpoint.
#
#   scripts/reproduce-paper.sh [--n N] [--count C] [--p-list "P1 P2 ..."] [--jobs J]
#                              [--work DIR] [--table FILE] [--compute LIST]
#                              [--sbgen-options "..."] [--build DIR] [--doc FILE]
#                              [--section TITLE] [--figure-with "RESULTS.h5 ..."]
# Defaults: N = 1000, C = 5, the paper's 12 p values, J = nproc, DIR = build/reproduce,
# FILE = DIR/reproduction.md, LIST = contacts (add pores,transport,hyper for the rest).
# --doc FILE also writes the tables into a document, as the section of this N (the command,
# date and commit above them, the figure against p beside it as reproduction-versus-p-nN.png),
# e.g. docs/reproduction.md: a rerun replaces that section alone, between its marks.
# --section TITLE names the section instead (its marks and its figure's name follow the title),
# e.g. "Beyond the paper's range, N = 1000" for p outside the paper's table (issue 68).
# --figure-with adds other sbanalyze results to the figures (not the tables), e.g. the paper's
# range (docs/reproduction-results.h5) beside the section's, so that the curves span both.
# The CI slice (tests/CMakeLists.txt, reproduce_paper_small): --n 40 --count 2 --p-list "1 1.5"
# --sbgen-options "--pressure-final 1e8 --gamma-slow 1e-2".
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# The command as it can be pasted again: arguments other than plain words single-quoted.
command="scripts/reproduce-paper.sh"
for arg in "$@"; do
    if [[ $arg =~ ^[A-Za-z0-9_./=:,+-]+$ ]]; then command+=" $arg"; else command+=" '${arg//\'/\'\\\'\'}'"; fi
done
n=1000 count=5 jobs=$(nproc) work=$root/build/reproduce table="" compute=contacts,order extra="" doc=""
section="" figure_with=""
build=$root/build
plist="0.85 0.9 0.95 0.975 1 1.025 1.05 1.1 1.2 1.3 1.4 1.5"
usage() { sed -n '2,23p' "$0" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
    case $1 in
        --n) n=$2; shift 2 ;;
        --count) count=$2; shift 2 ;;
        --p-list) plist=$2; shift 2 ;;
        --jobs) jobs=$2; shift 2 ;;
        --work) work=$2; shift 2 ;;
        --table) table=$2; shift 2 ;;
        --compute) compute=$2; shift 2 ;;
        --sbgen-options) extra=$2; shift 2 ;;
        --build) build=$2; shift 2 ;;
        --doc) doc=$2; shift 2 ;;
        --section) section=$2; shift 2 ;;
        --figure-with) figure_with=$2; shift 2 ;;
        -h|--help) usage; exit 0 ;;
        *) echo "reproduce-paper.sh: unknown option '$1' (see --help)" >&2; exit 1 ;;
    esac
done
table=${table:-$work/reproduction.md}
mkdir -p "$work/packings" "$work/logs"
for bin in generator/sbgen analysis/sbanalyze; do
    [ -x "$build/$bin" ] || { echo "reproduce-paper.sh: $build/$bin missing: run scripts/build.sh" >&2; exit 1; }
done

# One line per packing still to make: "p seed".
for p in $plist; do
    for seed in $(seq 1 "$count"); do
        [ -f "$work/packings/p$p-n$n-s$seed.h5" ] || echo "$p $seed"
    done
done | SBGEN="$build/generator/sbgen" WORK="$work" N="$n" EXTRA="$extra" \
    xargs -r -P "$jobs" -L 1 bash -c '
        name=p$0-n$N-s$1 out=$WORK/packings/p$0-n$N-s$1.h5 ck=$WORK/packings/p$0-n$N-s$1.checkpoint.h5
        if [ -f "$ck" ]; then set -- --resume "$ck"; else set -- --p "$0" --n "$N" --seed "$1" $EXTRA; fi
        "$SBGEN" "$@" --checkpoint "$ck" --checkpoint-interval 300 --out "$out" \
            2> "$WORK/logs/$name.log" # its progress lines and warnings
        rc=$?
        [ $rc -eq 0 ] && rm -f "$ck"
        [ $rc -eq 0 ] || [ $rc -eq 3 ] || { echo "sbgen $name: exit $rc (log $WORK/logs/$name.log)" >&2; exit 255; }
        echo "sbgen $name: done" >&2'

files=()
for p in $plist; do
    for seed in $(seq 1 "$count"); do files+=("$work/packings/p$p-n$n-s$seed.h5"); done
done
"$build/analysis/sbanalyze" "${files[@]}" --compute "$compute" --out "$work/results.h5" --quiet
/usr/bin/python3 "$root/scripts/reproduction_table.py" "$work/results.h5" \
    "$root/data/mst-reference-values.csv" "$root/data/jst2010-reference-values.csv" > "$table"
echo "reproduce-paper.sh: table $table" >&2
# shellcheck disable=SC2086 # --figure-with is a list of files
PYTHONPATH="$build/python${PYTHONPATH:+:$PYTHONPATH}" /usr/bin/python3 -m sbpack.plot \
    "$work/results.h5" $figure_with --out "$work/figures" > /dev/null \
    || { echo "reproduce-paper.sh: the figures failed (above); the table stands" >&2; exit 1; }
echo "reproduce-paper.sh: figures in $work/figures" >&2
[ -z "$doc" ] && exit 0
mkdir -p "$(dirname "$doc")"
commit=$(git -C "$root" rev-parse --short HEAD 2> /dev/null || echo unknown)
if [ -z "$section" ]; then
    key="--n $n" title="N = $n" figure=reproduction-versus-p-n$n.png
else # the title's words, lower case, joined by dashes, name the marks' key and the figure
    slug=$(printf '%s' "$section" | tr -d "'" | tr 'A-Z' 'a-z' | tr -cs 'a-z0-9.' '-' | sed 's/^-*//; s/-*$//')
    key="--section $slug" title=$section figure=reproduction-versus-p-$slug.png
fi
begin="<!-- reproduce-paper.sh $key: generated; a rerun replaces everything up to its end mark -->"
end="<!-- end of reproduce-paper.sh $key -->"
{
    echo "$begin"
    echo "## $title"
    echo
    echo "Generated by \`$command\` on $(date -u +%Y-%m-%d), commit $commit: $count packings of"
    echo "N = $n at each p made by \`sbgen --p P --n $n --seed S\` (S = 1..$count${extra:+, plus \`$extra\`}),"
    echo "analysed by \`sbanalyze --compute $compute\`, beside the paper's values"
    echo "(data/mst-reference-values.csv; where the paper has none, Jiao, Stillinger & Torquato 2010's,"
    echo "data/jst2010-reference-values.csv). Regenerate it with the same command; packings already made"
    echo "are kept."
    echo
    cat "$table"
    echo
    echo "![phi, Z, phi_R, alpha and the transport bounds against p at N = $n${figure_with:+, with $figure_with}, the paper's values as markers]($figure)"
    echo "$end"
} > "$work/doc-block.md"
# The block of this N replaces its earlier self; the rest of the document (other N, notes
# written by hand) stays. A new document starts with the title.
if [ -f "$doc" ] && grep -qxF "$begin" "$doc"; then
    awk -v b="$begin" -v e="$end" -v f="$work/doc-block.md" '
        $0 == b { while ((getline line < f) > 0) print line; skip = 1; next }
        skip { if ($0 == e) skip = 0; next }
        { print }' "$doc" > "$doc.tmp"
elif [ -f "$doc" ]; then
    { cat "$doc"; echo; cat "$work/doc-block.md"; } > "$doc.tmp"
else
    { echo "# Reproduction of the paper's tables"; echo; cat "$work/doc-block.md"; } > "$doc.tmp"
fi
mv "$doc.tmp" "$doc"
cp "$work/figures/versus_p.png" "$(dirname "$doc")/$figure"
echo "reproduce-paper.sh: document $doc" >&2
