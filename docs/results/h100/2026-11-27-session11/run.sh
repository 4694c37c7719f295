#!/usr/bin/env bash
# Session 11's GPU calls (H100). Shader variants through GLINT_SHADER_DIR=.exp/<name> on one binary
# ("embedded" = the binary's own shaders); base = the session's first binary with .exp/base (the walk
# of 798b084). Result files are named <step><call>-*: call 1 07:35 (a, v: the one-loop walk as
# embedded, u), 2 07:52 (a, v, r: depth pyramid and deformer), 3 07:59 (a, v: leaf corners), 4 08:04
# (n), 5 08:09 (a, k, v: the deformer's direct write), 6 08:11 (v, h), 7 08:15 (a, v: the refit's
# climb), 8 08:19 (v, h: the final tree a6894c1), 9 08:21 (c: the whole suite). The throwaway
# binaries of steps n and k were built from the tree with one line changed (the copy skipped; the
# trace capacity clamped to 200,000), timing only. The shader variants tried are the variant-*.patch
# files beside this one (the leaf-corners one is a whole-tree change against 9942abc).
set -u
STEP=$1
R=/tmp/r-$STEP; rm -rf $R; mkdir -p $R
if [ ! -x /tmp/w/.gpu/bin/glint ]; then mkdir -p /tmp/w && tar -xJf .gpu.tar.xz -C /tmp/w; fi
source /tmp/w/.gpu/env.sh
export GLINT_CLI=/tmp/w/.gpu/bin/glint GLINT_SOURCE_DIR=$PWD GLINT_ASSETS=/tmp/w/.gpu/assets PATH=/tmp/w/.gpu/bin:$PATH
pack() { tar -C /tmp -cJf $OUT/r-$STEP.tar.xz r-$STEP; }
trap pack EXIT
{ nvidia-smi --query-gpu=name,driver_version --format=csv,noheader; date -u; } | tee $R/device.txt
common="--gbuffer visibility --primary compute --accel sah --shadows rt"
[ -x /tmp/w/glint-base ] || { xz -dc .gpu-base.xz > /tmp/w/glint-base; chmod +x /tmp/w/glint-base; }
# run VARIANT ARGS...: glint (or the base binary for "base") with the variant's shader folder.
run() { local v=$1; shift; local g=glint dir=$PWD/.exp/$v
  [ $v = base ] && g=/tmp/w/glint-base; [ $v = embedded ] && dir=""
  env ${dir:+GLINT_SHADER_DIR=$dir} timeout 90 $g "$@"; }
if [ "$STEP" = a ]; then
  ( timeout 500 glint_tests --gtest_brief=1 --gtest_filter="${FILTER:-*GlRayTracer*:*Gl*Refit*:*Deform*:*RayTracedShadows*:*HitShadow*:*Occlusion*:GoldenImage*:*Hybrid*:GlInline*:*DepthPyramid*:*Ssr*}" > $R/tests.log 2>&1; echo "tests rc=$?" >> $R/tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|SKIPPED \]" $R/tests.log | tail -30
