#!/usr/bin/env bash
# Renders the pictures of the README and of docs/ into docs/images/ with the built vplab (run
# scripts/setup.sh first).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
vplab="${VPLAB:-$root/build/vplab}"
out="$root/docs/images"
mkdir -p "$out"
# The whole viewer at a projector's 1280 × 720: as it opens, at UI scale 1.6 with the Lecture tab and
# the matrices, and with the divide-first comparison beside the depth plot.
"$vplab" render --view ui --size 1280x720 --out "$out/viewer.png"
"$vplab" render --view ui --size 1280x720 --ui-scale 1.6 --tab lecture --tab matrices --out "$out/viewer-lecture.png"
"$vplab" render --view ui --size 1280x720 --strategy divide-first --tab clipping --tab depth \
  --out "$out/viewer-divide-first.png"
# In German (View > Language, --lang), at a projector's scale with the Clipping tab and the matrices.
"$vplab" render --view ui --size 1280x720 --ui-scale 1.6 --lang de --tab clipping --tab matrices --out "$out/viewer-de.png"
# A lesson as the lecture hall sees it, in German at 1280 × 720 × 1.6: the real window (under Xvfb
# when there is no display) at the clipping lesson's step 5, and a still of the view-orientation lesson.
window() { if [ -n "${DISPLAY:-}" ]; then "$@"; else xvfb-run -a -s "-screen 0 1280x720x24" "$@"; fi; }
window "$vplab" --lesson 05-clipping.de --step 5 --ui-scale 1.6 --lang de --quit-after-frames 90 --wait-for-views 20 \
  --screenshot "$out/lesson-window.png"
stills="$(mktemp -d)"
"$vplab" render --lesson 02-view-orientation.de --size 400x300 --ui-scale 1.6 --out "$stills"
cp "$stills/step-06.png" "$out/lesson-still.png"
rm -rf "$stills"
"$vplab" render --view all --style shaded --size 480x360 --out "$out/all-shaded.png"
"$vplab" render --view all --style hidden-line --size 480x360 --out "$out/all-hidden-line.png"
"$vplab" render --scene "$root/assets/scenes/behind-the-eye.json" --view all --style shaded --size 480x360 \
  --out "$out/behind-the-eye.png"
"$vplab" render --scene "$root/assets/scenes/depth-nonlinearity.json" --view all --style shaded --size 480x360 \
  --out "$out/depth-nonlinearity.png"
"$vplab" render --scene "$root/assets/scenes/clip-planes.json" --view all --style shaded --size 480x360 \
  --out "$out/clip-planes.png"
"$vplab" render --view all --style hidden-line --size 480x360 --theme light --out "$out/all-light.png"
"$vplab" render --view camera --style hidden-line --out "$out/camera-hidden-line.svg"
for t in 0 1 2 2.5 3 4; do
  "$vplab" render --view morph --morph-t "$t" --size 320x240 --out "$out/morph-$t.png"
done
# For course staff: the first page of a German clipping sheet as it prints, and the first page of its
# solution (pdflatex, pdftoppm).
tmp="$(mktemp -d)"
"$vplab" exercise --seed 3 --topic clipping --lang de --out "$tmp/ex"
for doc in sheet solution; do
  (cd "$tmp/ex" && pdflatex -interaction=nonstopmode -halt-on-error "$doc.tex" >/dev/null)
  pdftoppm -r 70 -png -f 1 -l 1 -singlefile "$tmp/ex/$doc.pdf" "$out/course-$doc"
done
rm -rf "$tmp"
echo "pictures written to $out"
