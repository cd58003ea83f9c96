#!/usr/bin/env bash
# Installs vplab's .deb into a clean Debian 12 root, as a lab machine gets it (issue 23 item 2): a
# debootstrap minbase root with no compiler, no cmake, no -dev package and none of this machine's caches;
# `apt-get install ./vplab_*.deb` must bring everything vplab needs at run time (Mesa's llvmpipe, EGL,
# GLX, fonts) from the Debian mirror. Then, in the root: vplab --version, presets, render (the camera view
# to PNG, headless on llvmpipe), render of the world view as SVG, dump and exercise must work, and nothing
# of a build may have come with it. Needs root (debootstrap, chroot, mounts) and the mirror this machine
# uses; takes a few minutes (the pristine root is made once per machine and unpacked anew for each run).
# Usage: sudo scripts/package-clean-root.sh [DEB] [OUT_DIR]
#   DEB      the package (default: made by cpack in $VPLAB_BUILD, or build/)
#   OUT_DIR  where the root's pictures and logs are copied (default: /tmp/vplab-package-root-out)
set -euo pipefail
VPLAB_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$VPLAB_ROOT/scripts/lib.sh"
[ "$(id -u)" -eq 0 ] || { echo "package-clean-root.sh: needs root (debootstrap, chroot)" >&2; exit 2; }
build="${VPLAB_BUILD:-$VPLAB_ROOT/build}"
deb="${1:-}"
out="${2:-/tmp/vplab-package-root-out}"
if [ -z "$deb" ]; then
  (cd "$build" && cpack -G DEB >/dev/null)
  deb=$(ls "$build"/vplab_*.deb | head -1)
fi
deb=$(realpath "$deb")
vplab_install_missing debootstrap

pristine=/tmp/vplab-package-pristine.tgz
root=/tmp/vplab-package-root
mirror=$(awk '/^URIs:/{print $2; exit}' /etc/apt/sources.list.d/debian.sources 2>/dev/null || true)
[ -n "$mirror" ] || mirror=$(awk '/^deb /{print $2; exit}' /etc/apt/sources.list)
if [ ! -f "$pristine" ]; then
  echo "package-clean-root.sh: debootstrap bookworm (minbase) from $mirror" >&2
  rm -rf "$root.boot"
  debootstrap --variant=minbase --include=ca-certificates bookworm "$root.boot" "$mirror" >/tmp/vplab-package-debootstrap.log 2>&1 ||
    { tail -20 /tmp/vplab-package-debootstrap.log >&2; exit 1; }
  tar czf "$pristine" -C "$root.boot" . && rm -rf "$root.boot"
fi
for m in dev/pts dev sys proc; do mountpoint -q "$root/$m" 2>/dev/null && umount -l "$root/$m"; done
rm -rf "$root" && mkdir -p "$root" && tar xzf "$pristine" -C "$root"
trap 'for m in dev sys proc; do umount -l "$root/$m" 2>/dev/null || true; done' EXIT
for m in proc sys dev; do mount --bind "/$m" "$root/$m"; done
cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
cp "$deb" "$root/tmp/"
mkdir -p "$out"

chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 /bin/bash -euo pipefail -c '
  fail() { echo "FAIL: $*" >&2; exit 1; }
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q >/tmp/apt.log
  apt-get install -y -q ./tmp/'"$(basename "$deb")"' >>/tmp/apt.log 2>&1 || { tail -30 /tmp/apt.log >&2; fail "apt-get install failed"; }
  echo "installed: $(dpkg-query -W -f="\${Package} \${Version}" vplab), $(dpkg -l | grep -c "^ii") packages in the root"
  for tool in cc gcc g++ c++ cmake make ld pkg-config; do
    command -v "$tool" >/dev/null && fail "the root has $tool: the package pulled in build tools"
  done
  dpkg -l | awk "/^ii/{print \$2}" | grep -E -- "-dev(:|$)" && fail "the package pulled in -dev packages"
  cd /tmp
  vplab --version
  vplab presets | head -3
  vplab render --view camera --out camera.png 2>render.err || { cat render.err >&2; fail "vplab render"; }
  [ "$(head -c 8 camera.png | od -An -tx1 | tr -d " ")" = 89504e470d0a1a0a ] || fail "vplab render wrote no PNG"
  size=$(stat -c %s camera.png); [ "$size" -gt 5000 ] || fail "camera.png has only $size bytes: blank?"
  vplab render --scene /usr/share/vplab/scenes/mesh-obj.json --view world --out world.svg
  grep -q "font-family=\"DejaVu Sans" world.svg || fail "the SVG does not use DejaVu Sans: the font is missing"
  vplab dump >dump.json
  grep -q "\"npc_from_vrc\"" dump.json || fail "vplab dump wrote no stages"
  vplab exercise --seed 1 --topic pipeline --out sheet >/dev/null
  [ -s sheet/answer.json ] || fail "vplab exercise wrote no answer template"
  echo "vplab render, dump and exercise work in the clean root ($size bytes of PNG)"
' 2>&1 | tee "$out/log.txt"
status=${PIPESTATUS[0]}
cp "$root"/tmp/camera.png "$root"/tmp/world.svg "$root"/tmp/dump.json "$out/" 2>/dev/null || true
exit "$status"
