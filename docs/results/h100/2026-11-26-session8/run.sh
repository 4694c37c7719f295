#!/usr/bin/env bash
# Session 8's GPU calls. h: host time inside the interop map/unmap, map-once upper bound, Vulkan probe.
# f: the session's tree against the previous session's binary: tests, frames, scopes, images. t: whole suite.
# r: the refit of all deforming meshes in one launch (new vs base), deforming frames and images.
# p: more GLSL walk variants (register top of stack, one array, groups of 64) and the gl backend deforming.
# m: walk variants: CUDA entry-less stacks (new2 vs new1), GLSL stack variants (GLINT_SHADER_DIR).
# k: any-hit walk without entry distances (new vs base) and shadow rays in blocks (GLINT_SHADER_DIR variants).
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
if [ "$STEP" = h ]; then
  { ls -la /usr/share/vulkan/icd.d /etc/vulkan/icd.d /usr/local/nvidia/share/vulkan/icd.d 2>&1; ldconfig -p | grep -iE "vulkan|GLX_nvidia|nvidia-glvk"; ls /usr/lib/x86_64-linux-gnu | grep -iE "nvidia" | head -40; } > $R/vulkan-probe.txt 2>&1
  cat $R/vulkan-probe.txt
  for v in plain host once; do
    envs=""; [ $v = host ] && envs="GLINT_INTEROP_HOST_TIMES=1"; [ $v = once ] && envs="GLINT_INTEROP_HOST_TIMES=1 GLINT_INTEROP_MAP_ONCE=1"
    for mode in hybrid rt off; do
      env $envs timeout 40 glint render atrium --backend cuda --reflections $mode --width 1280 --height 720 --frames 2071:2110 \
        --timings-only $common --shadows rt --deform off --out $R/f/$v-$mode > $R/f-$v-$mode.log 2>&1 || { echo "$v $mode failed"; tail -2 $R/f-$v-$mode.log; }
      grep "interop host" $R/f-$v-$mode.log | sed "s/^/$v $mode: /"
    done
    env $envs timeout 30 glint render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only $common --shadows rt --deform off --profile-scopes --out $R/s/$v > $R/s.log 2>&1 || echo "scopes $v failed"
  done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "^\| (scope|gbuffer|light|shadow|device_trace|ssr|resolve|frame)" $R/scopes.md
  rm -rf $R/f/*/frame_*.png
fi
if [ "$STEP" = k ]; then
  ( cd $R && timeout 200 glint_tests --gtest_brief=1 --gtest_filter='*Occlusion*:*GlRayTracer*:*RayTracedShadows*:*HitShadow*:*CudaRayTracer*:*TraceAny*:*HybridPipeline*:GoldenImage*' > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|SKIPPED \]" $R/tests.log | tail -12
  run() {  # name binary shader-dir mode size backend [extra]
    local name=$1 g=$2 dir=$3 mode=$4 size=$5 be=$6; shift 6
    env ${dir:+GLINT_SHADER_DIR=$dir} timeout 60 $g render atrium --backend $be --reflections $mode --width ${size%x*} --height ${size#*x} \
      --frames 2071:2110 --timings-only $common --shadows rt --deform off "$@" --out $R/f/$name > $R/run.log 2>&1 || { echo "$name failed"; tail -2 $R/run.log; }
  }
  for rep in 1 2; do
    for mode in hybrid rt off; do
      run base-$mode-r$rep /tmp/w/glint-base "" $mode 1280x720 cuda
      run new-$mode-r$rep glint "" $mode 1280x720 cuda
      for v in 8x4 4x8 16x2; do run t$v-$mode-r$rep glint .exp/tile$v $mode 1280x720 cuda; done
    done
    run base-hybrid2560-r$rep /tmp/w/glint-base "" hybrid 2560x1440 cuda
    run new-hybrid2560-r$rep glint "" hybrid 2560x1440 cuda
    run t8x4-hybrid2560-r$rep glint .exp/tile8x4 hybrid 2560x1440 cuda
    run gl-base-hybrid-r$rep /tmp/w/glint-base "" hybrid 1280x720 gl
    run gl-new-hybrid-r$rep glint "" hybrid 1280x720 gl
    run gl-t8x4-hybrid-r$rep glint .exp/tile8x4 hybrid 1280x720 gl
  done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for v in base:/tmp/w/glint-base: new:glint: t8x4:glint:.exp/tile8x4 gl-base:/tmp/w/glint-base: gl-new:glint:; do
    name=${v%%:*}; rest=${v#*:}; g=${rest%%:*}; dir=${rest#*:}; be=cuda; [[ $name == gl-* ]] && be=gl
    env ${dir:+GLINT_SHADER_DIR=$dir} timeout 40 $g render atrium --backend $be --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only $common --shadows rt --deform off --profile-scopes --out $R/s/$name > $R/s.log 2>&1 || echo "scopes $name failed"
  done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "^\| (scope|gbuffer \||light \||shadow|device_trace|ssr \||resolve \||trace|hit)" $R/scopes.md
  for v in base:/tmp/w/glint-base: new:glint: t8x4:glint:.exp/tile8x4; do
    name=${v%%:*}; rest=${v#*:}; g=${rest%%:*}; dir=${rest#*:}
    env ${dir:+GLINT_SHADER_DIR=$dir} timeout 60 $g render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2096:2103 \
      $common --shadows rt --deform on --out $R/img-$name > $R/img.log 2>&1 || echo "images $name failed"
  done
  for name in new t8x4; do n=0; for f in $R/img-base/frame_*.png; do cmp -s $f $R/img-$name/$(basename $f) && n=$((n+1)) || echo "$name DIFFERENT $(basename $f)"; done; echo "$name: $n frames byte-equal to base"; done
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
if [ "$STEP" = m ]; then
  [ -x /tmp/w/glint-new1 ] || { xz -dc .gpu-new1.xz > /tmp/w/glint-new1; chmod +x /tmp/w/glint-new1; }
  ( cd $R && timeout 200 glint_tests --gtest_brief=1 --gtest_filter='*Occlusion*:*GlRayTracer*:*CudaRayTracer*:*TraceAny*:*Cuda*Trace*:GoldenImage*' > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|SKIPPED \]" $R/tests.log | tail -12
  run() {  # name binary shader-dir mode size backend
    local name=$1 g=$2 dir=$3 mode=$4 size=$5 be=$6; shift 6
    env ${dir:+GLINT_SHADER_DIR=$dir} timeout 60 $g render atrium --backend $be --reflections $mode --width ${size%x*} --height ${size#*x} \
      --frames 2071:2110 --timings-only $common --shadows rt --deform off "$@" --out $R/f/$name > $R/run.log 2>&1 || { echo "$name failed"; tail -2 $R/run.log; }
  }
  for rep in 1 2; do
    for mode in hybrid rt; do
      run new1-$mode-r$rep /tmp/w/glint-new1 .exp/tile8x4 $mode 1280x720 cuda
      run new2-$mode-r$rep glint .exp/tile8x4 $mode 1280x720 cuda
      for v in tile8x4 a c; do run gl$v-$mode-r$rep glint .exp/$v $mode 1280x720 gl; done
    done
    run new1-hybrid2560-r$rep /tmp/w/glint-new1 .exp/tile8x4 hybrid 2560x1440 cuda
    run new2-hybrid2560-r$rep glint .exp/tile8x4 hybrid 2560x1440 cuda
    run glc-hybrid2560-r$rep glint .exp/c hybrid 2560x1440 gl
    run glc-hybrid-deform-r$rep glint .exp/c hybrid 1280x720 gl --deform on
    run new2-hybrid-deform-r$rep glint .exp/tile8x4 hybrid 1280x720 cuda --deform on
  done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for v in new1:/tmp/w/glint-new1:.exp/tile8x4:cuda new2:glint:.exp/tile8x4:cuda gl-t:glint:.exp/tile8x4:gl gl-a:glint:.exp/a:gl gl-c:glint:.exp/c:gl; do
    IFS=: read name g dir be <<< "$v"
    env GLINT_SHADER_DIR=$dir timeout 40 $g render atrium --backend $be --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only $common --shadows rt --deform off --profile-scopes --out $R/s/$name > $R/s.log 2>&1 || echo "scopes $name failed"
  done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "^\| (scope|shadow|device_trace \||trace|hit)" $R/scopes.md
  for v in new1:/tmp/w/glint-new1:.exp/tile8x4:cuda new2:glint:.exp/tile8x4:cuda gl-c:glint:.exp/c:gl gl-t:glint:.exp/tile8x4:gl; do
    IFS=: read name g dir be <<< "$v"
    env GLINT_SHADER_DIR=$dir timeout 60 $g render atrium --backend $be --reflections hybrid --width 1280 --height 720 --frames 2096:2103 \
      $common --shadows rt --deform on --out $R/img-$name > $R/img.log 2>&1 || echo "images $name failed"
  done
  for name in new2 gl-c gl-t; do n=0; for f in $R/img-new1/frame_*.png; do cmp -s $f $R/img-$name/$(basename $f) && n=$((n+1)) || echo "$name DIFFERENT $(basename $f): $(glint compare $f $R/img-$name/$(basename $f) 2>&1 | tail -1)"; done; echo "$name: $n frames byte-equal to new1"; done
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
if [ "$STEP" = p ]; then
  ( cd $R && timeout 300 glint_tests --gtest_brief=1 --gtest_filter='*ShadowRay*:*RayTracedShadows*:*GlRayTracer*:*Occlusion*:*HitShadow*:*CudaRayTracer*:GoldenImage*:*HybridPipeline*:*Gl*Trac*' > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|SKIPPED \]" $R/tests.log | tail -12
  run() {  # name shader-dir mode size backend deform
    local name=$1 dir=$2 mode=$3 size=$4 be=$5 deform=$6
    env ${dir:+GLINT_SHADER_DIR=$dir} timeout 60 glint render atrium --backend $be --reflections $mode --width ${size%x*} --height ${size#*x} \
      --frames 2071:2110 --timings-only $common --shadows rt --deform $deform --out $R/f/$name > $R/run.log 2>&1 || { echo "$name failed"; tail -2 $R/run.log; }
  }
  for rep in 1 2; do
    run cuda-hybrid-r$rep "" hybrid 1280x720 cuda off
    run cuda-rt-r$rep "" rt 1280x720 cuda off
    run cuda-hybrid2560-r$rep "" hybrid 2560x1440 cuda off
    run cuda-hybrid-deform-r$rep "" hybrid 1280x720 cuda on
    run gl-hybrid-deform-r$rep "" hybrid 1280x720 gl on
    for v in embedded v1 v3 v6 v13 v36; do dir=.exp/$v; [ $v = embedded ] && dir=""
      run gl$v-hybrid-r$rep "$dir" hybrid 1280x720 gl off
      run gl$v-rt-r$rep "$dir" rt 1280x720 gl off
      run gl$v-hybrid2560-r$rep "$dir" hybrid 2560x1440 gl off
    done
  done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for v in embedded v1 v3 v6 v13 v36; do dir=.exp/$v; [ $v = embedded ] && dir=""
    env ${dir:+GLINT_SHADER_DIR=$dir} timeout 40 glint render atrium --backend gl --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only $common --shadows rt --deform off --profile-scopes --out $R/s/gl-$v > $R/s.log 2>&1 || echo "scopes $v failed"
  done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "^\| (scope|shadow/shadow_rays/trace|trace \||hit_shade/hit_shadow_rays/trace)" $R/scopes.md
  rm -rf $R/f/*/frame_*.png
