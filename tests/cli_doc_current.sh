#!/usr/bin/env bash
# Checks that the command-line manual is current: DOC (docs/cli.md) must be exactly what
# scripts/make_cli_doc.sh prints for these two programs. On a difference it prints the diff and
# exits non-zero; regenerate with
#   scripts/make_cli_doc.sh build/generator/sbgen build/analysis/sbanalyze > docs/cli.md
set -euo pipefail

if [[ $# -ne 3 ]]; then
    echo "usage: cli_doc_current.sh SBGEN SBANALYZE DOC" >&2
    exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
generator="$here/../scripts/make_cli_doc.sh"
if [[ ! -f "$3" ]]; then
    echo "cli_doc_current.sh: '$3' is not a file" >&2
    exit 2
fi

generated=$(mktemp)
trap 'rm -f "$generated"' EXIT
bash "$generator" "$1" "$2" >"$generated"
if ! diff -u "$3" - <"$generated"; then
    echo "$3 is stale: regenerate it with scripts/make_cli_doc.sh SBGEN SBANALYZE > $3" >&2
    exit 1
fi
echo "docs/cli.md: current"
