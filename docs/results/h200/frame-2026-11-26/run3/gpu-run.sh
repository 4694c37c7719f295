#!/usr/bin/env bash
# Run 3 of 2026-11-26: scope profiles (where each pass's time goes), cuda vs gl, primary raster/compute/rt.
set -u
R=/tmp/r; mkdir -p $R
mkdir -p /tmp/w && tar -xJf .gpu.tar.xz -C /tmp/w && source /tmp/w/.gpu/env.sh
export GLINT_ASSETS=/tmp/w/.gpu/assets GLINT_CLI=/tmp/w/.gpu/bin/glint GLINT_SOURCE_DIR=$PWD GLINT=/tmp/w/.gpu/bin/glint
{ nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader; date -u; nproc; git log --oneline | head -1; } > $R/device.txt
cat $R/device.txt
pack() { tar -C /tmp -cJf $OUT/r.tar.xz r; }
trap pack EXIT
timeout 120 /tmp/w/.gpu/bin/glint_tests --gtest_brief=1 \
  --gtest_filter='ScopeProfilerTest*:RenderScopesCli*:GlRayTracer*:ComputeVisibility*:GlGpuTimer*' \
  > $R/gpu-tests.txt 2>&1; echo "gpu tests rc=$?" >> $R/gpu-tests.txt
grep -E "FAILED|PASSED|rc=|SKIPPED \[" $R/gpu-tests.txt | tail -15
P="--width 1280 --height 720 --frames 2071:2110 --timings-only --gbuffer visibility --shadows rt --reflections hybrid --deform off --overwrite"
for p in compute raster rt; do
  $GLINT render atrium $P --primary $p --backend cuda --accel lbvh --profile-scopes --out $R/s/cuda-$p > $R/s-cuda-$p.log 2>&1
  $GLINT render atrium $P --primary $p --backend gl --profile-scopes --out $R/s/gl-$p > $R/s-gl-$p.log 2>&1
done
$GLINT render atrium $P --primary compute --backend cuda --accel sah --profile-scopes --out $R/s/cuda-sah-compute > /dev/null 2>&1
$GLINT render atrium $P --primary compute --backend cuda --accel lbvh --out $R/s/cuda-compute-noprofile > /dev/null 2>&1
$GLINT render atrium $P --primary compute --backend gl --out $R/s/gl-compute-noprofile > /dev/null 2>&1
$GLINT render atrium ${P/--deform off/--deform on --update refit} --primary compute --backend cuda --accel lbvh --profile-scopes --out $R/s/cuda-compute-refit > /dev/null 2>&1
$GLINT render atrium ${P/--deform off/--deform on --update refit} --primary compute --backend gl --profile-scopes --out $R/s/gl-compute-refit > /dev/null 2>&1
$GLINT render sponza $P --primary compute --backend cuda --accel lbvh --profile-scopes --out $R/s/sponza-cuda-compute > $R/sponza.log 2>&1
$GLINT render atrium ${P/1280 --height 720/2560 --height 1440} --primary compute --backend cuda --accel lbvh --profile-scopes --out $R/s/cuda-compute-1440 > /dev/null 2>&1
date -u
python3 tools/scope_table.py $R/s/cuda-compute $R/s/cuda-sah-compute $R/s/cuda-raster $R/s/cuda-rt $R/s/gl-compute $R/s/gl-raster $R/s/cuda-compute-refit $R/s/gl-compute-refit $R/s/sponza-cuda-compute $R/s/cuda-compute-1440 --skip 10 | tee $R/scopes.md
python3 tools/frame_table.py $R/s | tee $R/frames.md
