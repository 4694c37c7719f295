#!/usr/bin/env bash
# The session's one GPU run: GPU tests, the issue-19 frame matrix, shadow images. Everything lands in $OUT/r.tar.xz.
set -u
R=/tmp/r; mkdir -p $R
export GLINT_ASSETS=/tmp/w/.gpu/assets GLINT_CLI=/tmp/w/.gpu/bin/glint GLINT_SOURCE_DIR=$PWD GLINT=/tmp/w/.gpu/bin/glint
{ nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader; date -u; nproc; } > $R/device.txt
cat $R/device.txt
pack() { tar -C /tmp -cJf $OUT/r.tar.xz r; }
trap pack EXIT
# 1. GPU tests
timeout 240 /tmp/w/.gpu/bin/glint_tests --gtest_brief=1 \
  --gtest_filter='CudaRayTracerOcclusion.*:OptixRayTracerOcclusion.*:RayTracedShadowsTest.*:VisibilityGBuffer.*:HybridPipelineTest.*:PipelinedFrameLoop.*:DeterministicFramesTest.*:GoldenImage.*:*Primary*:CudaRayTracer.*:OptixRayTracer.*:RenderTimingsRows.*' \
  > $R/gpu-tests.txt 2>&1; echo "gpu tests rc=$?" >> $R/gpu-tests.txt
grep -E "FAILED|PASSED|rc=|SKIPPED \[" $R/gpu-tests.txt | tail -25
date -u
# 2. frame matrix (cuda, lbvh; frames 2071:2110, the table skips the first 10)
M=$R/matrix; C="--backend cuda --accel lbvh"
SCENES=atrium MODES=hybrid DEFORMS="static refit" SHADOWS="cube rt hybrid" GBUFFERS="raster visibility" tools/frame_matrix.sh $M $C
SCENES=atrium MODES="off ssr rt" DEFORMS="static" SHADOWS="cube rt" GBUFFERS="raster visibility" tools/frame_matrix.sh $M $C
SCENES=atrium MODES=hybrid DEFORMS="rebuild" SHADOWS="cube rt" GBUFFERS="visibility" tools/frame_matrix.sh $M $C
SCENES=atrium SIZES=2560x1440 MODES=hybrid DEFORMS="static refit" SHADOWS="cube rt" GBUFFERS="raster visibility" tools/frame_matrix.sh $M $C
SCENES="atrium-simple sponza" MODES=hybrid DEFORMS="static refit" SHADOWS="cube rt" GBUFFERS="raster visibility" tools/frame_matrix.sh $M $C
SCENES=atrium MODES=hybrid DEFORMS="refit" SHADOWS="cube rt" GBUFFERS="visibility" tools/frame_matrix.sh $R/matrix-optix --backend optix
SCENES=atrium SIZES="1280x720 2560x1440" MODES="hybrid" DEFORMS="static refit" SHADOWS="rt" GBUFFERS="visibility" tools/frame_matrix.sh $R/matrix-primary-rt $C --primary rt
date -u
for d in matrix matrix-optix matrix-primary-rt; do echo "== $d"; python3 tools/frame_table.py $R/$d; done | tee $R/tables.md
# 3. shadow images: cube vs rt vs hybrid, final frame and shadow mask
for m in cube rt hybrid; do
  $GLINT render atrium $C --reflections hybrid --shadows $m --gbuffer visibility --frames 1800,2100,2300,4400 --debug-views --overwrite --out $R/img-$m > $R/img-$m.log 2>&1
done
for f in 01800 02100 02300 04400; do for m in cube hybrid; do for kind in "" _shadow_mask; do
  $GLINT compare $R/img-$m/frame_$f$kind.png $R/img-rt/frame_$f$kind.png --json $R/cmp-$f-$m-vs-rt$kind.json > /dev/null 2>&1
done; done; done
python3 - <<'PY' | tee $R/shadow-compare.md
import json,glob,os
for p in sorted(glob.glob('/tmp/r/cmp-*.json')):
    d=json.load(open(p)); print(f"| {os.path.basename(p)[4:-5]} | {d['ssim']['luma']:.4f} | {d['psnr_db']['overall']} | {d['color_buckets_percent']['mean']:.3f} |")
PY
# keep only the final frames and shadow masks of the images (the tarball must stay small)
find $R/img-* -name "*.png" -delete
date -u
