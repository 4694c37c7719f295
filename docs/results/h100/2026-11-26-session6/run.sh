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
if [ "$STEP" = d ]; then  # issue 19: GL-CUDA hand-over: separate maps (before), one joint map, EGL/CUDA syncs
  hv() { case $1 in sep) echo "GLINT_GL_CUDA_HANDOVER=map GLINT_EXP_SEPARATE_MAPS=1";; joint) echo "GLINT_GL_CUDA_HANDOVER=map";; sync) echo "GLINT_GL_CUDA_HANDOVER=sync";; esac; }
  for h in sep joint sync; do for deform in off on; do for mode in hybrid rt off; do
    env $(hv $h) timeout 30 glint render atrium --backend cuda --reflections $mode --width 1280 --height 720 --frames 2071:2110 \
      --timings-only --gbuffer visibility --shadows rt --primary compute --accel sah --deform $deform --out $R/f/$h-$mode-deform-$deform > $R/f-$h-$mode-$deform.log 2>&1 || { echo "$h $mode $deform failed"; tail -2 $R/f-$h-$mode-$deform.log; }; done; done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for h in sep joint sync; do
    env $(hv $h) timeout 30 glint render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only --gbuffer visibility --shadows rt --primary compute --accel sah --deform off --profile-scopes --out $R/s/$h > $R/s-$h.log 2>&1 || echo "scopes $h failed"
    env $(hv $h) timeout 60 glint render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2096:2103 \
      --gbuffer visibility --shadows rt --primary compute --accel sah --deform on --out $R/img-$h > $R/img-$h.log 2>&1 || echo "images $h failed"
  done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "trace|shadow_rays|^\| scope" $R/scopes.md
  for h in joint sync; do n=0; for f in $R/img-sep/frame_*.png; do cmp -s $f $R/img-$h/$(basename $f) && n=$((n+1)) || echo "$h DIFFERENT $(basename $f)"; done; echo "$h: $n frames equal to sep"; done
  rm -rf $R/img-* $R/f/*/frame_*.png
  ( cd $R && GLINT_GL_CUDA_HANDOVER=map timeout 150 glint_tests --gtest_brief=1 --gtest_filter='*Interop*:*Cuda*:*Device*:*Deform*:*GoldenImage*:*RayTraced*:*Occlusion*' > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=" $R/tests.log | tail -15
fi
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
if [ "$STEP" = e ]; then  # issue 21: SSR's colour where the ray meets the surface
  ( cd $R && timeout 100 glint_tests --gtest_brief=1 --gtest_filter='*Ssr*:GoldenImage*:*HybridPipeline*:*Adaptive*' > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|golden|sponza all" $R/tests.log | tail -12
  timeout 150 glint bench --experiment adaptive --scene atrium --simple-scene atrium-simple --backends cuda \
    --width 1280 --height 720 --warmup 3 --no-plot --out $R/adaptive > $R/adaptive.log 2>&1; echo "adaptive rc=$?"
  timeout 150 glint bench --experiment adaptive --scene sponza --simple-scene scenes/sponza-all-reflective.scene.json --backends cuda \
    --width 1280 --height 720 --warmup 3 --no-plot --out $R/adaptive-sponza > $R/adaptive-sponza.log 2>&1; echo "adaptive sponza rc=$?"
  for mode in hybrid ssr; do
    timeout 30 glint render atrium --backend cuda --reflections $mode --width 1280 --height 720 --frames 2071:2110 \
      --timings-only --gbuffer visibility --shadows rt --primary compute --accel sah --deform off --out $R/f/$mode > $R/f-$mode.log 2>&1 || echo "$mode failed"; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  rm -rf $R/adaptive*/cells/*/ $R/adaptive*/images
