#!/usr/bin/env bash
# Every tool a user runs answers --help and -h with its usage (the first line starts with
# "usage:") and exit status 0, and does nothing else: no build, no file written, neither
# in the checkout nor in the working directory. The tools are found, not listed: every
# executable file of tools/, tools/build/, tools/lib/, tools/farm/ and tools/compare/, and the C++ tools built in
# BUILD_TOOLS_DIR, so a new tool cannot be forgotten.
#
#   tools_help_test.sh SOURCE_DIR BUILD_TOOLS_DIR
set -euo pipefail

if (($# != 2)); then
    echo "usage: $0 SOURCE_DIR BUILD_TOOLS_DIR" >&2
    exit 2
fi
root=$(cd "$1" && pwd)
build_tools=$(cd "$2" && pwd)

mapfile -t tools < <(find "$root/tools" "$root/tools/build" "$root/tools/lib" "$root/tools/farm" "$root/tools/compare" -maxdepth 1 -type f -executable |
    sort)
mapfile -t built < <(find "$build_tools" -maxdepth 1 -type f -executable | sort)
[[ -x $build_tools/image_diff ]] || { echo "FAIL: $build_tools holds no built tools (image_diff)"; exit 1; }
tools+=("${built[@]}")

# Where a tool run from the checkout would leave something: the checkout's top level
# (build-fuzz/, out/) and its tools/ folders, and the working directory.
workdir=$(mktemp -d)
trap 'rm -rf "$workdir"' EXIT
snapshot() { ls -A "$root" "$root/tools" "$root/tools/build" "$root/tools/lib" "$root/tools/farm" "$root/tools/compare" "$build_tools"; }
before=$(snapshot)

failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
for tool in "${tools[@]}"; do
    for flag in --help -h; do
        status=0
        output=$(cd "$workdir" && timeout 30 "$tool" "$flag" 2>&1 < /dev/null) || status=$?
        name=${tool#"$root/"}
        name=${name#"$build_tools/"}
        if ((status != 0)); then
            fail "$name $flag: exit status $status"
        elif ! head -n 1 <<< "$output" | grep -qi '^usage: '; then
            fail "$name $flag: the first line is not a usage line: $(head -n 1 <<< "$output")"
        else
            echo "ok: $name $flag"
        fi
    done
done
[[ -z $(ls -A "$workdir") ]] || fail "files were written to the working directory: $(ls -A "$workdir")"
after=$(snapshot)
[[ $before == "$after" ]] || fail "the checkout changed: $(diff <(echo "$before") <(echo "$after") | tail -n +2)"

if ((failures)); then
    echo "$failures failures"
    exit 1
fi
echo "all ${#tools[@]} tools answer --help and -h"
