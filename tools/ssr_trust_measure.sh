#!/usr/bin/env bash
# Issue 21 item 1 measurements (docs/perf.md, "Trusted SSR"): hybrid against rt on every scene the
# issue names, at 640x360 with the cpu backend, frames 1800, 2100, 2300 and 4400.
#   tools/ssr_trust_measure.sh OUT [render options]
# GLINT (default: glint on PATH) names the binary; GLINT_SCENES (default: atrium atrium-simple sponza
# scenes/sponza-all-reflective.scene.json) the scenes. Output: OUT/<scene>-<mode>/{timings.csv,frame_*.png}
# and OUT/compare/<scene>_<frame>.json; tools/ssr_trust_table.py OUT prints the table.
set -euo pipefail
out=${1:?usage: ssr_trust_measure.sh OUT [render options]}
shift
glint=${GLINT:-glint}
here=$(cd "$(dirname "$0")/.." && pwd)
scenes=${GLINT_SCENES:-"atrium atrium-simple sponza $here/scenes/sponza-all-reflective.scene.json"}
frames=1800,2100,2300,4400
mkdir -p "$out/compare"
for scene in $scenes; do
  name=$(basename "$scene" .scene.json)
  for mode in hybrid rt; do
    "$glint" render "$scene" --frames "$frames" --width 640 --height 360 --backend cpu --reflections "$mode" \
      --overwrite --out "$out/$name-$mode" "$@" > /dev/null
  done
  for frame in ${frames//,/ }; do
    f=$(printf 'frame_%05d.png' "$frame")
    [ -f "$out/$name-hybrid/$f" ] || continue
    "$glint" compare "$out/$name-hybrid/$f" "$out/$name-rt/$f" --json "$out/compare/${name}_${frame}.json" > /dev/null
  done
done
echo "ssr_trust_measure: done, results in $out"
