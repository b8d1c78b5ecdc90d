#!/usr/bin/env bash
# The window with --compare, under Xvfb: another tracer's image of the scene (the headless
# render with a block darkened, as a tracer with a bug of its own would) is compared when
# the window opens (the report on stdout), and the window takes its size. Key 2 must show
# that image exactly, 1 and F the render (the headless PNG, exactly), 3 the difference,
# which P writes as it is shown; I over the darkened block prints that pixel's diagnosis:
# its region and the terms the image implies there. Q quits with status 0, the validation
# layer silent throughout.
#
# usage: window_compare_test.sh RAYTRACER SCENE OUTPUT_DIR IMAGE_DIFF
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/window_lib.sh"

readonly WIDTH=160 HEIGHT=120 SPP=1
readonly BLOCK_X=60 BLOCK_Y=50 BLOCK_SIDE=12 # the darkened block, in pixels

# mine.png: the render with the block darkened by 80 levels, written as a PNG by python3's
# standard library (as a student's own tracer would write its image).
write_mine() {
    timeout 60 python3 - render.png mine.png $BLOCK_X $BLOCK_Y $BLOCK_SIDE <<'PY'
import struct, sys, zlib
source, target, bx, by, side = sys.argv[1], sys.argv[2], *map(int, sys.argv[3:6])
data = open(source, "rb").read()
chunks, at = [], 8
while at < len(data):
    length, kind = struct.unpack(">I4s", data[at:at + 8])
    chunks.append((kind, data[at + 8:at + 8 + length]))
    at += 12 + length
width, height, depth, colour = struct.unpack(">IIBB", dict(chunks)[b"IHDR"][:10])
assert depth == 8 and colour in (2, 6), "an 8-bit RGB or RGBA PNG"
channels = 3 if colour == 2 else 4
raw = zlib.decompress(b"".join(body for kind, body in chunks if kind == b"IDAT"))
stride = width * channels
rows, previous = [], bytearray(stride)
for y in range(height):  # undo the PNG filters (the five of the standard)
    kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for x in range(stride):
        a = line[x - channels] if x >= channels else 0
        b, c = previous[x], previous[x - channels] if x >= channels else 0
        if kind == 1: line[x] = (line[x] + a) & 255
        elif kind == 2: line[x] = (line[x] + b) & 255
        elif kind == 3: line[x] = (line[x] + (a + b) // 2) & 255
        elif kind == 4:
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    rows.append(line)
    previous = line
for y in range(by, by + side):
    for x in range(bx, bx + side):
        for k in range(3):
            rows[y][x * channels + k] = max(0, rows[y][x * channels + k] - 80)
def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
out = b"".join(b"\0" + bytes(row) for row in rows)
open(target, "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour, 0, 0, 0))
                         + chunk(b"IDAT", zlib.compress(out)) + chunk(b"IEND", b""))
PY
}

run_inside_xvfb() {
    cd "$output_dir"
    local log=window.log name id shot count
    name=$(basename "$scene")
    headless render.png
    write_mine || { fail "could not write mine.png"; exit 1; }
    # No --width or --height: the window takes the image's size.
    timeout 600 "$raytracer" "$scene" --compare mine.png --spp $SPP --validate > "$log" 2>&1 &
    local pid=$!
    id=$(wait_for_window "$pid" "$name - ${WIDTH}x${HEIGHT}" 120) || { fail "no ${WIDTH}x${HEIGHT} window (log $log)"; cat "$log"; exit 1; }
    if grep -qF "verdict: differs" "$log" && grep -qE "^  1\. 144 pixels in x $BLOCK_X-$((BLOCK_X + BLOCK_SIDE - 1)), y $BLOCK_Y-$((BLOCK_Y + BLOCK_SIDE - 1)): darker by" "$log"; then
        pass "the comparison's report came first: one region, the darkened block"
    else
        fail "no report naming the darkened block as its region (log $log)"
    fi
    if window_matches "$id" render.png shown-render; then pass "the window opens on the render"; else fail "the window opens on another image than the render (shown-render-diff.txt)"; fi
    press_key "$id" 2
    if window_matches "$id" mine.png shown-mine; then pass "2 shows the image compared, exactly"; else fail "2 does not show mine.png exactly (shown-mine-diff.txt)"; fi
    press_key "$id" 3
    count=$(grep -cF "Screenshot: wrote" "$log" || true)
    press_key "$id" p
    if wait_for_log "$pid" "$log" "Screenshot: wrote" $((count + 1)) 60; then
        shot=$(grep -F "Screenshot: wrote" "$log" | tail -n 1 | sed -E 's/^Screenshot: wrote (.*) \([0-9]+x.*$/\1/')
        if ! grep -F "Screenshot: wrote" "$log" | tail -n 1 | grep -qF "(${WIDTH}x${HEIGHT}, the difference)"; then
            fail "P after 3 wrote something else: $(grep -F "Screenshot: wrote" "$log" | tail -n 1)"
        elif window_matches "$id" "$shot" shown-difference; then
            pass "3 shows the difference, and P writes it as shown"
        else
            fail "3 shows another image than P wrote (shown-difference-diff.txt)"
        fi
        "$image_diff" "$shot" render.png --tolerance 0 --min-match 100 > /dev/null 2>&1 &&
            fail "the difference P wrote is the render itself"
    else
        fail "P wrote no screenshot (log $log)"
    fi
    press_key "$id" f # from the difference: F shows the image, then the render
    press_key "$id" f
    if window_matches "$id" render.png shown-flipped; then pass "F flips back to the render"; else fail "F does not come back to the render (shown-flipped-diff.txt)"; fi
    # I over the block's middle: that pixel's diagnosis on stdout.
    timeout 10 xdotool mousemove --window "$id" $((BLOCK_X + BLOCK_SIDE / 2)) $((BLOCK_Y + BLOCK_SIDE / 2)) || true
    count=$(grep -cF "Diagnosis: pixel" "$log" || true)
    press_key "$id" i
    if wait_for_log "$pid" "$log" "Diagnosis: pixel" $((count + 1)) 60 &&
        grep -qF "pixel $((BLOCK_X + BLOCK_SIDE / 2)),$((BLOCK_Y + BLOCK_SIDE / 2)): differs: region 1 of 1" "$log" &&
        grep -qF "its terms in the reference, and what the image implies" "$log"; then
        pass "I over the block prints the pixel's region and the terms the image implies"
    else
        fail "I printed no diagnosis of pixel $((BLOCK_X + BLOCK_SIDE / 2)),$((BLOCK_Y + BLOCK_SIDE / 2)) (log $log)"
    fi
    expect_clean_quit "$pid" "$id" q "$log"
    echo "window compare test: $passed passed, $failed failed (files in $output_dir)"
    ((failed == 0))
}

window_test_main "$0" "$@"
