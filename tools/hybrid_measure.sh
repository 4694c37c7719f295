#!/usr/bin/env bash
# Issue-5 measurements on the atrium walkthrough (docs/perf.md, "Hybrid reflections"): renders the
# paper's four quality frames in ssr, hybrid and rt modes (static, and deformable with rebuild and
# refit), times them with --timings-only, and compares ssr and hybrid against rt with `glint compare`.
#   tools/hybrid_measure.sh OUT [--width W --height H --backend cpu|embree ...]
# Extra arguments go to every `glint render`. GLINT (default: glint on PATH) names the binary.
# Runs replace earlier ones in OUT (--overwrite). Output: OUT/<run>/{timings.csv,run.json,frame_*.png} and OUT/compare/<frame>_<mode>_<deform>.json;
# tools/hybrid_tables.py OUT prints the tables.
set -euo pipefail
out=${1:?usage: hybrid_measure.sh OUT [render options]}
shift
glint=${GLINT:-glint}
frames=1800,2100,2300,4400
mkdir -p "$out/compare"

render() {  # render NAME ARGS...
  local name=$1
  shift
  "$glint" render atrium --frames "$frames" --overwrite --out "$out/$name" "$@"
}

# Images (PNG writes between frames) for the quality tables.
for deform in off on; do
  for mode in ssr hybrid rt; do render "images-$mode-deform-$deform" --reflections "$mode" --deform "$deform" "$@"; done
  for frame in ${frames//,/ }; do
    f=$(printf 'frame_%05d.png' "$frame")
    for mode in ssr hybrid; do
      "$glint" compare "$out/images-$mode-deform-$deform/$f" "$out/images-rt-deform-$deform/$f" \
        --json "$out/compare/${frame}_${mode}_deform-${deform}.json" > /dev/null
    done
  done
done

# Timings: no PNG encoding between frames. Frame 1799 goes first as a warm-up (the first frame of a
# run pays for first-touch uploads; run.json's means leave it out).
timing_frames=1799,$frames
for mode in off ssr hybrid rt; do
  "$glint" render atrium --frames "$timing_frames" --timings-only --reflections "$mode" --deform off \
    --overwrite --out "$out/timing-$mode-static" "$@"
done
for mode in hybrid rt; do
  for update in rebuild refit; do
    "$glint" render atrium --frames "$timing_frames" --timings-only --reflections "$mode" --deform on \
      --update "$update" --overwrite --out "$out/timing-$mode-deform-$update" "$@"
  done
done
echo "hybrid_measure: done, results in $out"
