#!/usr/bin/env bash
# usage: tools/batch_bench.sh [--raytracer PATH] [--repeat N] SCENE... [-- RAYTRACER_OPTION...]
#
# Times a batch (docs/batches.md): the scenes rendered by one Raytracer process
# (Raytracer SCENE... -o DIR/) against one process per scene, N times each (default 3),
# and prints the best wall time of each way, in total and per scene, and what the batch
# reused (its "Batch:" line). Both write the same images, which are compared byte for byte.
# The options after -- go to every run (say --width 320 --height 240); the shader cache
# on disk is warm for both ways after the first run.
set -euo pipefail
usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
raytracer=$(dirname "$0")/../build/Raytracer
repeat=3
scenes=()
while (($#)); do
    case $1 in
        -h | --help) usage; exit 0 ;;
        --raytracer) raytracer=$2; shift 2 ;;
        --repeat) repeat=$2; shift 2 ;;
        --) shift; break ;;
        -*) usage >&2; exit 2 ;;
        *) scenes+=("$1"); shift ;;
    esac
done
((${#scenes[@]} > 0)) || { usage >&2; exit 2; }
[[ -x $raytracer ]] || { echo "batch_bench.sh: no Raytracer at $raytracer (--raytracer PATH)" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/batch" "$work/single"
now() { date +%s%N; } # nanoseconds, for bash arithmetic
best_batch="" best_single=""
for ((run = 0; run < repeat; ++run)); do
    start=$(now)
    "$raytracer" "${scenes[@]}" -o "$work/batch/" "$@" 2> "$work/batch.log"
    batch=$(($(now) - start))
    start=$(now)
    for scene in "${scenes[@]}"; do
        "$raytracer" "$scene" -o "$work/single/$(basename "${scene%.*}").png" "$@" 2> /dev/null
    done
    single=$(($(now) - start))
    [[ -n $best_batch ]] && ((batch >= best_batch)) || best_batch=$batch
    [[ -n $best_single ]] && ((single >= best_single)) || best_single=$single
done
for scene in "${scenes[@]}"; do
    name=$(basename "${scene%.*}").png
    cmp -s "$work/batch/$name" "$work/single/$name" || { echo "batch_bench.sh: $name differs between the ways" >&2; exit 1; }
done
n=${#scenes[@]}
printf 'scenes: %d, best of %d runs\n' "$n" "$repeat"
ms() { echo "$(($1 / 1000000)).$(($1 / 100000 % 10))"; } # nanoseconds to ms, one decimal
printf 'one process:          %9s ms in all, %7s ms per scene\n' "$(ms "$best_batch")" "$(ms $((best_batch / n)))"
printf 'a process per scene:  %9s ms in all, %7s ms per scene\n' "$(ms "$best_single")" "$(ms $((best_single / n)))"
grep '^Batch:' "$work/batch.log"
