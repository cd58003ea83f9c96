#!/usr/bin/env bash
# The Debian package (issue 23 item 2): `cpack -G DEB` makes vplab_VERSION_ARCH.deb of the installed
# files under /usr, its Depends found by dpkg-shlibdeps (the libraries vplab links, with the versions
# their symbols need) beside the ones vplab loads at run time (cmake/Package.cmake), and lintian finds
# nothing at any level (errors, warnings, info, pedantic, experimental).
# Installing it into a clean Debian 12 root needs root and a mirror: scripts/package-clean-root.sh.
# Usage: package_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(realpath "$1") source=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "package_test: $*" >&2; exit 1; }
for tool in cpack dpkg-deb dpkg-shlibdeps lintian; do
  command -v "$tool" >/dev/null || fail "$tool is missing (scripts/setup.sh installs dpkg-dev and lintian)"
done

cpack --config "$build/CPackConfig.cmake" -B "$work" >"$work/cpack.log" 2>&1 || { cat "$work/cpack.log" >&2; fail "cpack failed"; }
version=$(sed -n 's/^project(vplab VERSION \([0-9.]*\) .*/\1/p' "$source/CMakeLists.txt")
deb="$work/vplab_${version}_$(dpkg --print-architecture).deb"
[ -f "$deb" ] || fail "cpack made no $(basename "$deb"): $(ls "$work")"

field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = vplab ] && [ "$(field Version)" = "$version" ] && [ "$(field Section)" = education ] ||
  fail "control: $(field Package) $(field Version) $(field Section)"
depends=$(field Depends)
# dpkg-shlibdeps's work: versioned dependencies on the linked libraries' packages
for linked in 'libc6 (>= ' 'libglfw3 (>= ' 'libosmesa6 (>= ' 'libstdc++6 (>= ' 'libtinyobjloader2rc10 (>= '; do
  [[ "$depends" == *"$linked"* ]] || fail "Depends lacks \"$linked…\" (dpkg-shlibdeps): $depends"
done
for loaded in libegl1 libegl-mesa0 libgl1 libglx-mesa0 libgl1-mesa-dri fonts-dejavu-core; do
  [[ ", $depends," == *", $loaded,"* ]] || fail "Depends lacks $loaded, which vplab loads at run time: $depends"
done
dpkg-deb -c "$deb" | awk '{print $6}' | sed 's|^\./|/|' >"$work/files"
for f in /usr/bin/vplab /usr/share/vplab/scenes/default.json /usr/share/vplab/meshes/house.obj \
         /usr/share/applications/vplab.desktop /usr/share/icons/hicolor/256x256/apps/vplab.png \
         /usr/share/man/man1/vplab.1.gz /usr/share/bash-completion/completions/vplab \
         /usr/share/doc/vplab/copyright /usr/share/doc/vplab/changelog.gz; do
  grep -qx "$f" "$work/files" || fail "the package lacks $f"
done
if grep -v -e '^/usr/' -e '^/$' "$work/files" | grep . ; then fail "the package installs outside /usr"; fi
grep -q -e '/test_' -e '/bench_' -e '\.a$' "$work/files" && fail "the package carries test or build files: $(grep -e '/test_' -e '/bench_' -e '\.a$' "$work/files" | head -3)"
dpkg-deb -x "$deb" "$work/root"
file -b "$work/root/usr/bin/vplab" | grep -q ', stripped' || fail "vplab is not stripped: $(file -b "$work/root/usr/bin/vplab")"
zcat "$work/root/usr/share/doc/vplab/changelog.gz" | head -1 | grep -q "^vplab ($version) " ||
  fail "the Debian changelog does not begin with this version: $(zcat "$work/root/usr/share/doc/vplab/changelog.gz" | head -1)"

# lintian at every level; nothing may be left (a finding that must stay would be listed here with why)
lintian --display-level '>=pedantic' --display-experimental --info "$deb" 2>&1 |
  grep -E '^[EWIPX]: ' >"$work/lintian" || true
if [ -s "$work/lintian" ]; then
  echo "lintian's findings on $(basename "$deb"):" >&2
  lintian --display-level '>=pedantic' --display-experimental --info "$deb" >&2 2>&1 || true
  fail "lintian found $(wc -l <"$work/lintian") problem(s)"
fi
echo "package_test: $(basename "$deb") ($(stat -c %s "$deb") bytes), lintian clean; Depends: $depends"
