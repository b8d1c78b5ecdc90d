# Shared by the window tests (sourced): reading the window back and finding it by title.
# Needs python3, xwd and xwininfo.

# xwd dump (TrueColor, 24 or 32 bits per pixel) to an RGB PNG, standard library only.
xwd_to_png() {
    timeout 30 python3 - "$1" "$2" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
(header_size, _version, pixmap_format, _depth, width, height, _xoffset, byte_order, _unit,
 _bit_order, _pad, bits_per_pixel, bytes_per_line, visual_class, red_mask, green_mask,
 blue_mask, _bits_per_rgb, _entries, ncolors) = struct.unpack(">20I", data[:80])
if pixmap_format != 2 or visual_class not in (4, 5) or bits_per_pixel not in (24, 32):
    sys.exit(f"xwd: unsupported dump (format {pixmap_format}, visual {visual_class}, {bits_per_pixel} bpp)")
pixels = header_size + 12 * ncolors  # the header, then ncolors 12-byte colormap entries
step, order = bits_per_pixel // 8, "little" if byte_order == 0 else "big"
def channel(value, mask):  # the masked bits, scaled to 8 bits
    shift = (mask & -mask).bit_length() - 1
    return ((value & mask) >> shift) * 255 // (mask >> shift)
rows = bytearray()
for y in range(height):
    rows.append(0)  # PNG filter type: none
    line = pixels + y * bytes_per_line
    for x in range(width):
        value = int.from_bytes(data[line + x * step:line + (x + 1) * step], order)
        rows += bytes((channel(value, red_mask), channel(value, green_mask), channel(value, blue_mask)))
def chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
with open(sys.argv[2], "wb") as png:
    png.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
              + chunk(b"IDAT", zlib.compress(bytes(rows))) + chunk(b"IEND", b""))
print(f"{width}x{height}")
PY
}

# The id of the window whose title says it shows SCENE at WxH with all SPP samples in
# ("NAME - WxH - k/N spp - T ms - DEVICE", k == N: refinement is done).
find_window() { # NAME W H [SPP]
    local spp=${4:-1}
    timeout 10 xwininfo -root -tree | grep -F "\"$1 - $2x$3 - $spp/$spp spp - " |
        awk '{ print $1 }' | head -n 1 || true
}

# Waits until LOG holds at least COUNT lines matching the fixed string TEXT, while PID
# runs; fails after SECONDS. Returns 0 when they are there.
wait_for_log() { # PID LOG TEXT COUNT SECONDS
    local pid=$1 log=$2 text=$3 count=$4 deadline=$((SECONDS + $5))
    while (($(grep -cF -- "$text" "$log" || true) < count)); do
        kill -0 "$pid" 2>/dev/null || return 1
        ((SECONDS <= deadline)) || return 1
        sleep 0.2
    done
}

# Captures window ID until it equals EXPECTED.PNG exactly, up to TRIES times 0.4 s apart
# (default 50: the present may reach the X server a while after the program logs the frame,
# more so on a loaded machine; a match returns at once). Writes PREFIX.png and
# PREFIX-diff.txt; returns 0 on a match.
window_matches() { # ID EXPECTED.PNG PREFIX [TRIES]
    local id=$1 expected=$2 prefix=$3 tries=${4:-50}
    for _ in $(seq 1 "$tries"); do
        sleep 0.4
        timeout 10 xwd -id "$id" -silent > "$prefix.xwd" 2>/dev/null || continue
        xwd_to_png "$prefix.xwd" "$prefix.png" > /dev/null || continue
        if timeout 30 "$image_diff" "$expected" "$prefix.png" --tolerance 0 --min-match 100 \
            --diff "$prefix-diff.png" > "$prefix-diff.txt" 2>&1; then
            return 0
        fi
    done
    return 1
}

# Waits until the title of the window showing NAME reports at least MIN samples per pixel
# ("NAME - WxH - k/N spp - ..." with k >= MIN), while PID runs; fails after SECONDS.
wait_for_samples() { # PID NAME MIN SECONDS
    local pid=$1 name=$2 min=$3 deadline=$((SECONDS + $4)) done
    while :; do
        done=$(timeout 10 xwininfo -root -tree | grep -F "\"$name - " |
            sed -nE 's/^.* - ([0-9]+)\/[0-9]+ spp - .*$/\1/p' | head -n 1 || true)
        [[ -n $done ]] && ((done >= min)) && return 0
        kill -0 "$pid" 2>/dev/null || return 1
        ((SECONDS <= deadline)) || return 1
        sleep 0.2
    done
}

