#!/usr/bin/env bash
# Usage: tools/format.sh [--check]
#
# Applies the committed .clang-format to every C++ and GLSL file of the project, or with
# --check lists the files that differ from it and fails (CI runs the check).
#   tools/format.sh           reformat in place
#   tools/format.sh --check   exit 1 and name the files when any file is not formatted
#
# GLSL is formatted as C-like code; shaders/.clang-format keeps its include order, which
# matters there. Needs clang-format (Debian's clang-format package, version 14).
set -euo pipefail
usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
cd "$(dirname "$0")/.."

mode=fix
case "${1:-}" in
    "") ;;
    --check) mode=check ;;
    -h | --help) usage; exit 0 ;;
    *) usage >&2; exit 2 ;;
esac
command -v clang-format > /dev/null || { echo "format.sh: clang-format is not installed" >&2; exit 2; }

mapfile -t files < <(git ls-files --cached --others --exclude-standard \
    '*.cpp' '*.h' '*.comp' '*.glsl' | while read -r f; do [[ -f $f ]] && echo "$f"; done)
if [[ $mode == fix ]]; then
    clang-format -i "${files[@]}"
    exit 0
fi
# One clang-format for all the files (one per file took ten times longer). Each violation
# is a diagnostic "FILE:LINE:COLUMN: error: code should be clang-formatted [...]", in the
# order the files were given; the files are named once each, as a list.
status=0
report=$(clang-format --dry-run -Werror "${files[@]}" 2>&1) || status=$?
if ((status == 0)); then
    echo "format.sh: ${#files[@]} files formatted as .clang-format says"
    exit 0
fi
violation='^\(.*\):[0-9]\+:[0-9]\+: error: code should be clang-formatted \[-Wclang-format-violations\]$'
mapfile -t unformatted < <(sed -n "s/$violation/\\1/p" <<< "$report" | uniq)
if ((${#unformatted[@]} == 0)); then
    echo "$report" >&2  # clang-format failed for another reason: say what it said
    exit 1
fi
echo "format.sh: ${#unformatted[@]} files differ from .clang-format (run tools/format.sh):"
printf '  %s\n' "${unformatted[@]}"
exit 1
