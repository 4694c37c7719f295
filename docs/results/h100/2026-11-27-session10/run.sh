#!/usr/bin/env bash
# Session 10's GPU calls (H100). a: tests of what changed; b: this tree (new) against the session's
# first binary (base): frames, scopes, images; c: the whole suite; d-h below.
# Result files by call (UTC): a1 04:47 and b1 04:48 (the tree with the helpers' fused hit-shadow
# kernel); d1 05:02; e 05:04; f1 05:14, f2 05:15 (inline hit-shadow variants); c 05:23; b2 05:28 and
# d2 05:29 (hit shadows back to two steps, 92603ac); a2 and b3 05:38-05:39 (e937393, the final code);
# g 05:41; h 05:46.
set -u
STEP=$1
R=/tmp/r-$STEP; rm -rf $R; mkdir -p $R
if [ ! -x /tmp/w/.gpu/bin/glint ]; then mkdir -p /tmp/w && tar -xJf .gpu.tar.xz -C /tmp/w; fi
source /tmp/w/.gpu/env.sh
export GLINT_CLI=/tmp/w/.gpu/bin/glint GLINT_SOURCE_DIR=$PWD GLINT_ASSETS=/tmp/w/.gpu/assets PATH=/tmp/w/.gpu/bin:$PATH
pack() { tar -C /tmp -cJf $OUT/r-$STEP.tar.xz r-$STEP; }
trap pack EXIT
{ nvidia-smi --query-gpu=name,driver_version --format=csv,noheader; date -u; } | tee $R/device.txt
common="--gbuffer visibility --primary compute --accel sah"
[ -x /tmp/w/glint-base ] || { xz -dc .gpu-base.xz > /tmp/w/glint-base; chmod +x /tmp/w/glint-base; }
if [ "$STEP" = a ]; then
  ( timeout 400 glint_tests --gtest_brief=1 --gtest_filter="${FILTER:-ComputeVisibility*:*GlRayTracer*:*Gl*Refit*:*Refit*:*Deform*:*RayTracedShadows*:*HitShadow*:*Occlusion*:GoldenImage*:*FramePipeline*:*DeterministicFrames*:*Hybrid*:RenderCommand*}" > $R/tests.log 2>&1; echo "tests rc=$?" >> $R/tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|SKIPPED \]" $R/tests.log | tail -30
