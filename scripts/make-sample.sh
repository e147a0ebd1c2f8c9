#!/usr/bin/env bash
# Rebuilds the bundled sample projects from the shared data (CGAL elephant, CC0, with the Tux Paint
# side-view elephant drawing, GPL-2+, and the openclipart contour elephant, public domain):
#   elephant-plain.celform       the model and the two drawings, nothing else (tests, render baselines)
#   elephant-highlights.celform  the plain one with the stylized highlight examples
#   elephant.celform             the showcase the editor opens: two key viewpoints made from the
#                                drawings and a turntable, so Play shows view-dependent geometry
#   elephant-trunk.glb           the elephant skinned, its trunk swinging: an animated character to
#                                import (scripts/make-animated-sample.py)
# Usage: scripts/make-sample.sh [path/to/celform]   (default: build/release/app/celform)
set -euo pipefail
cd "$(dirname "$0")/.."
celform=${1:-build/release/app/celform}
data=../shared/data
"$celform" new "$data/meshes/cgal_elephant.off" \
  --drawing "$data/drawings/tuxpaint_elephant.png" \
  --drawing "$data/drawings/openclipart_contour_elephant.svg" \
  --drawing resources/samples/drawings/elephant-sheet-side.png \
  --drawing resources/samples/drawings/elephant-sheet-front.png \
  --out resources/samples/elephant-plain.celform
rm -f resources/samples/elephant-plain.celform.bak
echo "wrote resources/samples/elephant-plain.celform"

# The highlight sample: the paper's two worked examples (Anjyo & Hiramitsu 2003, Figures 5 and 6)
# on the same elephant, keyed over 30 frames, tuned for the front view, which is the project's
# render camera (the editor opens looking through it, and `celform render` uses it). The ear, nearly flat like a car window, carries the window streaks
# (rotation, directional scaling, split); the body carries a crescent (a layer minus a hidden,
# shifted copy).
hl=resources/samples/elephant-highlights.celform
cp resources/samples/elephant-plain.celform "$hl"
"$celform" patch "$hl" --add ear --sphere 0.14,-0.07,0.22,0.12
"$celform" patch "$hl" --add body --sphere -0.06,-0.12,0.15,0.2
"$celform" highlight "$hl" --add window --patch ear --smooth 8 --epsilon 0.03 \
  --op translate:0,0 --op rotate:30 --op scale:0.6 --op split:0.25,0 --frame 0
"$celform" highlight "$hl" --add window --frame 29 \
  --op translate:0.04,-0.02 --op rotate:50 --op scale:0.6 --op split:0.25,0
"$celform" highlight "$hl" --add "crescent cut" --patch body --smooth 6 --epsilon 0.04 \
  --op translate:0.1,0.1 --visible off --frame 0
"$celform" highlight "$hl" --add "crescent cut" --frame 29 --op translate:0.14,0.04
"$celform" highlight "$hl" --add crescent --patch body --smooth 6 --epsilon 0.04 \
  --combine "subtract:crescent cut" --frame 0
"$celform" set "$hl" --render-view 0,0,1
rm -f "$hl.bak"
echo "wrote $hl"

# The showcase: keys made by Fit to Drawing from the model sheet in the model's own pose
# (resources/samples/drawings, made by scripts/make-model-sheet.sh: the ears bigger and the trunk
# longer than the model's). Each key starts from a rough hand alignment, 5 to 7 degrees off the
# drawing's camera (resources/samples/README.md), then `celform fit --camera --shape` aligns the
# camera and deforms the key until its silhouette meets the drawing's outline; one brush stroke
# touches the trunk's tip up. Seen from between the keys, the blend returns to the base model, so
# the turntable shows the ears and trunk growing towards each drawn view.
show=resources/samples/elephant.celform
sheet=resources/samples/drawings
"$celform" new "$data/meshes/cgal_elephant.off" --out "$show"
"$celform" key add "$show" --name side --from-base --eye 0.2476,0.1357,2.348 --target 0.001793,0.012576,0.01161 \
  --up 0,1,0 --drawing "$sheet/elephant-sheet-side.png"
"$celform" key add "$show" --name front --from-base --eye 2.4115,0.1436,0.189 --target 0.067994,0.020561,-0.016062 \
  --up 0,1,0 --drawing "$sheet/elephant-sheet-front.png"
for key in side front; do
  "$celform" fit "$show" --key "$key" --camera --shape --json | grep -E "iou_|chamfer_px_|milliseconds"
done
"$celform" brush "$show" --key side --vertex 691 --radius 0.12 --drag 0.01,0.01 >/dev/null
"$celform" camera "$show" --turntable 48 --elevation 10
# Issue 25: the showcase is drawn on its smooth surface (Loop level 2), tones and lines as a studio's.
"$celform" set "$show" --subdivision 2
rm -f "$show.bak"
echo "wrote $show"

# The README's picture of it: eight frames of the turntable side by side (oiiotool comes with
# Debian's openimageio-tools, which scripts/setup.sh installs).
frames=$(mktemp -d)
"$celform" render "$show" --frames 0-47:6 --size 240x240 --out "$frames/turntable_####.png" 2>/dev/null
mkdir -p docs/images
oiiotool "$frames"/turntable_*.png --mosaic 8x1 -o docs/images/turntable-strip.png
rm -rf "$frames"
echo "wrote docs/images/turntable-strip.png"

python3 scripts/make-animated-sample.py "$data/meshes/cgal_elephant.off" resources/samples/elephant-trunk.glb
