#!/usr/bin/env bash
# Session 7's GPU calls. a: tests of the touched areas, frames and scopes against the previous binary
# (glint-base), images byte-compared. Output: $OUT/r-<step>.tar.xz
set -u
STEP=$1
R=/tmp/r-$STEP; rm -rf $R; mkdir -p $R
if [ ! -x /tmp/w/.gpu/bin/glint ]; then mkdir -p /tmp/w && tar -xJf .gpu.tar.xz -C /tmp/w; fi
source /tmp/w/.gpu/env.sh
export GLINT_CLI=/tmp/w/.gpu/bin/glint GLINT_SOURCE_DIR=$PWD GLINT_ASSETS=/tmp/w/.gpu/assets PATH=/tmp/w/.gpu/bin:$PATH
pack() { tar -C /tmp -cJf $OUT/r-$STEP.tar.xz r-$STEP; }
trap pack EXIT
{ nvidia-smi --query-gpu=name,driver_version --format=csv,noheader; date -u; } | tee $R/device.txt
[ -x /tmp/w/glint-base ] || { xz -dc .gpu-base.xz > /tmp/w/glint-base; chmod +x /tmp/w/glint-base; }
common="--gbuffer visibility --primary compute --accel sah"
if [ "$STEP" = a ] || [ "$STEP" = t ]; then
  filter='*ComputeVisibility*:*LightingPass*:*ShadowMask*:GoldenImage*:*HybridPipeline*:RenderCli*:RenderScopes*:*DeterministicFrames*:*Ssr*:*RayTracedShadows*:*GlShader*:*ShaderDefines*:*Shadow*:*SsrHitView*:*FramePipeline*:*Lighting*'
  [ "$STEP" = t ] && filter='*'
  ( cd $R && timeout 400 glint_tests --gtest_brief=1 --gtest_filter="$filter" > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|golden|SKIPPED \]" $R/tests.log | tail -16
fi
if [ "$STEP" = a ]; then
  for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    for cfg in 1280x720:hybrid:rt 1280x720:rt:rt 1280x720:ssr:rt 1280x720:off:rt 2560x1440:hybrid:rt 2560x1440:rt:rt 1280x720:hybrid:cube; do
      size=${cfg%%:*}; rest=${cfg#*:}; mode=${rest%%:*}; sh=${rest#*:}
      for deform in off on; do
        timeout 40 $g render atrium --backend cuda --reflections $mode --width ${size%x*} --height ${size#*x} --frames 2071:2110 \
          --timings-only $common --shadows $sh --deform $deform --out $R/f/$bin-$size-$mode-$sh-deform-$deform > $R/f.log 2>&1 || { echo "$bin $cfg $deform failed"; tail -2 $R/f.log; }
      done; done
    timeout 30 $g render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only $common --shadows rt --deform off --profile-scopes --out $R/s/$bin-rt > $R/s.log 2>&1 || echo "scopes $bin failed"
    timeout 30 $g render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only --accel sah --deform off --profile-scopes --out $R/s/$bin-paper > $R/s.log 2>&1 || echo "scopes paper $bin failed"
    for cfg in hybrid:rt rt:rt hybrid:cube; do mode=${cfg%%:*}; sh=${cfg#*:}
      timeout 60 $g render atrium --backend cuda --reflections $mode --width 1280 --height 720 --frames 2096:2103 \
        $common --shadows $sh --deform on --out $R/img-$bin-$mode-$sh > $R/img.log 2>&1 || echo "images $bin $cfg failed"
    done
  done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "^\| (scope|gbuffer|light|shadow|device_trace \|)" $R/scopes.md
  for cfg in hybrid-rt rt-rt hybrid-cube; do n=0; for f in $R/img-base-$cfg/frame_*.png; do cmp -s $f $R/img-new-$cfg/$(basename $f) && n=$((n+1)) || { echo "$cfg DIFFERENT $(basename $f): $(glint compare $f $R/img-new-$cfg/$(basename $f) 2>&1 | tail -1)"; }; done; echo "$cfg: $n frames byte-equal to base"; done
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
if [ "$STEP" = b ]; then  # issue 21: hybrid vs rt with SSR's colour seen from the reflecting surface
  for bin in new base; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    timeout 200 $g bench --experiment adaptive --scene sponza --simple-scene scenes/sponza-all-reflective.scene.json --backends cuda \
      --width 1280 --height 720 --warmup 3 --no-plot --out $R/adaptive-sponza-$bin > $R/adaptive-sponza-$bin.log 2>&1; echo "$bin adaptive sponza rc=$?"
  done
  rm -rf $R/adaptive*/cells/*/ $R/adaptive*/images
  for bin in new base; do echo "== $bin"; grep -E "^## |^\| (rt|ssr|hybrid|auto) " $R/adaptive-sponza-$bin/report.md | head -20; done
fi