fi
if [ "$STEP" = f ]; then  # issue 21: SSR colour variants on one warm machine (GLINT_SHADER_DIR)
  for v in old new nonormal old new nonormal; do
    sd=""; [ $v != new ] && sd=$PWD/.gpu-shaders/$v
    env ${sd:+GLINT_SHADER_DIR=$sd} timeout 30 glint render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only --gbuffer visibility --shadows rt --primary compute --accel sah --deform off --profile-scopes --out $R/f/$v-$RANDOM > /dev/null 2>&1 || echo "$v failed"; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  python3 tools/scope_table.py $R/f/* > $R/scopes.md 2>&1; grep -E "^\| ssr|^\| scope" $R/scopes.md
  for sc in "atrium atrium-simple" "sponza scenes/sponza-all-reflective.scene.json"; do set -- $sc
    GLINT_SHADER_DIR=$PWD/.gpu-shaders/nonormal timeout 150 glint bench --experiment adaptive --scene $1 --simple-scene $2 --backends cuda \
      --width 1280 --height 720 --warmup 3 --no-plot --out $R/adaptive-$1 > $R/adaptive-$1.log 2>&1; echo "adaptive $1 rc=$?"
    awk -F, '$3=="hybrid"{print $1,$2,$15,$16}' $R/adaptive-$1/adaptive.csv; done
  rm -rf $R/adaptive*/cells/*/ $R/adaptive*/images
fi
if [ "$STEP" = g ]; then  # issue 19: deforming without a hand-over (GL deforms its own vertices)
  ( cd $R && timeout 150 glint_tests --gtest_brief=1 --gtest_filter='*Deform*:*HybridPipeline*:*RenderCli*:*FrameLoop*:GlSceneDeformer*' > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=" $R/tests.log | tail -12
  for size in 1280x720 2560x1440; do for deform in off on; do for mode in hybrid rt ssr off; do
    timeout 30 glint render atrium --backend cuda --reflections $mode --width ${size%x*} --height ${size#*x} --frames 2071:2110 \
      --timings-only --gbuffer visibility --shadows rt --primary compute --accel sah --deform $deform --out $R/f/$size-$mode-deform-$deform > $R/f-$size-$mode-$deform.log 2>&1 || { echo "$size $mode $deform failed"; tail -2 $R/f-$size-$mode-$deform.log; }; done; done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  timeout 30 glint render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2071:2110 --timings-only --gbuffer visibility \
    --shadows rt --primary compute --accel sah --deform on --profile-scopes --out $R/s/deform-on > /dev/null 2>&1; python3 tools/scope_table.py $R/s/* > $R/scopes.md; grep -E "deform|^\| scope|^\| shadow \||^\| trace" $R/scopes.md
  for d in gpu cpu; do timeout 60 glint render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2100,4400 --gbuffer visibility \
    --shadows rt --primary compute --accel sah --deform on --deform-on $d --out $R/img-$d > /dev/null 2>&1 || echo "img $d failed"; done
  for f in 2100 4400; do glint compare $R/img-gpu/frame_0$f.png $R/img-cpu/frame_0$f.png | grep -E "buckets|SSIM|PSNR"; done
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
if [ "$STEP" = h ]; then  # issue 19: the trace's overflow word copies (memset + 4-byte copy per span) in the hand-over?
  for v in base lean base lean; do for mode in hybrid rt off; do
    e=""; [ $v = lean ] && e="GLINT_EXP_LEAN=1"; env $e timeout 30 glint render atrium --backend cuda --reflections $mode --width 1280 --height 720 --frames 2071:2110 \
      --timings-only --gbuffer visibility --shadows rt --primary compute --accel sah --deform off --profile-scopes --out $R/f/$v-$mode-$RANDOM > /dev/null 2>&1 || echo "$v $mode failed"; done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  python3 tools/scope_table.py $R/f/*hybrid* > $R/scopes.md 2>&1; grep -E "^\| scope|shadow_rays/trace|^\| trace" $R/scopes.md
fi
if [ "$STEP" = t ]; then  # the whole test suite on the GPU
  ( cd $R && timeout 480 glint_tests --gtest_brief=1 > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|SKIPPED \]|tests from|rc=" $R/tests.log | tail -30
fi