fi
# v: variants, frames (2 reps) and scopes; CFGS entries scene:mode:deform:backend:size; images of each
# variant against the first (gl and cuda, deforming).
if [ "$STEP" = v ]; then
  VARIANTS=${VARIANTS:-"base embedded"}
  CFGS=${CFGS:-"atrium:hybrid:off:gl:1280x720 atrium:hybrid:on:gl:1280x720 atrium:rt:off:gl:1280x720 sponza:hybrid:off:gl:1280x720"}
  for rep in 1 2; do for v in $VARIANTS; do for cfg in $CFGS; do IFS=: read scene mode deform be size <<< "$cfg"
    run $v render $scene --backend $be --reflections $mode --width ${size%x*} --height ${size#*x} --frames 2071:2110 --timings-only \
      $common $([ $be = gl ] && echo --update refit) --deform $deform --out $R/f/$v-$scene-$be-$size-$mode-deform-$deform-r$rep > $R/f.log 2>&1 || { echo "$v $cfg failed"; tail -2 $R/f.log; }
  done; done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for v in $VARIANTS; do for be in gl cuda; do
    run $v render atrium --backend $be --reflections hybrid --width 1280 --height 720 --frames 2071:2110 --timings-only \
      $common $([ $be = gl ] && echo --update refit) --deform on --profile-scopes --out $R/s/$v-$be > $R/s.log 2>&1 || echo "scopes $v $be failed"
    run $v render atrium --backend $be --reflections hybrid --width 1280 --height 720 --frames 2096:2103 \
      $common $([ $be = gl ] && echo --update refit) --deform on --out $R/img-$v-$be > $R/img.log 2>&1 || echo "images $v $be failed"
  done; done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; cat $R/scopes.md
  first=${VARIANTS%% *}
  for v in $VARIANTS; do for be in gl cuda; do n=0; for f in $R/img-$first-$be/frame_*.png; do cmp -s $f $R/img-$v-$be/$(basename $f) && n=$((n+1)) || echo "$v $be DIFFERENT $(basename $f): $(glint compare $f $R/img-$v-$be/$(basename $f) 2>&1 | tail -1)"; done; echo "$v $be: $n frames byte-equal to $first"; done; done
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
# r: the GL refit's parts (timing only: variants that skip a dispatch or the climb's barriers).
if [ "$STEP" = r ]; then
  for rep in 1 2; do for v in embedded refit_nobarrier refit_blasonly refit_tlasonly; do
    run $v render atrium --backend gl --reflections hybrid --width 1280 --height 720 --frames 2071:2110 --timings-only \
      $common --update refit --deform on --profile-scopes --out $R/s/$v-r$rep > $R/s.log 2>&1 || { echo "$v failed"; tail -2 $R/s.log; }
  done; done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "^\| (scope|deform|accel_refit|trace )" $R/scopes.md
fi
# u: what deforming costs the gl trace: the host's refit against its rebuild (SAH on each pose) and
# the static frame, scopes.
if [ "$STEP" = u ]; then
  for cfg in refit:off:gpu refit:on:gpu refit:on:cpu rebuild:on:cpu; do IFS=: read up deform on <<< "$cfg"
    timeout 90 glint render atrium --backend gl --reflections hybrid --width 1280 --height 720 --frames 2071:2110 --timings-only \
      $common --update $up --deform $deform --deform-on $on --profile-scopes --out $R/s/gl-$up-deform-$deform-$on > $R/s.log 2>&1 || { echo "$cfg failed"; tail -2 $R/s.log; }
  done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "^\| (scope|trace|shadow |shadow/shadow_rays/inline|hit_shade/hit_shadow_rays/trace|deform|accel)" $R/scopes.md
fi
# n: the deforming gl frame without the copy of the poses into the tracer's vertices (a throwaway
# binary, timing only: the refit then reads stale positions) against the tree's binary; and the host
# CPU time per frame of a long static run (is the frame loop CPU-bound?).
if [ "$STEP" = n ]; then
  [ -x /tmp/w/glint-nocopy ] || { xz -dc .exp/glint-nocopy.xz > /tmp/w/glint-nocopy; chmod +x /tmp/w/glint-nocopy; }
  for rep in 1 2; do for v in tree nocopy; do g=glint; [ $v = nocopy ] && g=/tmp/w/glint-nocopy
    timeout 90 $g render atrium --backend gl --reflections hybrid --width 1280 --height 720 --frames 2071:2110 --timings-only \
      $common --update refit --deform on --out $R/f/$v-deform-on-r$rep > $R/f.log 2>&1 || { echo "$v failed"; tail -2 $R/f.log; }
  done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for deform in off on; do
    /usr/bin/time -f "deform $deform: user %U s, system %S s, wall %e s for 1000 frames" timeout 120 glint render atrium --backend gl --reflections hybrid --width 1280 --height 720 --frames 2071:3070 --timings-only \
      $common --update refit --deform $deform --out $R/long-$deform > $R/long.log 2>&1; tail -1 $R/long.log
    python3 tools/frame_table.py $R/long-$deform/.. 2>/dev/null | grep long-$deform
  done
fi
# k: the gl traces dispatched for at most 200,000 rays instead of the ray list's capacity (a throwaway
# binary, timing only; hybrid lists hold fewer rays, so the images are the same) against the tree's.
if [ "$STEP" = k ]; then
  [ -x /tmp/w/glint-clamp ] || { xz -dc .exp/glint-clamp.xz > /tmp/w/glint-clamp; chmod +x /tmp/w/glint-clamp; }
  for rep in 1 2; do for v in tree clamp; do g=glint; [ $v = clamp ] && g=/tmp/w/glint-clamp
    for deform in off on; do
      timeout 90 $g render atrium --backend gl --reflections hybrid --width 1280 --height 720 --frames 2071:2110 --timings-only \
        $common --update refit --deform $deform --out $R/f/$v-deform-$deform-r$rep > $R/f.log 2>&1 || { echo "$v failed"; tail -2 $R/f.log; }
    done
  done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for v in tree clamp; do g=glint; [ $v = clamp ] && g=/tmp/w/glint-clamp
    timeout 90 $g render atrium --backend gl --reflections hybrid --width 1280 --height 720 --frames 2071:2110 --timings-only \
      $common --update refit --deform on --profile-scopes --out $R/s/$v > $R/s.log 2>&1 || echo "scopes $v failed"
  done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "^\| (scope|trace |hit_shade/hit_shadow_rays/trace|deform|accel_refit)" $R/scopes.md
fi
# h: scenes it was not tuned for: atrium-simple and sponza, gl against cuda (frames, and the gl frame
# against the cuda frame: glint compare), this tree.
if [ "$STEP" = h ]; then
  for scene in atrium-simple sponza; do for be in cuda gl; do for rep in 1 2; do
    timeout 90 glint render $scene --backend $be --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only $common --update refit --out $R/f/$scene-$be-r$rep > $R/f.log 2>&1 || { echo "$scene $be failed"; tail -2 $R/f.log; }
  done
    timeout 90 glint render $scene --backend $be --reflections hybrid --width 1280 --height 720 --frames 1800,2100,2300,4400 \
      $common --update refit --out $R/img-$scene-$be > $R/img.log 2>&1 || { echo "images $scene $be failed"; tail -2 $R/img.log; }
  done
    for f in $R/img-$scene-cuda/frame_*.png; do echo "$scene $(basename $f) gl vs cuda: $(glint compare $R/img-$scene-gl/$(basename $f) $f 2>&1 | grep -E 'SSIM|PSNR|buckets' | tr -s ' ' | tr '\n' ' ')"; done
  done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
# c: the whole test suite.
if [ "$STEP" = c ]; then
  ( cd $R && timeout 560 glint_tests --gtest_brief=1 > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|SKIPPED \]" $R/tests.log | tail -30
fi
