#!/usr/bin/env bash
# Usage: tools/fuzz.sh [SECONDS]    (default 60)
#
# Fuzzes the scene parser with libFuzzer for a bounded time, then the OBJ model reader
# for half that time, the other model readers (PLY, STL; GLB through assimp) and the
# handed-in image readers (PPM, JPEG markers) for a quarter each; any crash, sanitizer
# report, leak, hang (-timeout) or out-of-memory
# (-rss_limit_mb, -malloc_limit_mb) fails with libFuzzer's non-zero status and leaves the
# input that did it in build-fuzz/artifacts/. Commit such an input to
# tests/fuzz/regressions/ (tests/fuzz/obj_regressions/ for the OBJ reader,
# tests/fuzz/model_regressions/ for the other model readers): the fuzz_replay,
# obj_fuzz_replay and model_fuzz_replay tests replay them in every build.
# Seeds: tests/fuzz/seeds/, scenes/, and ../shared/scenes when present (read in place,
# never copied); for the OBJ reader tests/fuzz/obj_seeds/ and obj_corpus/. New inputs go to
# build-fuzz/corpus-TARGET/, kept between runs.
set -euo pipefail
usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
if [[ ${1:-} == -h || ${1:-} == --help ]]; then usage; exit 0; fi
[[ ${1:-60} =~ ^[0-9]+$ && $# -le 1 ]] || { usage >&2; exit 2; }
cd "$(dirname "$0")/.."
seconds=${1:-60}
build=build-fuzz

cmake -S tests/fuzz -B "$build" -DCMAKE_CXX_COMPILER=clang++ > /dev/null
cmake --build "$build" -j "$(nproc)" > /dev/null
mkdir -p "$build/artifacts"
seeds=(tests/fuzz/seeds tests/fuzz/regressions scenes)
[[ -d ../shared/scenes ]] && seeds+=(../shared/scenes)

# One target after the other, with the same limits. -max_len 8192: the inputs are text;
# longer ones explore nothing new and run slower (larger seeds, such as mesh.scene, are
# cut to that length). -timeout 10: one input read for 10 s is a hang. -rss_limit_mb /
# -malloc_limit_mb 2048: a reader must never allocate from a claimed count.
fuzz() { # NAME TARGET SECONDS DICTIONARY SEED...
    local name=$1 target=$2 time=$3 dictionary=$4
    shift 4
    echo "Fuzzing the $name for ${time} s (seeds: $*)"
    mkdir -p "$build/corpus-$target"
    set +e
    "$build/$target" "$build/corpus-$target" "$@" \
        -dict="$dictionary" -max_total_time="$time" -max_len=8192 -timeout=10 \
        -rss_limit_mb=2048 -malloc_limit_mb=2048 -artifact_prefix="$build/artifacts/" \
        -print_final_stats=1 2>&1 | tee "$build/last-run-$target.log" |
        grep -vE '^#[0-9]+|# Uses:|Recommended dictionary|End of recommended'
    local status=${PIPESTATUS[0]}
    set -e
    if ((status != 0)); then
        echo "fuzz: FAILED (status $status); the input is in $build/artifacts/, the log in $build/last-run-$target.log" >&2
        exit 1
    fi
}
fuzz "scene parser" scene_parser_fuzz "$seconds" tests/fuzz/scene.dict "${seeds[@]}"
# The OBJ reader for half as long: its grammar is smaller.
fuzz "OBJ model reader" obj_model_fuzz $(((seconds + 1) / 2)) tests/fuzz/obj.dict \
    tests/fuzz/obj_seeds tests/fuzz/obj_corpus tests/fuzz/obj_regressions
# The other model readers (PLY, STL; GLB through assimp) for a quarter of the time.
fuzz "model readers (PLY, STL; GLB through assimp)" model_file_fuzz $(((seconds + 3) / 4)) tests/fuzz/model.dict \
    tests/fuzz/model_seeds tests/fuzz/model_regressions
# The handed-in image readers (PPM, JPEG markers) for a quarter of the time.
fuzz "image header readers" image_header_fuzz $(((seconds + 3) / 4)) tests/fuzz/image.dict \
    tests/fuzz/image_seeds
echo "fuzz: no crash, leak, hang or out-of-memory in ${seconds} s"
