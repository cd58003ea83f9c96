#!/usr/bin/env bash
# `cmake --install` into a temporary prefix (issue 23 item 1): the installed vplab renders, writes an
# exercise sheet and lists the bundled scenes from the prefix alone, never opening a file of the source
# or the build tree (strace records every file it names); the desktop entry, the icon, the manual page
# and bash's completion are there and say what the program takes; the desktop entry's command opens a
# window under Xvfb whose title, class and icon are vplab's.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(realpath "$1") source=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
fail() { echo "install_test: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" >/dev/null
for f in bin/vplab share/vplab/scenes/default.json share/vplab/scenes/mesh-obj.json share/vplab/meshes/house.obj \
         share/vplab/lessons/01-synthetic-camera.en.json share/vplab/lessons/01-synthetic-camera.de.json \
         share/applications/vplab.desktop share/icons/hicolor/256x256/apps/vplab.png share/man/man1/vplab.1.gz \
         share/bash-completion/completions/vplab share/doc/vplab/CHANGELOG.md \
         share/doc/vplab/docs/lecturers.md share/doc/vplab/docs/command-line.md; do
  [ -f "$prefix/$f" ] || fail "cmake --install wrote no $f"
done

# ---------------------------------------------------------------- the installed program, from a directory of its own
cd "$work"
command -v strace >/dev/null || fail "strace is missing (scripts/setup.sh installs it)"
traced() {  # runs the installed vplab with ARGS under strace; the log of files it named is $work/trace
  strace -f -qq -e trace=%file -o "$work/trace" "$prefix/bin/vplab" "$@"
  if grep -F -e "\"$source/" -e "\"$build/" "$work/trace" >"$work/outside"; then
    echo "the installed vplab $* named files of the source or build tree:" >&2
    head -5 "$work/outside" >&2
    exit 1
  fi
}
traced presets >"$work/presets"
grep -q "^default  *Default lecture scene" "$work/presets" || fail "vplab presets does not list the default scene"
grep -q "^    $prefix/share/vplab/scenes/mesh-obj.json$" "$work/presets" || fail "the presets are not the prefix's: $(head -2 "$work/presets")"
traced render --scene "$prefix/share/vplab/scenes/mesh-obj.json" --view camera --out "$work/camera.png"
[ "$(head -c 8 "$work/camera.png" | od -An -tx1 | tr -d ' ')" = 89504e470d0a1a0a ] || fail "vplab render wrote no PNG"
traced exercise --seed 2 --topic pipeline --out "$work/sheet"
[ -s "$work/sheet/answer.json" ] || fail "vplab exercise wrote no answer template"
traced --version >"$work/version"
grep -Eq '^vplab [0-9]+\.[0-9]+\.[0-9]+ \(git [0-9a-f]+|unknown\)$' "$work/version" || fail "vplab --version: $(cat "$work/version")"

# ---------------------------------------------------------------- what the desktop and the shell find
desktop="$prefix/share/applications/vplab.desktop"
grep -qx 'Exec=vplab %f' "$desktop" && grep -qx 'Icon=vplab' "$desktop" && grep -qx 'MimeType=application/json;' "$desktop" ||
  fail "the desktop entry does not open scenes with vplab: $(cat "$desktop")"
if command -v desktop-file-validate >/dev/null; then desktop-file-validate "$desktop"; fi
[ "$(od -An -tu1 -j16 -N8 "$prefix/share/icons/hicolor/256x256/apps/vplab.png" | tr -s ' ')" = " 0 0 1 0 0 0 1 0" ] ||
  fail "the icon is not 256 × 256"
man="$work/vplab.1"
zcat "$prefix/share/man/man1/vplab.1.gz" >"$man"
for sub in dump render bench presets exercise 'grade numbers' 'grade batch' 'grade image'; do
  grep -q "^\.SH VPLAB ${sub^^}$" "$man" || fail "the manual page has no section for vplab $sub"
done
grep -q 'max\\-shift' "$man" || fail "the manual page leaves out grade image's --max-shift"
complete_words() {  # what bash completes for the command line "$@" (the last word being typed)
  bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _vplab; printf "%s\n" "${COMPREPLY[@]}"' \
    _ "$prefix/share/bash-completion/completions/vplab" "$@"
}
complete_words vplab ren | grep -qx render || fail "bash does not complete 'vplab ren' to render"
complete_words vplab render --sc | grep -qx -- --scene || fail "bash does not complete 'vplab render --sc' to --scene"
complete_words vplab grade image --max-s | grep -qx -- --max-shift || fail "bash does not complete grade image's --max-shift"

# ---------------------------------------------------------------- the desktop entry starts the viewer
# As a desktop starts it: the entry's Exec line with %f replaced by the opened file, vplab found on PATH.
# The window must carry vplab's title, WM_CLASS (the entry's StartupWMClass) and the installed icon,
# pixel for pixel (_NET_WM_ICON: width, height, then ARGB cardinals, top row first).
if command -v Xvfb >/dev/null && command -v xdotool >/dev/null && command -v xprop >/dev/null; then
  exec 3>"$work/display"  # Xvfb picks a free display and writes its number: no race with other tests
  Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp 2>/dev/null & xvfb=$!
  exec 3>&-
  trap 'kill $xvfb ${viewer:-} 2>/dev/null; rm -rf "$work"' EXIT
  for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
  export DISPLAY=":$(cat "$work/display")"
  scene="$prefix/share/vplab/scenes/default.json"
  exec_line=$(sed -n 's/^Exec=//p' "$desktop")
  read -r -a command <<<"${exec_line//%f/$scene}"
  PATH="$prefix/bin:$PATH" "${command[@]}" 2>"$work/viewer-err" & viewer=$!
  wid=$(timeout 60 xdotool search --sync --onlyvisible --class '^vplab$' | head -1) ||
    fail "the desktop entry's command opened no window of class vplab: $(cat "$work/viewer-err")"
  # The title names the scene from the first frames on (the window opens as "vplab"): wait for it.
  for _ in $(seq 100); do
    title=$(xprop -id "$wid" -notype WM_NAME)
    [ "$title" = 'WM_NAME = "vplab — default.json"' ] && break
    sleep 0.1
  done
  [ "$title" = 'WM_NAME = "vplab — default.json"' ] || fail "the window's title is $title"
  [ "$(xprop -id "$wid" -notype WM_CLASS)" = 'WM_CLASS = "vplab", "vplab"' ] || fail "the window's class: $(xprop -id "$wid" WM_CLASS)"
  xprop -id "$wid" -len 1000000 -notype -f _NET_WM_ICON 32c ' $0+' _NET_WM_ICON >"$work/icon"
  python3 - "$prefix/share/icons/hicolor/256x256/apps/vplab.png" "$work/icon" <<'PY' || fail "the window's icon is not vplab's"
import struct, sys, zlib
png = open(sys.argv[1], "rb").read()
chunks, i = {}, 8
while i < len(png):  # the PNG's chunks: IHDR, then the image data, possibly in several IDAT chunks
    n, kind = struct.unpack(">I4s", png[i:i + 8]); chunks[kind] = chunks.get(kind, b"") + png[i + 8:i + 8 + n]; i += 12 + n
w, h, depth, color = struct.unpack(">IIBB", chunks[b"IHDR"][:10])
assert (depth, color) == (8, 6), "an RGBA8 PNG"
raw, rows, prev, stride = zlib.decompress(chunks[b"IDAT"]), [], bytearray(w * 4), w * 4
for y in range(h):  # undo the per-row filters (PNG spec, section 9)
    f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for x in range(stride):
        a, b, c = line[x - 4] if x >= 4 else 0, prev[x], prev[x - 4] if x >= 4 else 0
        p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
        line[x] = (line[x] + [0, a, b, (a + b) // 2, a if pa <= pb and pa <= pc else b if pb <= pc else c][f]) & 255
    rows.append(line); prev = line
expected = [w, h] + [r[x + 3] << 24 | r[x] << 16 | r[x + 1] << 8 | r[x + 2] for r in rows for x in range(0, stride, 4)]
got = [int(v) for v in open(sys.argv[2]).read().split(None, 1)[1].split(",")]
if got != expected:
    print(f"_NET_WM_ICON holds {len(got)} values, {got[:2]}; the icon is {w} x {h}", file=sys.stderr); sys.exit(1)
PY
  kill "$viewer"; wait "$viewer" 2>/dev/null || true; viewer=
  echo "install_test: the desktop entry opened the window \"vplab — default.json\" with vplab's icon"
else
  echo "install_test: no Xvfb, xdotool or xprop: the desktop entry's window is not checked" >&2
fi
echo "install_test: the installed vplab works from $prefix alone"
