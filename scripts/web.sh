#!/usr/bin/env bash
# Builds vplab for the web into build-web/ (docs/course-staff.md "The page on a course page"): index.html,
# vplab.js, vplab.wasm and vplab.data (the bundled scenes and meshes). Installs what it needs from Debian's
# packages (emscripten, and what the desktop build's setup installs for the headers), as
# scripts/setup.sh does, and takes Dear ImGui's sources from Debian's source package of the version
# the desktop links (1.86), with a private sources list: nothing in /etc changes, nothing else is
# downloaded, nothing is vendored. Serve the result with `python3 -m http.server -d build-web`.
set -euo pipefail

VPLAB_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WEB_BUILD="${VPLAB_WEB_BUILD:-$VPLAB_ROOT/build-web}"
IMGUI_VERSION=1.86
source "$VPLAB_ROOT/scripts/lib.sh"

packages=(emscripten nodejs cmake make python3-glad dpkg-dev brotli
          libglm-dev nlohmann-json3-dev libtinyobjloader-dev libstb-dev fonts-dejavu-core)
vplab_install_missing "${packages[@]}"

# ---------------------------------------------------------------- Dear ImGui's sources (Debian's imgui source package)
deps="$WEB_BUILD/deps"
imgui="$deps/imgui-$IMGUI_VERSION"
if [ ! -f "$imgui/imgui.cpp" ]; then
  echo "web.sh: fetching Dear ImGui $IMGUI_VERSION's sources from Debian (apt-get source imgui)" >&2
  apt_dir="$deps/apt"
  rm -rf "$apt_dir" && mkdir -p "$apt_dir/sources" "$apt_dir/lists/partial" "$deps/src"
  # The machine's own Debian mirror and suite (deb822 or one-line form), for deb-src.
  uri="" suite=""
  if [ -f /etc/apt/sources.list.d/debian.sources ]; then
    uri=$(awk '/^URIs:/ {print $2; exit}' /etc/apt/sources.list.d/debian.sources)
    suite=$(awk '/^Suites:/ {print $2; exit}' /etc/apt/sources.list.d/debian.sources)
  fi
  if [ -z "$uri" ] && [ -f /etc/apt/sources.list ]; then
    read -r uri suite < <(awk '$1 == "deb" && $2 !~ /^\[/ {print $2, $3; exit}' /etc/apt/sources.list)
  fi
  uri="${uri:-http://deb.debian.org/debian}" suite="${suite:-bookworm}"
  printf 'Types: deb-src\nURIs: %s\nSuites: %s\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
    "$uri" "$suite" > "$apt_dir/sources/debian-src.sources"
  apt_opts=(-o Dir::Etc::SourceList=/dev/null -o "Dir::Etc::SourceParts=$apt_dir/sources"
            -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache=$apt_dir/cache" -o Debug::NoLocking=1)
  apt-get "${apt_opts[@]}" update -q >&2
  # The version the desktop links (libimgui-dev), from the same suite.
  version=$(dpkg-query -W -f='${source:Version}' libimgui-dev 2>/dev/null || true)
  version="${version:-$IMGUI_VERSION+ds-1}"
  case "$version" in "$IMGUI_VERSION"+*) ;; *) echo "web.sh: libimgui-dev is $version, not $IMGUI_VERSION" >&2; exit 1 ;; esac
  (cd "$deps/src" && apt-get "${apt_opts[@]}" source -q "imgui=$version" >&2)
  unpacked=$(find "$deps/src" -mindepth 1 -maxdepth 1 -type d -name "imgui-*" | head -n 1)
  grep -q "#define IMGUI_VERSION *\"$IMGUI_VERSION\"" "$unpacked/imgui.h" ||
    { echo "web.sh: $unpacked is not Dear ImGui $IMGUI_VERSION" >&2; exit 1; }
  rm -rf "$imgui" && mv "$unpacked" "$imgui"
  rm -rf "$deps/src" "$apt_dir"
fi

# ---------------------------------------------------------------- configure and build (CMakePresets.json "web")
# Debian's emscripten works offline with its own frozen cache (EM_CACHE stays unset). Its JavaScript
# optimizer needs Debian's node modules when `node` is not Debian's own.
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"
cd "$VPLAB_ROOT"
emcmake cmake --preset web -B "$WEB_BUILD" -DVPLAB_IMGUI_SOURCE="$imgui" \
  "-DCMAKE_CROSSCOMPILING_EMULATOR=$(command -v node);--no-experimental-fetch" >/dev/null
cmake --build "$WEB_BUILD" -j "$(nproc)"
echo "web.sh: built $WEB_BUILD/index.html (serve it: python3 -m http.server -d $WEB_BUILD -b 127.0.0.1 8000)" >&2

# ---------------------------------------------------------------- the bundle for course pages (scripts/web_bundle.py)
version=$(sed -n 's/^project(vplab VERSION \([0-9][0-9.]*\).*/\1/p' "$VPLAB_ROOT/CMakeLists.txt")
python3 "$VPLAB_ROOT/scripts/web_bundle.py" "$WEB_BUILD" "${version:?web.sh: no version in CMakeLists.txt}"
