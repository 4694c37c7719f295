#!/usr/bin/env bash
# Session 6's GPU calls (issue 19: one GL-CUDA hand-over a frame): h (tests, frames and scopes against
# the previous binary, glint-base), i (trace times with and without the hits' shadow rays), j (auto's
# bench), k (tests after the refactor; auto's bench with rt shadows). h ran three times; its files
# here are the last run's, on the final tree. Output: $OUT/r-<step>.tar.xz
set -u
STEP=$1
R=/tmp/r-$STEP; rm -rf $R; mkdir -p $R
if [ ! -x /tmp/w/.gpu/bin/glint ]; then mkdir -p /tmp/w && tar -xJf .gpu.tar.xz -C /tmp/w; fi
source /tmp/w/.gpu/env.sh
export GLINT_CLI=/tmp/w/.gpu/bin/glint GLINT_SOURCE_DIR=$PWD GLINT_ASSETS=/tmp/w/.gpu/assets PATH=/tmp/w/.gpu/bin:$PATH
pack() { tar -C /tmp -cJf $OUT/r-$STEP.tar.xz r-$STEP; }
trap pack EXIT
{ nvidia-smi --query-gpu=name,driver_version --format=csv,noheader; date -u; } | tee $R/device.txt
if [ "$STEP" = h ]; then  # issue 19: one hand-over a frame, against the previous binary (glint-base)
  [ -x /tmp/w/glint-base ] || { xz -dc .gpu-base.xz > /tmp/w/glint-base; chmod +x /tmp/w/glint-base; }
  ( cd $R && timeout 240 glint_tests --gtest_brief=1 --gtest_filter='*HybridPipeline*:*RayTraced*:*Ssr*:GoldenImage*:*Adaptive*:*Deform*:*PoseMesh*:RenderCli*:*Occlusion*:*ReflectionTraceStep*:*Interop*:*DeterministicFrames*:*Glossy*' > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|golden|sponza all" $R/tests.log | tail -14
  for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    for cfg in 1280x720:hybrid 1280x720:rt 1280x720:ssr 1280x720:off 2560x1440:hybrid 2560x1440:rt; do size=${cfg%%:*}; mode=${cfg#*:}
      for deform in off on; do
        timeout 40 $g render atrium --backend cuda --reflections $mode --width ${size%x*} --height ${size#*x} --frames 2071:2110 \
          --timings-only --gbuffer visibility --shadows rt --primary compute --accel sah --deform $deform --out $R/f/$bin-$size-$mode-deform-$deform > $R/f-$bin-$size-$mode-$deform.log 2>&1 || { echo "$bin $size $mode $deform failed"; tail -2 $R/f-$bin-$size-$mode-$deform.log; }
      done; done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    timeout 30 $g render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only --gbuffer visibility --shadows rt --primary compute --accel sah --deform off --profile-scopes --out $R/s/$bin > $R/s-$bin.log 2>&1 || echo "scopes $bin failed"
    for mode in hybrid rt; do
      timeout 60 $g render atrium --backend cuda --reflections $mode --width 1280 --height 720 --frames 2096:2103 \
        --gbuffer visibility --shadows rt --primary compute --accel sah --deform on --out $R/img-$bin-$mode > $R/img-$bin-$mode.log 2>&1 || echo "images $bin $mode failed"
    done
  done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; head -40 $R/scopes.md
  for mode in hybrid rt; do n=0; for f in $R/img-base-$mode/frame_*.png; do cmp -s $f $R/img-new-$mode/$(basename $f) && n=$((n+1)) || { echo "$mode DIFFERENT $(basename $f)"; glint compare $f $R/img-new-$mode/$(basename $f) 2>&1 | tail -1; }; done; echo "$mode: $n frames byte-equal to base"; done
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
if [ "$STEP" = i ]; then  # issue 19/21: the reflection trace's time with the hits' shadow rays
  [ -x /tmp/w/glint-base ] || { xz -dc .gpu-base.xz > /tmp/w/glint-base; chmod +x /tmp/w/glint-base; }
  ( cd $R && timeout 260 glint_tests --gtest_brief=1 --gtest_filter='*HybridPipeline*:*RayTraced*:GoldenImage*:*Adaptive*:*Deform*:*PoseMesh*:RenderCli*:RenderScopes*:RenderTimings*:*ReflectionTraceStep*:*Glossy*:*Interop*' > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|golden" $R/tests.log | tail -14
  for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    for cfg in hybrid:rt rt:rt hybrid:cube rt:cube; do mode=${cfg%%:*}; sh=${cfg#*:}
      timeout 40 $g render atrium --backend cuda --reflections $mode --width 1280 --height 720 --frames 2071:2110 \
        --timings-only --gbuffer visibility --shadows $sh --primary compute --accel sah --deform off --profile-scopes --out $R/f/$bin-$mode-$sh > $R/f-$bin-$mode-$sh.log 2>&1 || { echo "$bin $cfg failed"; tail -2 $R/f-$bin-$mode-$sh.log; }
    done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  python3 tools/scope_table.py $R/f/* > $R/scopes.md 2>&1; grep -E "^\| (scope|trace|device_trace|shadow \||shadow/shadow_rays/trace|hit_shade \|)" $R/scopes.md
  python3 - $R/f <<'PY'
import csv, sys, os
for d in sorted(os.listdir(sys.argv[1])):
    rows = list(csv.DictReader(open(os.path.join(sys.argv[1], d, "timings.csv"))))[10:]
    col = lambda c: sum(float(r[c]) for r in rows if r.get(c)) / max(1, len([r for r in rows if r.get(c)]))
    print(d, "trace_ms %.3f" % col("trace_ms"), "hit_shadow_trace_ms %.3f" % col("hit_shadow_trace_ms") if "hit_shadow_trace_ms" in rows[0] else "", "rays %.0f" % col("rays_traced"), "gpu_total %.3f frame %.3f" % (col("gpu_total_ms"), col("frame_ms")))
PY
fi
if [ "$STEP" = j ]; then  # issue 21: auto with the hits' shadow rays in its ray cost, against the previous binary
  [ -x /tmp/w/glint-base ] || { xz -dc .gpu-base.xz > /tmp/w/glint-base; chmod +x /tmp/w/glint-base; }
  for bin in new base; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    timeout 140 $g bench --experiment adaptive --scene atrium --simple-scene atrium-simple --backends cuda \
      --width 1280 --height 720 --warmup 3 --no-plot --out $R/adaptive-$bin > $R/adaptive-$bin.log 2>&1; echo "$bin adaptive rc=$?"
    timeout 140 $g bench --experiment adaptive --scene sponza --simple-scene scenes/sponza-all-reflective.scene.json --backends cuda \
      --width 1280 --height 720 --warmup 3 --no-plot --out $R/adaptive-sponza-$bin > $R/adaptive-sponza-$bin.log 2>&1; echo "$bin adaptive sponza rc=$?"
  done
  rm -rf $R/adaptive*/cells/*/ $R/adaptive*/images
fi
if [ "$STEP" = k ]; then  # after the refactor: GPU tests; auto with rt shadows, this binary and the previous one
  [ -x /tmp/w/glint-base ] || { xz -dc .gpu-base.xz > /tmp/w/glint-base; chmod +x /tmp/w/glint-base; }
  ( cd $R && timeout 200 glint_tests --gtest_brief=1 --gtest_filter='*HybridPipeline*:*RayTraced*:GoldenImage*:*Adaptive*:RenderCli*:RenderScopes*:*Ssr*:*Deform*:*PoseMesh*:*DeterministicFrames*' > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|golden" $R/tests.log | tail -8
  for bin in new base; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    timeout 150 $g bench --experiment adaptive --scene atrium --simple-scene atrium-simple --backends cuda --shadows rt \
      --gbuffer visibility --width 1280 --height 720 --warmup 3 --no-plot --out $R/adaptive-rt-$bin > $R/adaptive-rt-$bin.log 2>&1; echo "$bin adaptive rc=$?"
  done
  rm -rf $R/adaptive*/cells/*/ $R/adaptive*/images
  for bin in new base; do echo "== $bin"; grep -E "^## |^\| (rt|ssr|hybrid|auto) " $R/adaptive-rt-$bin/report.md; done
fi