# Holds KEY down in window ID until the camera has moved away from the one O printed last
# (O is pressed again until its line differs), then lets go; LOG is the program's output.
# The fly keys are read as held on each frame, so the key is held for frames, not seconds:
# a loaded machine that draws a frame a second still sees it held. Returns 1 if the camera
# has not moved after SECONDS.
hold_key_until_moved() { # PID ID KEY LOG SECONDS
    local pid=$1 id=$2 key=$3 log=$4 deadline=$((SECONDS + $5)) before count moved=1
    count=$(grep -cF "Camera: --camera-pos" "$log" || true)
    press_key "$id" o
    wait_for_log "$pid" "$log" "Camera: --camera-pos" $((count + 1)) 30 || return 1
    before=$(grep -F "Camera: --camera-pos" "$log" | tail -n 1)
    timeout 10 xdotool keydown --window "$id" "$key" || true
    while ((SECONDS <= deadline)); do
        count=$(grep -cF "Camera: --camera-pos" "$log" || true)
        press_key "$id" o
        wait_for_log "$pid" "$log" "Camera: --camera-pos" $((count + 1)) 30 || break
        if [[ $(grep -F "Camera: --camera-pos" "$log" | tail -n 1) != "$before" ]]; then
            moved=0
            break
        fi
        sleep 0.2
    done
    timeout 10 xdotool keyup --window "$id" "$key" || true
    return "$moved"
}

# The id of the first window whose title starts with "NAME - ", waiting up to SECONDS.
wait_for_window() { # PID NAME SECONDS
    local pid=$1 name=$2 deadline=$((SECONDS + $3)) id=""
    while [[ -z $id ]]; do
        kill -0 "$pid" 2>/dev/null || return 1
        ((SECONDS <= deadline)) || return 1
        sleep 0.3
        id=$(timeout 10 xwininfo -root -tree | grep -F "\"$name - " | awk '{ print $1 }' | head -n 1 || true)
    done
    echo "$id"
}

# Waits up to 30 s for PID to end and returns its exit status; 124 (after killing it) if
# it is still running then.
wait_for_exit() { # PID
    local pid=$1 status=0
    for _ in $(seq 1 150); do kill -0 "$pid" 2>/dev/null || break; sleep 0.2; done
    if kill -0 "$pid" 2>/dev/null; then kill "$pid"; wait "$pid" || true; return 124; fi
    wait "$pid" || status=$?
    return "$status"
}

# Ends PID with KEY sent to window ID; returns as wait_for_exit.
quit_with_key() { # PID ID KEY
    # Key press only: the program quits on the press, so a release would find no window.
    timeout 10 xdotool keydown --window "$2" "$3" || true
    wait_for_exit "$1"
}

# Records a failure (fail, defined by the test), its message starting with PREFIX, unless
# the program ended cleanly after WHAT: STATUS (from wait_for_exit) 0, and not a word
# from the validation layer in LOG. Returns 0 when it did.
judge_exit() { # STATUS LOG PREFIX WHAT
    local status=$1 log=$2 prefix=$3 what=$4
    if ((status == 124)); then
        fail "$prefix: still running 30 s after $what (log $log)"
    elif ((status != 0)); then
        fail "$prefix: exited with status $status after $what (log $log)"
    elif grep -qiE "validation (error|warning)|VUID-" "$log"; then
        fail "$prefix: the validation layer spoke (log $log)"
    else
        return 0
    fi
    return 1
}

# Ends PID with KEY and records that it exited with status 0, validation silent.
expect_clean_quit() { # PID ID KEY LOG
    local status=0
    quit_with_key "$1" "$2" "$3" || status=$?
    judge_exit "$status" "$4" quit "the $3 key" && pass "$3 quit with status 0, validation silent"
}

# Asks window ID to close as a window manager's close button does: a WM_DELETE_WINDOW
# client message (ICCCM), sent with libX11 through ctypes since Xvfb runs no window
# manager and xdotool has no such command. Returns non-zero if it could not be sent.
request_close() { # ID
    timeout 10 python3 - "$1" <<'PY'
import ctypes, sys
x11 = ctypes.CDLL("libX11.so.6")
x11.XOpenDisplay.restype = ctypes.c_void_p
x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
x11.XInternAtom.restype = ctypes.c_ulong
x11.XInternAtom.argtypes = [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int]
x11.XSendEvent.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_long, ctypes.c_void_p]
x11.XFlush.argtypes = x11.XCloseDisplay.argtypes = [ctypes.c_void_p]
class ClientMessage(ctypes.Structure):  # XClientMessageEvent
    _fields_ = [("type", ctypes.c_int), ("serial", ctypes.c_ulong), ("send_event", ctypes.c_int),
                ("display", ctypes.c_void_p), ("window", ctypes.c_ulong),
                ("message_type", ctypes.c_ulong), ("format", ctypes.c_int), ("data", ctypes.c_long * 5)]
class XEvent(ctypes.Union):  # Xlib's XEvent is 24 longs
    _fields_ = [("xclient", ClientMessage), ("pad", ctypes.c_long * 24)]
