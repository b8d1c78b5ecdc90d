#!/usr/bin/env bash
# tools/make_video.sh: without ffmpeg it says so, word for word, with exit status 1 and no
# video; with ffmpeg (when installed) two frames of Raytracer --turntable become a video.
# Bad arguments are exit status 2.
#
#   make_video_test.sh SOURCE_DIR RAYTRACER
set -euo pipefail
(($# == 2)) || { echo "usage: $0 SOURCE_DIR RAYTRACER" >&2; exit 2; }
root=$(cd "$1" && pwd)
raytracer=$2
tool=$root/tools/make_video.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# A PATH with bash and the tools the script needs, but no ffmpeg.
mkdir bin
for program in bash sed awk env; do ln -s "$(command -v "$program")" "bin/$program"; done
status=0
message=$(PATH=$work/bin "$tool" 'out/frame-{frame:04}.png' out.mp4 2>&1) || status=$?
expected="make_video.sh: ffmpeg is not installed (Debian: apt-get install ffmpeg); the frames out/frame-{frame:04}.png are left as they are"
((status == 1)) || fail "without ffmpeg: exit status $status, not 1"
[[ $message == "$expected" ]] || fail "without ffmpeg: '$message'"
[[ ! -e out.mp4 ]] || fail "without ffmpeg a video was written"

status=0
"$tool" 'frame.png' out.mp4 2> /dev/null || status=$?
((status == 2)) || fail "a pattern without a frame number: exit status $status, not 2"
status=0
"$tool" 'f-%04d.png' out.mp4 --fps 0 2> /dev/null || status=$?
((status == 2)) || fail "--fps 0: exit status $status, not 2"

if command -v ffmpeg > /dev/null; then
    mkdir frames
    "$raytracer" "$root/scenes/showcase.scene" --width 32 --height 24 --turntable 2 \
        -o 'frames/f-{frame:04}.png' 2> /dev/null
    "$tool" 'frames/f-{frame:04}.png' video.mp4 --fps 2 > /dev/null || fail "ffmpeg failed"
    [[ -s video.mp4 ]] || fail "no video written"
else
    echo "note: ffmpeg is not installed; only its absence was checked"
fi

if ((failures)); then
    echo "$failures failures"
    exit 1
fi
echo "make_video.sh answers as documented"
