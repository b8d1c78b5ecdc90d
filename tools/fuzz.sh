#!/usr/bin/env bash
# Usage: tools/fuzz.sh [SECONDS]    (default 60)
#
# Fuzzes the scene parser with libFuzzer for a bounded time; any crash, sanitizer
# report, leak, hang (-timeout) or out-of-memory (-rss_limit_mb, -malloc_limit_mb)
# fails with libFuzzer's non-zero status and leaves the input that did it in
# build-fuzz/artifacts/. Commit such an input to tests/fuzz/regressions/ (the
# fuzz_replay test replays it in every build).
# Seeds: tests/fuzz/seeds/, scenes/, and ../shared/scenes when present (read in
# place, never copied). New inputs go to build-fuzz/corpus/, kept between runs.
set -euo pipefail
usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
if [[ ${1:-} == -h || ${1:-} == --help ]]; then usage; exit 0; fi
[[ ${1:-60} =~ ^[0-9]+$ && $# -le 1 ]] || { usage >&2; exit 2; }
cd "$(dirname "$0")/.."
seconds=${1:-60}
build=build-fuzz

cmake -S tests/fuzz -B "$build" -DCMAKE_CXX_COMPILER=clang++ > /dev/null
cmake --build "$build" -j "$(nproc)" > /dev/null
mkdir -p "$build/corpus" "$build/artifacts"
seeds=(tests/fuzz/seeds tests/fuzz/regressions scenes)
[[ -d ../shared/scenes ]] && seeds+=(../shared/scenes)

echo "Fuzzing the scene parser for ${seconds} s (seeds: ${seeds[*]})"
# -max_len 8192: scenes are text; longer inputs explore nothing new and run slower
# (larger seeds, such as mesh.scene, are cut to that length).
# -timeout 10: one input parsing for 10 s is a hang. -rss_limit_mb / -malloc_limit_mb
# 2048: the parser must never allocate from a claimed count.
set +e
"$build/scene_parser_fuzz" "$build/corpus" "${seeds[@]}" \
    -dict=tests/fuzz/scene.dict -max_total_time="$seconds" -max_len=8192 -timeout=10 \
    -rss_limit_mb=2048 -malloc_limit_mb=2048 -artifact_prefix="$build/artifacts/" \
    -print_final_stats=1 2>&1 | tee "$build/last-run.log" | grep -vE '^#[0-9]+|# Uses:|Recommended dictionary|End of recommended'
status=${PIPESTATUS[0]}
set -e
if ((status != 0)); then
    echo "fuzz: FAILED (status $status); the input is in $build/artifacts/, the log in $build/last-run.log" >&2
    exit 1
fi
echo "fuzz: no crash, leak, hang or out-of-memory in ${seconds} s"
