#!/usr/bin/env bash
# Rebuilds the bundled sample project from the shared data (CGAL elephant, CC0, with the Tux Paint
# side-view elephant drawing, GPL-2+, and the openclipart contour elephant, public domain).
# Usage: scripts/make-sample.sh [path/to/celform]   (default: build/release/app/celform)
set -euo pipefail
cd "$(dirname "$0")/.."
celform=${1:-build/release/app/celform}
data=../shared/data
"$celform" new "$data/meshes/cgal_elephant.off" \
  --drawing "$data/drawings/tuxpaint_elephant.png" \
  --drawing "$data/drawings/openclipart_contour_elephant.svg" \
  --out resources/samples/elephant.celform
rm -f resources/samples/elephant.celform.bak
echo "wrote resources/samples/elephant.celform"

# The highlight sample: the paper's two worked examples (Anjyo & Hiramitsu 2003, Figures 5 and 6)
# on the same elephant, keyed over 30 frames, tuned for the front view, which is the project's
# render camera (the editor opens looking through it, and `celform render` uses it). The ear, nearly flat like a car window, carries the window streaks
# (rotation, directional scaling, split); the body carries a crescent (a layer minus a hidden,
# shifted copy).
hl=resources/samples/elephant-highlights.celform
cp resources/samples/elephant.celform "$hl"
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