fi
if [ "$STEP" = b ]; then
  CFGS=${CFGS:-"1280x720:hybrid:cuda:off 1280x720:hybrid:cuda:on 1280x720:rt:cuda:off 2560x1440:hybrid:cuda:off 2560x1440:hybrid:cuda:on 1280x720:hybrid:gl:off 1280x720:hybrid:gl:on 1280x720:rt:gl:off 1280x720:rt:gl:on 2560x1440:hybrid:gl:off 2560x1440:hybrid:gl:on"}
  for rep in 1 2; do for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    for cfg in $CFGS; do IFS=: read size mode be deform <<< "$cfg"
      timeout 60 $g render atrium --backend $be --reflections $mode --width ${size%x*} --height ${size#*x} --frames 2071:2110 \
        --timings-only $common --shadows rt --deform $deform $([ $be = gl ] && echo --update refit) --out $R/f/$bin-$be-$size-$mode-deform-$deform-r$rep > $R/f.log 2>&1 || { echo "$bin $cfg failed"; tail -2 $R/f.log; }
    done
  done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for d in $R/f/*deform-on*r1; do echo "$(basename $d): accel_update_ms $(awk -F, 'NR>11 {s+=$13; n++} END {printf "%.4f", s/n}' $d/timings.csv)"; done | sort > $R/update.txt; cat $R/update.txt
  for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    for be in cuda gl; do for deform in off on; do
      timeout 30 $g render atrium --backend $be --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
        --timings-only $common --shadows rt --deform $deform $([ $be = gl ] && echo --update refit) --profile-scopes --out $R/s/$bin-$be-deform-$deform > $R/s.log 2>&1 || echo "scopes $bin $be failed"
    done; done
    for cfg in hybrid:rt:cuda:on rt:rt:cuda:on hybrid:cube:cuda:on hybrid:rt:gl:off rt:rt:gl:off hybrid:rt:gl:on; do IFS=: read mode sh be deform <<< "$cfg"
      timeout 60 $g render atrium --backend $be --reflections $mode --width 1280 --height 720 --frames 2096:2103 \
        $common --shadows $sh --deform $deform --out $R/img-$bin-$mode-$sh-$be-$deform > $R/img.log 2>&1 || echo "images $bin $cfg failed"
    done
  done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; cat $R/scopes.md
  for cfg in hybrid-rt-cuda-on rt-rt-cuda-on hybrid-cube-cuda-on hybrid-rt-gl-off rt-rt-gl-off hybrid-rt-gl-on; do n=0; for f in $R/img-base-$cfg/frame_*.png; do cmp -s $f $R/img-new-$cfg/$(basename $f) && n=$((n+1)) || echo "$cfg DIFFERENT $(basename $f): $(glint compare $f $R/img-new-$cfg/$(basename $f) 2>&1 | tail -1)"; done; echo "$cfg: $n frames byte-equal to base"; done
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
if [ "$STEP" = c ]; then
  ( cd $R && timeout 560 glint_tests --gtest_brief=1 > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|SKIPPED \]" $R/tests.log | tail -30
fi
# d: the gl backend deforming with its GPU refit (--update refit --deform-on gpu) against the host
# refit (--deform-on cpu) and the static frame; scopes.
if [ "$STEP" = d ]; then
  for rep in 1 2; do for size in 1280x720 2560x1440; do for mode in hybrid rt; do
    for cfg in off:gpu on:gpu on:cpu; do IFS=: read deform on <<< "$cfg"
      timeout 60 glint render atrium --backend gl --reflections $mode --width ${size%x*} --height ${size#*x} --frames 2071:2110 \
        --timings-only $common --shadows rt --update refit --deform $deform --deform-on $on --out $R/f/gl-$size-$mode-deform-$deform-on-$on-r$rep > $R/f.log 2>&1 || { echo "$cfg failed"; tail -2 $R/f.log; }
    done
  done; done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for d in $R/f/*deform-on*r1; do echo "$(basename $d): accel_update_ms $(awk -F, 'NR>11 {s+=$13; n++} END {printf "%.4f", s/n}' $d/timings.csv)"; done
  for on in gpu cpu; do
    timeout 30 glint render atrium --backend gl --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only $common --shadows rt --update refit --deform on --deform-on $on --profile-scopes --out $R/s/gl-deform-on-$on > $R/s.log 2>&1 || echo "scopes $on failed"
  done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -vE "compute_visibility/|ssr/|resolve/|light/" $R/scopes.md
  rm -rf $R/f/*/frame_*.png
fi
# e: the fused reflection + hit-shadow kernel with the two walks written out apart (.exp/spec, through
# GLINT_SHADER_DIR) against the embedded one (one walk with an any_hit argument, called twice); the
# closest-hit kernel alone (cube shadows) new against base.
if [ "$STEP" = e ]; then
  for rep in 1 2; do
    for v in embedded spec; do dir=$PWD/.exp/$v; [ $v = embedded ] && dir=""
      for mode in hybrid rt; do
        env ${dir:+GLINT_SHADER_DIR=$dir} timeout 60 glint render atrium --backend gl --reflections $mode --width 1280 --height 720 --frames 2071:2110 \
          --timings-only $common --shadows rt --deform off --out $R/f/gl$v-$mode-rtshadows-r$rep > $R/f.log 2>&1 || { echo "$v failed"; tail -2 $R/f.log; }
      done
    done
    for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
      timeout 60 $g render atrium --backend gl --reflections rt --width 1280 --height 720 --frames 2071:2110 \
        --timings-only $common --shadows cube --deform off --out $R/f/$bin-gl-rt-cubeshadows-r$rep > $R/f.log 2>&1 || echo "$bin cube failed"
    done
  done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for v in embedded spec; do dir=$PWD/.exp/$v; [ $v = embedded ] && dir=""
    env ${dir:+GLINT_SHADER_DIR=$dir} timeout 60 glint render atrium --backend gl --reflections hybrid --width 1280 --height 720 --frames 2096:2103 \
      $common --shadows rt --deform off --out $R/img-$v > $R/img.log 2>&1 || echo "images $v failed"
  done
  n=0; for f in $R/img-embedded/frame_*.png; do cmp -s $f $R/img-spec/$(basename $f) && n=$((n+1)); done; echo "spec: $n of 8 frames byte-equal to embedded"
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
# f: variants of the gl backend's inline hit-shadow pass through GLINT_SHADER_DIR (timing; vgenonly
# makes the rays without tracing them, vnoprecise changes the rays by rounding: timing only).
if [ "$STEP" = f ]; then
  VARIANTS=${VARIANTS:-"cur v64 vnoprecise vgenonly"}
  for rep in 1 2; do for v in $VARIANTS; do
    env GLINT_SHADER_DIR=$PWD/.exp/$v timeout 60 glint render atrium --backend gl --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only $common --shadows rt --deform off --profile-scopes --out $R/s/gl-$v-r$rep > $R/s.log 2>&1 || { echo "$v failed"; tail -2 $R/s.log; }
  done; done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "^\| (scope|trace|shadow/shadow_rays/inline_trace)" $R/scopes.md
fi
# g: images of the gl backend deforming on the GPU (GL deformer, GL refit) against the first binary's
# host deformation and refit (both --update refit), 8 frames, glint compare (SSIM, PSNR).
if [ "$STEP" = g ]; then
  for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    timeout 60 $g render atrium --backend gl --reflections hybrid --width 1280 --height 720 --frames 2096:2103 \
      $common --shadows rt --deform on --update refit --out $R/img-$bin > $R/img.log 2>&1 || { echo "images $bin failed"; tail -2 $R/img.log; }
  done
  grep -o '"deform_on": *"[a-z]*"' $R/img-base/run.json $R/img-new/run.json
  for f in $R/img-base/frame_*.png; do echo "$(basename $f): $(glint compare $f $R/img-new/$(basename $f) 2>&1 | tr '\n' ' ' | cut -c1-300)"; done
  rm -rf $R/img-*
fi
# h: scenes it was not tuned for: atrium-simple and sponza, gl against cuda (frames, and the gl frame
# against the cuda frame: glint compare), this tree.
if [ "$STEP" = h ]; then
  for scene in atrium-simple sponza; do for be in cuda gl; do for rep in 1 2; do
    timeout 90 glint render $scene --backend $be --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only $common --shadows rt --update refit --out $R/f/$scene-$be-r$rep > $R/f.log 2>&1 || { echo "$scene $be failed"; tail -2 $R/f.log; }
  done
    timeout 90 glint render $scene --backend $be --reflections hybrid --width 1280 --height 720 --frames 1800,2100,2300,4400 \
      $common --shadows rt --update refit --out $R/img-$scene-$be > $R/img.log 2>&1 || { echo "images $scene $be failed"; tail -2 $R/img.log; }
  done
    for f in $R/img-$scene-cuda/frame_*.png; do echo "$scene $(basename $f) gl vs cuda: $(glint compare $R/img-$scene-gl/$(basename $f) $f 2>&1 | grep -E 'SSIM|PSNR|buckets' | tr -s ' ' | tr '\n' ' ')"; done
  done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
