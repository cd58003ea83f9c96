#!/usr/bin/env bash
# `cmake --install` into a temporary prefix (issue 23 item 1): the installed vplab renders, writes an
# exercise sheet and lists the bundled scenes from the prefix alone, never opening a file of the source
# or the build tree (strace records every file it names); the desktop entry, the icon, the manual page
# and bash's completion are there and say what the program takes.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(realpath "$1") source=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
fail() { echo "install_test: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" >/dev/null
for f in bin/vplab share/vplab/scenes/default.json share/vplab/scenes/mesh-obj.json share/vplab/meshes/house.obj \
         share/applications/vplab.desktop share/icons/hicolor/256x256/apps/vplab.png share/man/man1/vplab.1 \
         share/bash-completion/completions/vplab share/doc/vplab/CHANGELOG.md; do
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
man="$prefix/share/man/man1/vplab.1"
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
echo "install_test: the installed vplab works from $prefix alone"
