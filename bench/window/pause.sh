#!/usr/bin/env bash
# How long the real window pauses when a key changes the scene (issue 20: the CPU pipeline off the
# window's thread). Starts `vplab --scene SCENE --report-frames` under the current X display (run it
# through xvfb-run), waits until the window is idle, presses P (the next projection: a new run of
# the pipeline) COUNT times a few seconds apart, ends it with SIGTERM and prints vplab's report: the
# longest frame, and the longest of the frames that answered input (the pause a lecturer sees).
# Usage: xvfb-run -a -s "-screen 0 1280x800x24" bench/window/pause.sh VPLAB SCENE [COUNT]
set -euo pipefail
vplab=$(realpath "$1"); scene=$(realpath "$2"); count=${3:-6}
work=$(mktemp -d)
trap '[ -n "${pid:-}" ] && kill "$pid" 2>/dev/null; rm -rf "$work"' EXIT
export XDG_STATE_HOME="$work/state"
"$vplab" --scene "$scene" --report-frames 2> "$work/err" &
pid=$!
wid=$(timeout 60 xdotool search --sync --onlyvisible --name '^vplab' | head -1)
cpu_ticks() { local a; read -r -a a < "/proc/$1/stat"; echo $((a[13] + a[14])); }
hz=$(getconf CLK_TCK)
for _ in $(seq 120); do  # idle: a second with < 2 % of a core
  a=$(cpu_ticks $pid); sleep 1; b=$(cpu_ticks $pid)
  (( (b - a) * 100 < 2 * hz )) && break
done
xdotool windowfocus --sync "$wid"
for _ in $(seq "$count"); do
  xdotool key p
  sleep 3  # the views of a million triangles take ~2 s on llvmpipe's render thread
done
kill -TERM $pid
wait $pid || true
unset pid
grep "frames drawn" "$work/err"
