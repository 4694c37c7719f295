#!/usr/bin/env bash
# Run 2 of 2026-11-26: GPU tests (gl backend, compute raster, fused shadows), frame matrix cuda vs gl x primary.
set -u
R=/tmp/r; mkdir -p $R
mkdir -p /tmp/w && tar -xJf .gpu.tar.xz -C /tmp/w && source /tmp/w/.gpu/env.sh
export GLINT_ASSETS=/tmp/w/.gpu/assets GLINT_CLI=/tmp/w/.gpu/bin/glint GLINT_SOURCE_DIR=$PWD GLINT=/tmp/w/.gpu/bin/glint
{ nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader; date -u; nproc; } > $R/device.txt
cat $R/device.txt
pack() { tar -C /tmp -cJf $OUT/r.tar.xz r; }
trap pack EXIT
timeout 150 /tmp/w/.gpu/bin/glint_tests --gtest_brief=1 \
  --gtest_filter='GlRayTracer*:ComputeVisibility*:CudaRayTracerOcclusion.*:RayTracedShadowsTest.*:HybridPipelineTest.*:PipelinedFrameLoop.*:*Primary*:VisibilityGBuffer*' \
  > $R/gpu-tests.txt 2>&1; echo "gpu tests rc=$?" >> $R/gpu-tests.txt
grep -E "FAILED|PASSED|rc=|SKIPPED \[" $R/gpu-tests.txt | tail -25
date -u
for p in raster compute rt; do
  SCENES=atrium MODES=hybrid DEFORMS="static refit" SHADOWS="rt" GBUFFERS="visibility" tools/frame_matrix.sh $R/cuda-$p --backend cuda --accel lbvh --primary $p
  SCENES=atrium MODES=hybrid DEFORMS="static refit" SHADOWS="rt" GBUFFERS="visibility" tools/frame_matrix.sh $R/gl-$p --backend gl --primary $p
done
SCENES=atrium MODES="off rt" DEFORMS="static" SHADOWS="rt" GBUFFERS="visibility" tools/frame_matrix.sh $R/gl-compute --backend gl --primary compute
SCENES=atrium SIZES=2560x1440 MODES=hybrid DEFORMS="static refit" SHADOWS="rt" GBUFFERS="visibility" tools/frame_matrix.sh $R/gl-compute --backend gl --primary compute
SCENES=atrium SIZES=2560x1440 MODES=hybrid DEFORMS="static refit" SHADOWS="rt" GBUFFERS="visibility" tools/frame_matrix.sh $R/cuda-compute --backend cuda --accel lbvh --primary compute
SCENES="atrium-simple sponza" MODES=hybrid DEFORMS="static refit" SHADOWS="rt" GBUFFERS="visibility" tools/frame_matrix.sh $R/gl-compute --backend gl --primary compute
SCENES=atrium MODES=hybrid DEFORMS="static refit" SHADOWS="cube" GBUFFERS="raster" tools/frame_matrix.sh $R/cuda-paper --backend cuda --accel lbvh
date -u
for d in $R/cuda-* $R/gl-*; do echo "== $(basename $d)"; python3 tools/frame_table.py $d; done | tee $R/tables.md
# images: gl vs cuda equality on a frame
for b in cuda gl; do $GLINT render atrium --backend $b --frames 2100 --overwrite --out $R/img-$b --primary compute > $R/img-$b.log 2>&1; done
$GLINT compare $R/img-gl/frame_02100.png $R/img-cuda/frame_02100.png --json $R/cmp-gl-cuda.json > /dev/null 2>&1; cat $R/cmp-gl-cuda.json | head -c 600
find $R/img-* -name "*.png" -delete
date -u
