#!/usr/bin/env bash
# usage: tools/make_video.sh FRAMES OUT.mp4 [--fps N]
#
# Joins numbered frames (Raytracer --turntable or --camera-path) into a video with ffmpeg.
# FRAMES is the pattern given to Raytracer's -o, as out/frame-{frame:04}.png, or ffmpeg's
# own, out/frame-%04d.png; the frames must start at 0. N frames per second (default 30).
# ffmpeg is optional (Debian: ffmpeg): without it this says so and exits 1.
set -euo pipefail
usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
case "${1:-}" in -h | --help) usage; exit 0 ;; esac
fps=30
(($# == 2 || $# == 4)) || { usage >&2; exit 2; }
if (($# == 4)); then
    [[ $3 == --fps && $4 =~ ^[0-9]+$ ]] && (($4 > 0)) || { usage >&2; exit 2; }
    fps=$4
fi
frames=$1 video=$2
# Raytracer's fields to ffmpeg's: {frame:04} is %04d, {frame} is %d.
pattern=$(sed -E 's/\{frame:0([1-9])\}/%0\1d/g; s/\{frame\}/%d/g' <<< "$frames")
[[ $pattern == *%* ]] || { echo "make_video.sh: $frames has no frame number ({frame:04} or %04d)" >&2; exit 2; }
if ! command -v ffmpeg > /dev/null; then
    echo "make_video.sh: ffmpeg is not installed (Debian: apt-get install ffmpeg); the frames $frames are left as they are" >&2
    exit 1
fi
ffmpeg -hide_banner -loglevel error -y -framerate "$fps" -i "$pattern" -vf "pad=ceil(iw/2)*2:ceil(ih/2)*2" -pix_fmt yuv420p "$video"
echo "Wrote $video"