fi
if [ "$STEP" = r ]; then
  run() {  # name binary mode size deform
    local name=$1 g=$2 mode=$3 size=$4 deform=$5
    timeout 60 $g render atrium --backend cuda --reflections $mode --width ${size%x*} --height ${size#*x} \
      --frames 2071:2110 --timings-only $common --shadows rt --deform $deform --out $R/f/$name > $R/run.log 2>&1 || { echo "$name failed"; tail -2 $R/run.log; }
  }
  for rep in 1 2; do
    for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
      for deform in off on; do run $bin-hybrid-deform-$deform-r$rep $g hybrid 1280x720 $deform; done
      run $bin-hybrid2560-deform-on-r$rep $g hybrid 2560x1440 on
    done
  done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for d in $R/f/*deform-on*; do echo "$(basename $d): accel_update_ms $(awk -F, 'NR>11 {s+=$13; n++} END {printf "%.4f", s/n}' $d/timings.csv)"; done | sort | tee $R/update.txt
  for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    timeout 60 $g render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2096:2103 \
      $common --shadows rt --deform on --out $R/img-$bin > $R/img.log 2>&1 || echo "images $bin failed"
    timeout 60 $g render atrium --backend cuda --accel lbvh --reflections rt --width 640 --height 360 --frames 2096:2103 \
      --gbuffer visibility --primary compute --shadows rt --deform on --out $R/img-lbvh-$bin > $R/img.log 2>&1 || echo "images lbvh $bin failed"
  done
  for pair in img-base:img-new img-lbvh-base:img-lbvh-new; do a=${pair%%:*}; b=${pair#*:}; n=0; for f in $R/$a/frame_*.png; do cmp -s $f $R/$b/$(basename $f) && n=$((n+1)) || echo "$b DIFFERENT $(basename $f)"; done; echo "$b: $n frames byte-equal to $a"; done
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
if [ "$STEP" = f ] || [ "$STEP" = t ]; then
  filter='*ComputeVisibility*:*ShadowMask*:*HitShading*:*Shadow*:GoldenImage*:*HybridPipeline*:RenderCli*:RenderScopes*:*DeterministicFrames*:*Ssr*:*Pyramid*:*GpuBvh*:*CudaRayTracer*:*Occlusion*:*GlRayTracer*:*Deform*:*Refit*'
  [ "$STEP" = t ] && filter='*'
  ( cd $R && timeout 500 glint_tests --gtest_brief=1 --gtest_filter="$filter" > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|golden|SKIPPED \]" $R/tests.log | tail -16
fi
if [ "$STEP" = f ]; then
  for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    for cfg in 1280x720:hybrid:rt:cuda 1280x720:rt:rt:cuda 1280x720:ssr:rt:cuda 1280x720:off:rt:cuda 2560x1440:hybrid:rt:cuda 2560x1440:rt:rt:cuda 1280x720:hybrid:cube:cuda 1280x720:hybrid:rt:gl 1280x720:rt:rt:gl; do
      IFS=: read size mode sh be <<< "$cfg"
      for deform in off on; do
        [ $be = gl ] && [ $deform = on ] && continue
        timeout 40 $g render atrium --backend $be --reflections $mode --width ${size%x*} --height ${size#*x} --frames 2071:2110 \
          --timings-only $common --shadows $sh --deform $deform --out $R/f/$bin-$be-$size-$mode-$sh-deform-$deform > $R/f.log 2>&1 || { echo "$bin $cfg $deform failed"; tail -2 $R/f.log; }
      done; done
    for be in cuda gl; do
      timeout 30 $g render atrium --backend $be --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
        --timings-only $common --shadows rt --deform off --profile-scopes --out $R/s/$bin-$be > $R/s.log 2>&1 || echo "scopes $bin $be failed"
    done
    timeout 30 $g render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only --accel sah --deform off --profile-scopes --out $R/s/$bin-paper > $R/s.log 2>&1 || echo "scopes paper $bin failed"
    for cfg in hybrid:rt rt:rt hybrid:cube; do mode=${cfg%%:*}; sh=${cfg#*:}
      timeout 60 $g render atrium --backend cuda --reflections $mode --width 1280 --height 720 --frames 2096:2103 \
        $common --shadows $sh --deform on --out $R/img-$bin-$mode-$sh > $R/img.log 2>&1 || echo "images $bin $cfg failed"
    done
  done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for d in $R/f/*deform-on*; do echo "$(basename $d): accel_update_ms $(awk -F, 'NR>11 {s+=$13; n++} END {printf "%.4f", s/n}' $d/timings.csv)"; done | sort > $R/update.txt
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "^\| (scope|gbuffer \||shadow \||ssr \||ssr/ssr_march/depth_pyramid|device_trace \||light \||resolve \||trace \|)" $R/scopes.md
  for cfg in hybrid-rt rt-rt hybrid-cube; do n=0; for f in $R/img-base-$cfg/frame_*.png; do cmp -s $f $R/img-new-$cfg/$(basename $f) && n=$((n+1)) || { echo "$cfg DIFFERENT $(basename $f): $(glint compare $f $R/img-new-$cfg/$(basename $f) 2>&1 | tail -1)"; }; done; echo "$cfg: $n frames byte-equal to base"; done
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
