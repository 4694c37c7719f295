#!/usr/bin/env bash
# GPU tests and measurements for the open issues, in two calls: `a` (the whole test suite, issue 21's
# adaptive bench, issue 23's denoiser frames) and `b` (issue 23's glossy bench). Output: $OUT/r-<step>.tar.xz
set -u
STEP=$1
R=/tmp/r-$STEP; rm -rf $R; mkdir -p $R
if [ ! -x /tmp/w/.gpu/bin/glint ]; then mkdir -p /tmp/w && tar -xJf .gpu.tar.xz -C /tmp/w; fi
source /tmp/w/.gpu/env.sh
export GLINT_CLI=/tmp/w/.gpu/bin/glint GLINT_SOURCE_DIR=$PWD GLINT_ASSETS=/tmp/w/.gpu/assets PATH=/tmp/w/.gpu/bin:$PATH
pack() { tar -C /tmp -cJf $OUT/r-$STEP.tar.xz r-$STEP; }
trap pack EXIT
{ nvidia-smi --query-gpu=name,driver_version --format=csv,noheader; date -u; } | tee $R/device.txt
if [ "$STEP" = a ]; then
  ( cd $R && timeout 330 glint_tests --gtest_brief=1 > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=" $R/tests.log | tail -25
  timeout 110 glint bench --experiment adaptive --scene atrium --simple-scene atrium-simple --backends cuda \
    --width 1280 --height 720 --warmup 3 --no-plot --out $R/adaptive > $R/adaptive.log 2>&1; echo "adaptive rc=$?"
  for run in "mirror:--glossy off --denoise off" "glossy:--glossy on --denoise on"; do for deform in on off; do
    timeout 30 glint render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only --gbuffer visibility --shadows rt --primary compute --accel sah --deform $deform \
      --profile-scopes ${run#*:} --out $R/dn/${run%%:*}-$deform > $R/dn-${run%%:*}-$deform.log 2>&1; echo "$run $deform rc=$?"; done; done
  python3 tools/scope_table.py $R/dn/* > $R/dn-scopes.md 2>&1; python3 tools/frame_table.py $R/dn > $R/dn-frames.md 2>&1
  rm -rf $R/dn/*/frame_*.png
fi
if [ "$STEP" = b ]; then
  timeout 200 glint bench --experiment glossy --scene atrium --simple-scene atrium --backends cuda \
    --width 1280 --height 720 --gbuffer visibility --shadows rt --no-plot --out $R/glossy > $R/glossy.log 2>&1; echo "glossy rc=$?"
  rm -rf $R/glossy/references
fi
if [ "$STEP" = c ]; then
  ( cd $R && timeout 120 glint_tests --gtest_brief=0 --gtest_filter='ComputeVisibility.*:GoldenImage*:ObjPolygon*:RenderCliStatic*' > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|compute \]|golden" $R/tests.log | tail -12
  timeout 100 glint bench --experiment adaptive --scene sponza --simple-scene scenes/sponza-all-reflective.scene.json --backends cuda \
    --width 1280 --height 720 --warmup 3 --no-plot --out $R/adaptive-sponza > $R/adaptive-sponza.log 2>&1; echo "adaptive sponza rc=$?"
  for size in 1280x720 2560x1440; do for deform in off on; do for mode in hybrid rt ssr off; do
    timeout 30 glint render atrium --backend cuda --reflections $mode --width ${size%x*} --height ${size#*x} --frames 2071:2110 \
      --timings-only --gbuffer visibility --shadows rt --primary compute --accel sah --deform $deform --out $R/f/$size-$mode-deform-$deform > $R/f-$size-$mode-$deform.log 2>&1 || echo "$size $mode $deform failed"; done; done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
fi
