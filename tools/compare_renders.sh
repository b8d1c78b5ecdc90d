#!/usr/bin/env bash
# Usage: tools/compare_renders.sh OLD_RAYTRACER NEW_RAYTRACER [SCENE_DIR_OR_FILE...] [-- RAYTRACER_ARGS...]
#        tools/compare_renders.sh --commit REV NEW_RAYTRACER [...]
#
# Renders every scene with two Raytracer builds and checks that the PNGs are identical,
# byte for byte: the check for a change that must not move a pixel (a refactoring, a
# faster kernel that claims the same images).
#
# --commit REV builds Raytracer of that commit (a detached git worktree, built in
# build-compare/REV; about a minute on 2 cores) and uses it as OLD: e.g.
# `tools/compare_renders.sh --commit HEAD~1 build/Raytracer` after a refactoring.
#
# Without scene arguments: scenes/, scenes/stress/ and the classic scenes beside the
# checkout (../shared/scenes) when present. Arguments after -- go to both builds
# (e.g. -- --spp 4 --depth 2). Both run on lavapipe unless VK_ICD_FILENAMES is set.
# Exit status: 0 when every pair is identical, 1 when any differs or fails, 2 on usage.
set -euo pipefail

usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
if [[ ${1:-} == -h || ${1:-} == --help ]]; then usage; exit 0; fi
if (($# < 2)); then usage >&2; exit 2; fi
root=$(cd "$(dirname "$0")/.." && pwd)
if [[ $1 == --commit ]]; then
    (($# >= 3)) || { usage >&2; exit 2; }
    revision=$(git -C "$root" rev-parse --verify --short "$2^{commit}") ||
        { echo "compare_renders: $2 is not a commit" >&2; exit 2; }
    build=$root/build-compare/$revision
    if [[ ! -x $build/Raytracer ]]; then
        source_tree=$build/source
        rm -rf "$source_tree"
        git -C "$root" worktree add --detach --force "$source_tree" "$revision" > /dev/null
        cmake -S "$source_tree" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
        cmake --build "$build" --target Raytracer -j "$(nproc)" > /dev/null
        git -C "$root" worktree remove --force "$source_tree"
    fi
    set -- "$build/Raytracer" "${@:3}"
fi
old=$1 new=$2
shift 2
for program in "$old" "$new"; do
    [[ -x $program ]] || { echo "compare_renders: $program is not an executable" >&2; exit 2; }
done

inputs=() extra=()
while (($#)); do
    if [[ $1 == -- ]]; then shift; extra=("$@"); break; fi
    inputs+=("$1"); shift
done
if ((${#inputs[@]} == 0)); then
    inputs=("$root/scenes" "$root/scenes/stress")
    [[ -d $root/../shared/scenes ]] && inputs+=("$root/../shared/scenes")
fi

scenes=()
for input in "${inputs[@]}"; do
    if [[ -d $input ]]; then
        for scene in "$input"/*.scene; do [[ -f $scene ]] && scenes+=("$scene"); done
    elif [[ -f $input ]]; then
        scenes+=("$input")
    else
        echo "compare_renders: no such scene or folder: $input" >&2; exit 2
    fi
done

export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
same=0 failed=0
for scene in "${scenes[@]}"; do
    if ! "$old" "$scene" -o "$work/old.png" "${extra[@]}" 2>"$work/old.log" ||
       ! "$new" "$scene" -o "$work/new.png" "${extra[@]}" 2>"$work/new.log"; then
        echo "FAILED    $scene (a build did not render it)"; tail -n 3 "$work"/*.log; failed=$((failed + 1))
    elif cmp -s "$work/old.png" "$work/new.png"; then
        echo "identical $scene"; same=$((same + 1))
    else
        echo "DIFFERENT $scene"; failed=$((failed + 1))
    fi
    rm -f "$work/old.png" "$work/new.png"
done
echo "compare_renders: ${#scenes[@]} scenes, $same identical, $failed different or failed"
((failed == 0))
