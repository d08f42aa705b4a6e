#!/usr/bin/env bash
# Runs the README's commands as a reader would on a built tree: the shell block of "Already
# built? Start here" from a folder where build/ is the build tree under test and data/ the
# repository's, and the Python block of "Python" from an empty folder (issue 66 item 4) (issue 43: every command in the README is run in CI;
# "Two commands" are .ci/run and scripts/demo.sh themselves).
# usage: readme_commands.sh ROOT BUILD PYTHON
set -euo pipefail
root=$1 build=$2 python=$3
readme=$root/README.md
work=$(mktemp -d "${TMPDIR:-/tmp}/sbpack-readme.XXXXXX")
trap 'rm -rf "$work"' EXIT
ln -s "$build" "$work/build"
ln -s "$root/data" "$work/data"

# block HEADING LANGUAGE [FILE]: the first ```LANGUAGE block after the line "## HEADING".
block() {
    awk -v heading="## $1" -v open="\`\`\`$2" '
        $0 == heading { found = 1; next }
        found && !inside && $0 == open { inside = 1; next }
        inside && $0 == "```" { exit }
        inside { print }' "${3:-$readme}"
}
shell=$(block "Already built? Start here" sh)
python_code=$(block "Python" python)
[[ -n $shell && -n $python_code ]] || { echo "README.md: a block was not found" >&2; exit 1; }

cd "$work"
echo "== the shell walk-through"
# The walk-through writes build/demo (the demo's folder) and reads PYTHONPATH=build/python with
# /usr/bin/python3, as the README says.
bash -euo pipefail -c "$shell" > "$work/shell.log" 2>&1 ||
    { cat "$work/shell.log"; echo "README.md: the walk-through failed" >&2; exit 1; }
for file in mrj-spheres-250.h5 mrj-spheres-250-results.h5 mrj-spheres-250.xyz structure_factor.png; do
    [[ -s build/demo/$file ]] || { echo "README.md: build/demo/$file was not written" >&2; exit 1; }
done
echo "== the Python block, from an empty folder (its packings are the module's own)"
mkdir "$work/elsewhere"
(cd "$work/elsewhere" && PYTHONPATH="$build/python" "$python" -c "$python_code")
manual=$root/docs/python.md
manual_code=$(for heading in Packing Analyses Generator; do block "$heading" python "$manual"; done)
[[ $(grep -c . <<< "$manual_code") -gt 10 ]] || { echo "docs/python.md: blocks not found" >&2; exit 1; }
echo "== docs/python.md's blocks"
PYTHONPATH=build/python "$python" -c "$manual_code" | tail -n 2
echo "readme_commands: ok"
