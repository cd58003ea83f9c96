#!/usr/bin/env bash
# A lesson in the real window under Xvfb (run by ctest through xvfb-run, tests/CMakeLists.txt), as a
# lecturer presents it (docs/lecturers.md "Lessons"):
#  1. `vplab --lesson NAME --step 5` opens the bundled lesson at step 5; F12 shows its picture;
#  2. → (what a clicker sends) moves to step 6: after the move the window is another picture, and
#     once the move is over the window is idle again (< 2 % of one core over 3 s);
#  3. a number and Enter jump back to step 5: the picture is step 5's again, pixel for pixel;
#  4. Ctrl+Q quits at once: a lesson's step leaves nothing unsaved to ask about.
# Usage: lesson_window.sh VPLAB
set -euo pipefail
vplab=$(realpath "$1")
work=$(mktemp -d)
trap '[ -n "${pid:-}" ] && kill "$pid" 2>/dev/null; rm -rf "$work"' EXIT
cd "$work"
export XDG_STATE_HOME="$work/state"
fail() { echo "FAIL: $*" >&2; echo "--- vplab's stderr:" >&2; cat "$work"/err >&2 || true; exit 1; }
cpu_ticks() { local a; read -r -a a < "/proc/$1/stat"; echo $((a[13] + a[14])); }
hz=$(getconf CLK_TCK)

# Waits until a whole second passes with < 2 % of a core used (at most 60 s): the window settled.
settle() {
  for _ in $(seq 60); do
    a=$(cpu_ticks $pid); sleep 1; b=$(cpu_ticks $pid)
    (( (b - a) * 100 < 2 * hz )) && return 0
  done
  fail "the window never settled"
}
# F12, then the screenshot renamed to $1 (F12's names change only by the second).
shot() {
  rm -f vplab-*.png
  xdotool key F12
  for _ in $(seq 100); do ls vplab-*.png >/dev/null 2>&1 && break; sleep 0.1; done
  local f; f=$(ls vplab-*.png 2>/dev/null | head -1) || true
  [ -n "$f" ] || fail "F12 wrote no screenshot ($1)"
  sleep 0.3  # written whole (the runner writes it before the next frame)
  mv "$f" "$1"
  (( $(stat -c %s "$1") > 20000 )) || fail "the screenshot $1 has only $(stat -c %s "$1") bytes: blank?"
}

"$vplab" --lesson 02-view-orientation --step 5 --ui-scale 1.25 2> err &
pid=$!
wid=$(timeout 30 xdotool search --sync --onlyvisible --name '^vplab' | head -1) || fail "no vplab window appeared"
settle
xdotool windowfocus --sync "$wid"
shot step5.png

# 2. The next step, its move, and idle again.
xdotool key Right
sleep 2
settle
shot step6.png
cmp -s step5.png step6.png && fail "→ did not change the picture (step 5 and 6 are alike)"
t0=$(cpu_ticks $pid); s0=$(date +%s%N)
sleep 3
t1=$(cpu_ticks $pid); s1=$(date +%s%N)
pct100=$(( (t1 - t0) * 100 * 100 * 1000000000 / hz / (s1 - s0) ))
printf 'CPU over 3 s after the move: %d.%02d %% of one core\n' $((pct100 / 100)) $((pct100 % 100))
(( pct100 < 200 )) || fail "the window is not idle after the move: ${pct100}/100 % of a core"

# 3. "5", Enter: step 5 again, the same picture in the upper half right of the left column (the
#    world and camera views; the panels' status line names the last screenshot, a name that
#    changes by the second, and a step whose evidence is in the inspector puts the controls below
#    right).
xdotool key 5 Return
sleep 2
settle
shot back5.png
python3 - step5.png back5.png step6.png <<'PY' || fail "step 5 reached again by its number is not step 5's picture"
import struct, sys, zlib
def pixels(path):  # an 8-bit RGB or RGBA PNG, not interlaced, as vplab writes them (stb_image_write)
    data = open(path, 'rb').read()
    pos, chunks, width, height, channels = 8, b'', 0, 0, 0
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8]); body = data[pos + 8:pos + 8 + n]; pos += 12 + n
        if kind == b'IHDR': width, height, _, colour = struct.unpack('>IIBB', body[:10]); channels = 4 if colour == 6 else 3
        elif kind == b'IDAT': chunks += body
    raw, stride, rows, prev = zlib.decompress(chunks), width * channels, [], bytearray(width * channels)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0; b = prev[i]; c = prev[i - channels] if i >= channels else 0
            p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (0, a, b, (a + b) // 2, a if pa <= pb and pa <= pc else b if pb <= pc else c)[f]) & 255
        rows.append(line); prev = line
    return width, channels, rows
def right_of_controls(path):
    width, channels, rows = pixels(path)
    return [bytes(r[400 * channels:]) for r in rows[:len(rows) // 2]]
first, again, other = (right_of_controls(p) for p in sys.argv[1:4])
differing = sum(a != b for a, b in zip(first, again))
print(f"rows of the upper views that differ between step 5 and step 5 again: {differing}")
assert first != other, "step 6 is step 5's picture"
sys.exit(0 if differing == 0 else 1)
PY

# 4. Ctrl+Q: nothing unsaved, no question.
xdotool key ctrl+q
for _ in $(seq 50); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
kill -0 $pid 2>/dev/null && fail "Ctrl+Q did not quit within 5 s (did the lesson leave unsaved changes?)"
status=0; wait $pid || status=$?
unset pid
(( status == 0 )) || fail "vplab ended with status $status"
echo "ok"
