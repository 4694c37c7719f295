#!/usr/bin/env bash
# Issue-19 frame measurements (docs/perf.md, "GPU-first frame"): times `glint render --timings-only`
# over every combination of the axes below and writes one run folder per combination;
# tools/frame_table.py OUT prints the table (per-pass GPU means, steady-state frame, latency).
#   tools/frame_matrix.sh OUT [render options, e.g. --backend cuda --accel lbvh]
# Axes (environment, space-separated lists; defaults in brackets):
#   SCENES [atrium]  SIZES [1280x720]  MODES [off ssr hybrid rt]  DEFORMS [static refit rebuild]
#   SHADOWS [cube rt hybrid]  GBUFFERS [raster visibility]  FRAMES [2071:2110]
# DEFORMS: static (--deform off), refit or rebuild (--deform on --update ...); off and ssr modes
# trace no reflection rays, so they run static only unless their shadows are traced.
# GLINT names the binary (default: glint on PATH). Runs replace earlier ones (--overwrite).
# Run folders: OUT/<scene>-<size>-<mode>-<deform>-<shadows>-<gbuffer>/{timings.csv,run.json}.
set -euo pipefail
out=${1:?usage: frame_matrix.sh OUT [render options]}
shift
glint=${GLINT:-glint}
read -r -a scenes <<<"${SCENES:-atrium}"
read -r -a sizes <<<"${SIZES:-1280x720}"
read -r -a modes <<<"${MODES:-off ssr hybrid rt}"
read -r -a deforms <<<"${DEFORMS:-static refit rebuild}"
read -r -a shadows <<<"${SHADOWS:-cube rt hybrid}"
read -r -a gbuffers <<<"${GBUFFERS:-raster visibility}"
frames=${FRAMES:-2071:2110}
mkdir -p "$out"
total=$((${#scenes[@]} * ${#sizes[@]} * ${#modes[@]} * ${#deforms[@]} * ${#shadows[@]} * ${#gbuffers[@]}))
done_runs=0
for scene in "${scenes[@]}"; do
  for size in "${sizes[@]}"; do
    width=${size%x*} height=${size#*x}
    for mode in "${modes[@]}"; do
      for deform in "${deforms[@]}"; do
        for shadow in "${shadows[@]}"; do
          for gbuffer in "${gbuffers[@]}"; do
            done_runs=$((done_runs + 1))
            # Without rays (off/ssr with cube shadows) there is no structure to update.
            if [[ $deform != static && $shadow == cube && ($mode == off || $mode == ssr) ]]; then continue; fi
            deform_args=(--deform off)
            [[ $deform == static ]] || deform_args=(--deform on --update "$deform")
            name="$scene-$size-$mode-$deform-$shadow-$gbuffer"
            echo "frame_matrix: [$done_runs/$total] $name" >&2
            "$glint" render "$scene" --frames "$frames" --timings-only --overwrite --width "$width" --height "$height" \
              --reflections "$mode" --shadows "$shadow" --gbuffer "$gbuffer" "${deform_args[@]}" \
              --out "$out/$name" "$@" >"$out/$name.log" 2>&1 || { echo "frame_matrix: $name failed, see $out/$name.log" >&2; }
          done
        done
      done
    done
  done
done
echo "frame_matrix: done, results in $out" >&2