display = x11.XOpenDisplay(None)
if not display:
    sys.exit("request_close: cannot open the display")
window = int(sys.argv[1], 0)
event = XEvent()
event.xclient.type = 33  # ClientMessage
event.xclient.window = window
event.xclient.message_type = x11.XInternAtom(display, b"WM_PROTOCOLS", 0)
event.xclient.format = 32
event.xclient.data[0] = x11.XInternAtom(display, b"WM_DELETE_WINDOW", 0)
event.xclient.data[1] = 0  # CurrentTime
if not x11.XSendEvent(display, window, 0, 0, ctypes.byref(event)):
    sys.exit("request_close: XSendEvent failed")
x11.XFlush(display)
x11.XCloseDisplay(display)
PY
}

# The test's tally: pass and fail print one line each and count it.
passed=0 failed=0
pass() { echo "PASS: $*"; passed=$((passed + 1)); }
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }

# Renders the test's scene headless to OUT.PNG at the test's WIDTH x HEIGHT and SPP, with
# ARGS, its output in OUT.PNG.log; a failed render ends the test.
headless() { # OUT.PNG ARGS...
    local out=$1
    shift
    env -u DISPLAY timeout 120 "$raytracer" "$scene" -o "$out" --width $WIDTH --height $HEIGHT --spp $SPP "$@" \
        > "$out.log" 2>&1 || { echo "FAIL: headless render $out (log $out.log)"; exit 1; }
}

# Sends one key press and release to window ID.
press_key() { # ID KEY
    timeout 10 xdotool key --window "$1" "$2" || true
}

# Exits 1 naming the first tool the window tests need that is not installed.
require_window_tools() {
    local tool
    for tool in xvfb-run xauth xwininfo xwd xdotool python3 timeout; do
        command -v "$tool" > /dev/null || { echo "window test: $tool is missing (tools/build/install_deps.sh)"; exit 1; }
    done
}

# Runs COMMAND under a new Xvfb server with a screen of WxHxDEPTH, for at most SECONDS,
# and returns its status. Window tests run in parallel, and xvfb-run -a alone lets two
# that start at once pick the same display number (it reads lock files that the other's
# server has not written yet): each try starts its search at a random number, and a try
# whose server never came up (COMMAND did not start), or went away under it (a failed
# COMMAND whose output says the display could not be opened), is made again, up to 5 times.
run_in_xvfb() { # SECONDS SCREEN COMMAND...
    local seconds=$1 screen=$2 started output status=0 try
    shift 2
    started=$(mktemp)
    output=$(mktemp)
    for try in 1 2 3 4 5; do
        rm -f "$started"
        status=0
        # -n before -a: -a searches upward from the number given so far.
        timeout "$seconds" xvfb-run -n $((100 + RANDOM % 800)) -a -s "-screen 0 $screen" \
            bash -c ': > "$0" && exec "$@"' "$started" "$@" > >(tee "$output") 2>&1 || status=$?
        wait # for tee
        if [[ ! -e $started ]]; then
            echo "Xvfb did not come up (try $try of 5, status $status)" >&2
        elif ((status != 0)) && grep -q "Failed to open display" "$output"; then
            echo "Xvfb's display could not be opened (try $try of 5): the test runs again" >&2
        else
            break
        fi
        sleep 1
    done
    rm -f "$started" "$output"
    return "$status"
}

# The absolute path of an existing file, for the re-run of a test inside xvfb-run.
absolute() { echo "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"; }

# The entry of a window test run as SCRIPT RAYTRACER SCENE OUTPUT_DIR IMAGE_DIFF: clears
# OUTPUT_DIR's files and runs SCRIPT again inside a new 1024x768 Xvfb for at most 560 s;
# there (first argument --inside-xvfb) it sets raytracer, scene, output_dir and image_diff
# and calls the script's run_inside_xvfb. Call it last, as: window_test_main "$0" "$@".
window_test_main() { # SCRIPT ARGS...
    local script=$1
    shift
    if [[ $# == 5 && $1 == --inside-xvfb ]]; then
        raytracer=$2 scene=$3 output_dir=$4 image_diff=$5
        run_inside_xvfb
        exit
    fi
    if (($# != 4)); then
        echo "usage: $script RAYTRACER SCENE OUTPUT_DIR IMAGE_DIFF" >&2
        exit 2
    fi
    require_window_tools
    mkdir -p "$3"
    rm -f "$3"/*.png "$3"/*.xwd "$3"/*.log "$3"/*.txt
    run_in_xvfb 560 1024x768x24 "$(absolute "$script")" --inside-xvfb "$(absolute "$1")" \
        "$(absolute "$2")" "$(absolute "$3")" "$(absolute "$4")"
}
