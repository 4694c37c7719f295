#!/usr/bin/env bash
# Run 4 of 2026-11-26: GPU tests of the session's work (kd-tree on cuda, registry, viewer session, compute ids), frame timings after the compute-ids change.
set -u
R=/tmp/r; mkdir -p $R
mkdir -p /tmp/w && tar -xJf .gpu.tar.xz -C /tmp/w && source /tmp/w/.gpu/env.sh
export GLINT_ASSETS=/tmp/w/.gpu/assets GLINT_CLI=/tmp/w/.gpu/bin/glint GLINT_SOURCE_DIR=$PWD GLINT=/tmp/w/.gpu/bin/glint
{ nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader; date -u; nproc; } > $R/device.txt
cat $R/device.txt
pack() { tar -C /tmp -cJf $OUT/r.tar.xz r; }
trap pack EXIT
timeout 300 /tmp/w/.gpu/bin/glint_tests --gtest_brief=1 \
  --gtest_filter='Backend/KdTreeRayTracer.*:RenderCliKdTree*:CudaRayTracer*:CudaRayTracerOcclusion*:OptixRayTracer*:ComputeVisibility*:RenderPrimaryComputeCli*:GlRayTracer*:ViewerSession*:BackendRegistry*:*Registration*:HybridPipelineTest.*:RayTracedShadowsTest.*:ScopeProfilerTest*:RenderScopesCli*:PipelinedFrameLoop*:GpuDeformer*:*Primary*' \
  > $R/gpu-tests.txt 2>&1; echo "gpu tests rc=$?" >> $R/gpu-tests.txt
grep -E "FAILED|PASSED|rc=|SKIPPED \[" $R/gpu-tests.txt | tail -25
date -u
P="--frames 2071:2110 --timings-only --gbuffer visibility --shadows rt --reflections hybrid --overwrite"
for a in sah lbvh; do for d in "--deform off" "--deform on --update refit"; do for s in "1280 --height 720" "2560 --height 1440"; do
  n=cuda-$a-$(echo $d | tr -d ' -')-${s%% *}
  $GLINT render atrium --width $s $P $d --primary compute --backend cuda --accel $a --out $R/s/$n > $R/$n.log 2>&1
done; done; done
$GLINT render atrium --width 1280 --height 720 $P --deform off --primary compute --backend cuda --accel sah --profile-scopes --out $R/s/cuda-sah-profiled > /dev/null 2>&1
$GLINT render atrium --width 1280 --height 720 $P --deform off --primary compute --backend gl --out $R/s/gl-sah > /dev/null 2>&1
$GLINT render sponza --width 1280 --height 720 $P --deform off --primary compute --backend cuda --accel sah --out $R/s/sponza-cuda-sah > $R/sponza.log 2>&1
$GLINT render atrium-simple --width 1280 --height 720 $P --deform off --primary compute --backend cuda --accel sah --out $R/s/simple-cuda-sah > /dev/null 2>&1
$GLINT render atrium --width 1280 --height 720 --frames 2071:2110 --timings-only --overwrite --shadows cube --gbuffer raster --reflections hybrid --deform off --backend cuda --accel sah --out $R/s/paper-cuda-sah > /dev/null 2>&1
python3 tools/frame_table.py $R/s | tee $R/frames.md
python3 tools/scope_table.py $R/s/cuda-sah-profiled --skip 10 | tee $R/scopes.md
date -u
timeout 200 $GLINT bench --experiment paper --backends cuda --accels kdtree,lbvh,sah --updates rebuild,refit --stride 490 --out $R/bench-kd > $R/bench-kd.log 2>&1; echo "bench rc=$?" | tee -a $R/bench-kd.log
find $R/bench-kd -name "*.png" -size +200k -delete 2>/dev/null
date -u
