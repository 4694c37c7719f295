#!/usr/bin/env bash
# Session 9's GPU calls. a: GLSL walk variants (while-while, TLAS too, speculative with a group vote)
# through GLINT_SHADER_DIR on one binary: tests, frames, scopes, images against the embedded shaders.
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
run() {  # name shader-dir mode size backend deform
  local name=$1 dir=$2 mode=$3 size=$4 be=$5 deform=$6; shift 6
  env ${dir:+GLINT_SHADER_DIR=$dir} timeout 60 glint render atrium --backend $be --reflections $mode --width ${size%x*} --height ${size#*x} \
    --frames 2071:2110 --timings-only $common --shadows rt --deform $deform "$@" --out $R/f/$name > $R/run.log 2>&1 || { echo "$name failed"; tail -2 $R/run.log; }
}
if [ "$STEP" = a ]; then
  VARIANTS=${VARIANTS:-"ww ww2 spec"}
  for v in embedded $VARIANTS; do dir=.exp/$v; [ $v = embedded ] && dir=""
    ( env ${dir:+GLINT_SHADER_DIR=$PWD/$dir} timeout 200 glint_tests --gtest_brief=1 --gtest_filter='*GlRayTracer*:*Occlusion*:*RayTracedShadows*:*HitShadow*' > $R/tests-$v.log 2>&1; echo "tests rc=$?" >> $R/tests-$v.log )
    echo "$v: $(grep -E 'PASSED|FAILED|rc=' $R/tests-$v.log | tr '\n' ' ')"
  done
  for rep in 1 2; do
    run cuda-hybrid-r$rep "" hybrid 1280x720 cuda off
    for v in embedded $VARIANTS; do dir=.exp/$v; [ $v = embedded ] && dir=""
      run gl$v-hybrid-r$rep "$dir" hybrid 1280x720 gl off
      run gl$v-rt-r$rep "$dir" rt 1280x720 gl off
      run gl$v-hybrid2560-r$rep "$dir" hybrid 2560x1440 gl off
    done
  done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for v in embedded $VARIANTS; do dir=.exp/$v; [ $v = embedded ] && dir=""
    env ${dir:+GLINT_SHADER_DIR=$dir} timeout 40 glint render atrium --backend gl --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only $common --shadows rt --deform off --profile-scopes --out $R/s/gl-$v > $R/s.log 2>&1 || echo "scopes $v failed"
    env ${dir:+GLINT_SHADER_DIR=$dir} timeout 60 glint render atrium --backend gl --reflections hybrid --width 1280 --height 720 --frames 2096:2103 \
      $common --shadows rt --deform off --out $R/img-$v > $R/img.log 2>&1 || echo "images $v failed"
  done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "^\| (scope|shadow/shadow_rays/trace|trace \||hit_shade/hit_shadow_rays/trace)" $R/scopes.md
  for v in $VARIANTS; do n=0; for f in $R/img-embedded/frame_*.png; do cmp -s $f $R/img-$v/$(basename $f) && n=$((n+1)) || echo "$v DIFFERENT $(basename $f)"; done; echo "$v: $n frames byte-equal to embedded"; done
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
# b: the CUDA walk in while-while form (new binary) against the previous binary (base); the GLSL
# while-while at both levels (.exp/ww2) against the embedded walk; what the two-level structure costs
# against one flat BVH (accel-bench on frame 2100's mirror rays; the frame's closest-hit trace).
if [ "$STEP" = b ]; then
  ( timeout 300 glint_tests --gtest_brief=1 --gtest_filter='*Occlusion*:*GlRayTracer*:*CudaRayTracer*:*TraceAny*:*Cuda*Trace*:*GpuBvh*:*RayTracedShadows*:*HitShadow*:GoldenImage*:*HybridPipeline*:*DeterministicFrames*' > $R/tests.log 2>&1; echo "tests rc=$?" >> $R/tests.log )
  grep -E "FAILED|PASSED|tests from|rc=" $R/tests.log | tail -8
  runb() {  # name binary shader-dir mode size backend deform [extra]
    local name=$1 g=$2 dir=$3 mode=$4 size=$5 be=$6 deform=$7; shift 7
    env ${dir:+GLINT_SHADER_DIR=$dir} timeout 60 $g render atrium --backend $be --reflections $mode --width ${size%x*} --height ${size#*x} \
      --frames 2071:2110 --timings-only $common --deform $deform "$@" --out $R/f/$name > $R/run.log 2>&1 || { echo "$name failed"; tail -2 $R/run.log; }
  }
  for rep in 1 2; do
    for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
      for mode in hybrid rt; do runb $bin-cuda-$mode-r$rep $g "" $mode 1280x720 cuda off --shadows rt; done
      runb $bin-cuda-hybrid-deform-r$rep $g "" hybrid 1280x720 cuda on --shadows rt
      runb $bin-cuda-hybrid2560-r$rep $g "" hybrid 2560x1440 cuda off --shadows rt
    done
    for v in embedded ww2; do dir=.exp/$v; [ $v = embedded ] && dir=""
      runb gl$v-hybrid-r$rep glint "$dir" hybrid 1280x720 gl off --shadows rt
      runb gl$v-hybrid2560-r$rep glint "$dir" hybrid 2560x1440 gl off --shadows rt
    done
  done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    timeout 30 $g render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only $common --shadows rt --deform off --profile-scopes --out $R/s/$bin-cuda > $R/s.log 2>&1 || echo "scopes $bin failed"
    for cfg in hybrid:rt rt:rt; do mode=${cfg%%:*}; sh=${cfg#*:}
      timeout 60 $g render atrium --backend cuda --reflections $mode --width 1280 --height 720 --frames 2096:2103 \
        $common --shadows $sh --deform on --out $R/img-$bin-$mode > $R/img.log 2>&1 || echo "images $bin $cfg failed"
    done
  done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "^\| (scope|shadow \||device_trace \||trace \|)" $R/scopes.md
  for mode in hybrid rt; do n=0; for f in $R/img-base-$mode/frame_*.png; do cmp -s $f $R/img-new-$mode/$(basename $f) && n=$((n+1)) || echo "$mode DIFFERENT $(basename $f)"; done; echo "$mode: $n frames byte-equal to base"; done
  # Two levels against one flat BVH: reflection rays only (cube shadows: trace_ms is the closest-hit kernel alone).
  for be in cuda gl; do
    timeout 60 glint render atrium --backend $be --reflections rt --width 1280 --height 720 --frames 2071:2110 --timings-only \
      --gbuffer visibility --primary compute --accel sah --shadows cube --deform off --out $R/two-level-$be > $R/tl.log 2>&1 || echo "two-level $be failed"
    awk -F, -v be=$be 'NR>11 {t+=$14; r+=$18; n++} END {printf "two-level %s: %d frames, mean rays %.0f, mean closest-hit trace %.4f ms, %.0f Mrays/s\n", be, n, r/n, t/n, r/t/1000}' $R/two-level-$be/timings.csv | tee -a $R/overlap.txt
  done
  timeout 300 glint accel-bench atrium --builders cuda-sah,cuda-lbvh --rays reflection --frames 2100 --width 1280 --height 720 --deform-frames 0 --build-runs 1 \
    --json $R/accel-bench-flat.json > $R/accel-bench-flat.txt 2>&1 || echo "accel-bench failed"
  tail -20 $R/accel-bench-flat.txt
  rm -rf $R/img-* $R/f/*/frame_*.png $R/two-level-*/frame_*.png
fi
# c: accel-bench's GPU trace rate as measured on 2026-11-23 (same command), to see whether the
# closest-hit kernel got slower since (2,921 Mrays/s for cuda-sah then).
if [ "$STEP" = c ]; then
  timeout 400 glint accel-bench atrium --builders cuda-sah,cuda-lbvh,cuda-sah-persistent --rays reflection --width 1280 --height 720 \
    --deform-frames 0 --build-runs 1 --json $R/accel-bench-4frames.json > $R/accel-bench-4frames.txt 2>&1 || echo "accel-bench failed"
  grep -E "^(structure|cuda|embree-medium|scene)" $R/accel-bench-4frames.txt
  for f in 1800 2100 2300 4400; do
    timeout 200 glint accel-bench atrium --builders cuda-sah --rays reflection --frames $f --width 1280 --height 720 \
      --deform-frames 0 --build-runs 1 > $R/ab-$f.txt 2>&1; echo "frame $f: $(grep -E '^(scene|cuda-sah)' $R/ab-$f.txt | tr '\n' ' ')"
  done
  timeout 200 glint accel-bench atrium --builders cuda-sah --rays primary --frames 2100 --width 1280 --height 720 \
    --deform-frames 0 --build-runs 1 > $R/ab-primary.txt 2>&1; grep -E '^(scene|cuda-sah)' $R/ab-primary.txt
fi
# d: Nsight Compute on the trace kernels of a steady frame (cuda hybrid) and of accel-bench's cuda-sah
# trace: duration, clocks, registers, local memory, occupancy, memory throughput.
if [ "$STEP" = d ]; then
  metrics="gpu__time_duration.sum,sm__cycles_elapsed.avg.per_second,launch__registers_per_thread,launch__occupancy_limit_registers,sm__warps_active.avg.pct_of_peak_sustained_active,launch__grid_size,launch__block_size,smsp__thread_inst_executed_per_inst_executed.ratio,l1tex__t_sector_hit_rate.pct,lts__t_sector_hit_rate.pct,dram__throughput.avg.pct_of_peak_sustained_elapsed,sm__throughput.avg.pct_of_peak_sustained_elapsed,launch__stack_size,smsp__inst_executed.sum,local_load_store:l1tex__t_sectors_pipe_lsu_mem_local_op_ld.sum"
  metrics="gpu__time_duration.sum,sm__cycles_elapsed.avg.per_second,launch__registers_per_thread,launch__occupancy_limit_registers,sm__warps_active.avg.pct_of_peak_sustained_active,launch__grid_size,launch__block_size,smsp__thread_inst_executed_per_inst_executed.ratio,l1tex__t_sector_hit_rate.pct,lts__t_sector_hit_rate.pct,dram__throughput.avg.pct_of_peak_sustained_elapsed,sm__throughput.avg.pct_of_peak_sustained_elapsed,smsp__inst_executed.sum,l1tex__t_sectors_pipe_lsu_mem_local_op_ld.sum,l1tex__t_sectors_pipe_lsu_mem_global_op_ld.sum"
  timeout 250 ncu --clock-control none --kernel-name regex:"one_ray_per_thread|hit_shadow_rays" --launch-skip 60 --launch-count 6 --metrics $metrics \
    glint render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2071:2100 --timings-only $common --shadows rt --deform off --out $R/ncu-frame > $R/ncu-frame.txt 2>&1 || echo "ncu frame rc=$?"
  grep -vE "^==PROF==|^  *-+ " $R/ncu-frame.txt | grep -E "one_ray|hit_shadow|duration|per_second|registers|occupancy|warps_active|grid_size|block_size|ratio|hit_rate|throughput|inst_executed.sum|sectors" | head -120
  timeout 250 ncu --clock-control none --kernel-name regex:"one_ray_per_thread" --launch-skip 1 --launch-count 2 --metrics $metrics \
    glint accel-bench atrium --builders cuda-sah --rays reflection --frames 2100 --width 1280 --height 720 --deform-frames 0 --build-runs 1 > $R/ncu-bench.txt 2>&1 || echo "ncu bench rc=$?"
  grep -vE "^==PROF==" $R/ncu-bench.txt | grep -E "one_ray|duration|per_second|registers|occupancy|warps_active|grid_size|ratio|hit_rate|throughput|inst_executed.sum|sectors" | head -40
fi
# e: where accel-bench's flat closest-hit kernel spends its time: warp states and the hottest SASS.
if [ "$STEP" = e ]; then
  timeout 300 ncu --clock-control none --kernel-name regex:"one_ray_per_thread" --launch-skip 1 --launch-count 1 \
    --section WarpStateStats --section SourceCounters --section InstructionStats --section ComputeWorkloadAnalysis --section SchedulerStats \
    --import-source no --print-details all \
    glint accel-bench atrium --builders cuda-sah --rays reflection --frames 2100 --width 1280 --height 720 --deform-frames 0 --build-runs 1 > $R/ncu-e.txt 2>&1 || echo "ncu rc=$?"
  grep -vE "^==PROF==" $R/ncu-e.txt | sed -n '/one_ray_per_thread/,$p' | grep -vE "^\s*$" | head -150
  timeout 300 ncu --clock-control none --kernel-name regex:"one_ray_per_thread" --launch-skip 1 --launch-count 1 --page source --csv --print-source sass \
    glint accel-bench atrium --builders cuda-sah --rays reflection --frames 2100 --width 1280 --height 720 --deform-frames 0 --build-runs 1 > $R/ncu-sass.csv 2>&1 || echo "ncu sass rc=$?"
  head -3 $R/ncu-sass.csv | cut -c1-400
fi
# g: the triangle test picking the ray's axes by selects on the GPU (new) against the previous binary
# (base): tests, accel-bench trace rates, frames, scopes, kernel metrics, images.
if [ "$STEP" = g ]; then
  ( timeout 400 glint_tests --gtest_brief=1 --gtest_filter='*Occlusion*:*GlRayTracer*:*CudaRayTracer*:*TraceAny*:*Cuda*:*GpuBvh*:*RayTracedShadows*:*HitShadow*:GoldenImage*:*HybridPipeline*:*DeterministicFrames*:*Backend*:*RayTracer*:*AccelBench*' > $R/tests.log 2>&1; echo "tests rc=$?" >> $R/tests.log )
  grep -E "FAILED|PASSED|tests from|rc=" $R/tests.log | tail -8
  for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    timeout 300 $g accel-bench atrium --builders cuda-sah,cuda-lbvh --rays reflection --width 1280 --height 720 --deform-frames 0 --build-runs 1 > $R/ab-$bin.txt 2>&1
    echo "$bin: $(grep -E '^(cuda)' $R/ab-$bin.txt | awk '{print $1, $(NF-2)}' | tr '\n' ' ')"
  done
  runb() {  # name binary mode size backend deform [extra]
    local name=$1 g=$2 mode=$3 size=$4 be=$5 deform=$6; shift 6
    timeout 60 $g render atrium --backend $be --reflections $mode --width ${size%x*} --height ${size#*x} \
      --frames 2071:2110 --timings-only $common --deform $deform "$@" --out $R/f/$name > $R/run.log 2>&1 || { echo "$name failed"; tail -2 $R/run.log; }
  }
  for rep in 1 2; do
    for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
      for mode in hybrid rt off; do runb $bin-cuda-$mode-r$rep $g $mode 1280x720 cuda off --shadows rt; done
      runb $bin-cuda-hybrid-deform-r$rep $g hybrid 1280x720 cuda on --shadows rt
      runb $bin-cuda-hybrid2560-r$rep $g hybrid 2560x1440 cuda off --shadows rt
      runb $bin-cuda-hybrid2560-deform-r$rep $g hybrid 2560x1440 cuda on --shadows rt
    done
  done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    timeout 30 $g render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
      --timings-only $common --shadows rt --deform off --profile-scopes --out $R/s/$bin-cuda > $R/s.log 2>&1 || echo "scopes $bin failed"
    for cfg in hybrid:rt rt:rt hybrid:cube; do mode=${cfg%%:*}; sh=${cfg#*:}
      timeout 60 $g render atrium --backend cuda --reflections $mode --width 1280 --height 720 --frames 2096:2103 \
        $common --shadows $sh --deform on --out $R/img-$bin-$mode-$sh > $R/img.log 2>&1 || echo "images $bin $cfg failed"
    done
  done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "^\| (scope|shadow \||device_trace|trace \|)" $R/scopes.md
  for cfg in hybrid-rt rt-rt hybrid-cube; do n=0; for f in $R/img-base-$cfg/frame_*.png; do cmp -s $f $R/img-new-$cfg/$(basename $f) && n=$((n+1)) || echo "$cfg DIFFERENT $(basename $f)"; done; echo "$cfg: $n frames byte-equal to base"; done
  metrics="gpu__time_duration.sum,launch__registers_per_thread,sm__warps_active.avg.pct_of_peak_sustained_active,smsp__thread_inst_executed_per_inst_executed.ratio,smsp__inst_executed.sum,l1tex__t_sectors_pipe_lsu_mem_local_op_ld.sum,l1tex__t_sectors_pipe_lsu_mem_global_op_ld.sum"
  timeout 200 ncu --clock-control none --kernel-name regex:"one_ray_per_thread" --launch-skip 60 --launch-count 3 --metrics $metrics \
    glint render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2071:2100 --timings-only $common --shadows rt --deform off --out $R/ncu-frame > $R/ncu-frame.txt 2>&1 || echo "ncu frame rc=$?"
  grep -vE "^==PROF==|^  *-+ " $R/ncu-frame.txt | grep -E "one_ray|duration|registers|warps_active|ratio|inst_executed.sum|sectors" | sed 's/(T1, TraceLaunch).*//' | head -40
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
# i: what the two-level structure costs against one flat BVH over the same triangles: the frame's
# closest-hit kernel (rt reflections, cube shadows, so trace_ms is that kernel alone) against
# accel-bench's flat BVH on the same frames' mirror rays, one binary; per frame and over four frames.
if [ "$STEP" = i ]; then
  for accel in sah lbvh; do
  for f in 1800 2100 2300 4400; do
    for be in cuda gl; do
      timeout 60 glint render atrium --backend $be --reflections rt --width 1280 --height 720 --frames $((f-20)):$f --timings-only \
        --gbuffer visibility --primary compute --accel $accel --shadows cube --deform off --out $R/tl-$accel-$be-$f > $R/tl.log 2>&1 || echo "two-level $be $f failed"
      awk -F, -v be=$be -v f=$f -v a=$accel 'NR>11 {t+=$14; r+=$18; n++} END {printf "two-level %s %s frames %d-%d: mean rays %.0f, closest-hit trace %.4f ms, %.0f Mrays/s\n", a, be, f-9, f, r/n, t/n, r/t/1000}' $R/tl-$accel-$be-$f/timings.csv | tee -a $R/overlap.txt
    done
    timeout 200 glint accel-bench atrium --builders cuda-$accel --rays reflection --frames $f --width 1280 --height 720 --deform-frames 0 --build-runs 1 > $R/ab-$accel-$f.txt 2>&1
    echo "flat $accel frame $f: $(grep -E '^(scene|cuda-)' $R/ab-$accel-$f.txt | awk '{print $1, $2, $3, $4, $5, $6, $(NF-2)}' | tr '\n' ' ')" | tee -a $R/overlap.txt
  done
  done
  rm -rf $R/tl-*/frame_*.png
fi
# j: why the GLSL walk is twice the CUDA kernel's time: variants through GLINT_SHADER_DIR (timing
# only: no precise, no double fallback, stacks in shared memory), the closest-hit trace alone (rt,
# cube shadows) and the hybrid frame with rt shadows.
if [ "$STEP" = j ]; then
  VARIANTS=${VARIANTS:-"cur noprecise nodouble shared"}
  for rep in 1 2; do
    for v in $VARIANTS; do
      env GLINT_SHADER_DIR=.exp/$v timeout 60 glint render atrium --backend gl --reflections rt --width 1280 --height 720 --frames 2071:2110 --timings-only \
        --gbuffer visibility --primary compute --accel sah --shadows cube --deform off --out $R/c-$v-r$rep > $R/c.log 2>&1 || { echo "closest $v failed"; tail -3 $R/c.log; }
      awk -F, -v v=$v 'NR>11 {t+=$14; r+=$18; n++} END {printf "%s closest-hit: rays %.0f, trace %.4f ms, %.0f Mrays/s\n", v, r/n, t/n, r/t/1000}' $R/c-$v-r$rep/timings.csv
      env GLINT_SHADER_DIR=.exp/$v timeout 60 glint render atrium --backend gl --reflections hybrid --width 1280 --height 720 --frames 2071:2110 --timings-only \
        $common --shadows rt --deform off --out $R/f/gl$v-hybrid-r$rep > $R/c.log 2>&1 || echo "hybrid $v failed"
    done
  done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  rm -rf $R/c-*/frame_*.png $R/f/*/frame_*.png
fi
# k: the whole test suite with the session's final binary.
if [ "$STEP" = k ]; then
  ( cd $R && timeout 560 glint_tests --gtest_brief=1 > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|SKIPPED \]" $R/tests.log | tail -30
fi
# l: the session's final binary against the session's first (base): frames, scopes, images, accel-bench.
if [ "$STEP" = l ]; then
  for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    for cfg in 1280x720:hybrid:cuda:off 1280x720:hybrid:cuda:on 1280x720:rt:cuda:off 1280x720:rt:cuda:on 1280x720:ssr:cuda:off 1280x720:off:cuda:off \
               2560x1440:hybrid:cuda:off 2560x1440:hybrid:cuda:on 1280x720:hybrid:gl:off 1280x720:rt:gl:off 2560x1440:hybrid:gl:off 1280x720:hybrid:gl:on; do
      IFS=: read size mode be deform <<< "$cfg"
      for rep in 1 2; do
        timeout 60 $g render atrium --backend $be --reflections $mode --width ${size%x*} --height ${size#*x} --frames 2071:2110 \
          --timings-only $common --shadows rt --deform $deform --out $R/f/$bin-$be-$size-$mode-deform-$deform-r$rep > $R/f.log 2>&1 || { echo "$bin $cfg failed"; tail -2 $R/f.log; }
      done
    done
    for be in cuda gl; do
      timeout 30 $g render atrium --backend $be --reflections hybrid --width 1280 --height 720 --frames 2071:2110 \
        --timings-only $common --shadows rt --deform off --profile-scopes --out $R/s/$bin-$be > $R/s.log 2>&1 || echo "scopes $bin $be failed"
    done
    for cfg in hybrid:rt:cuda rt:rt:cuda hybrid:cube:cuda hybrid:rt:gl; do IFS=: read mode sh be <<< "$cfg"
      timeout 60 $g render atrium --backend $be --reflections $mode --width 1280 --height 720 --frames 2096:2103 \
        $common --shadows $sh --deform on --out $R/img-$bin-$mode-$sh-$be > $R/img.log 2>&1 || echo "images $bin $cfg failed"
    done
    timeout 300 $g accel-bench atrium --builders cuda-sah,cuda-lbvh,cuda-ploc --rays reflection --width 1280 --height 720 --build-runs 1 > $R/ab-$bin.txt 2>&1 || echo "accel-bench $bin failed"
  done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for d in $R/f/*deform-on*; do echo "$(basename $d): accel_update_ms $(awk -F, 'NR>11 {s+=$13; n++} END {printf "%.4f", s/n}' $d/timings.csv)"; done | sort > $R/update.txt; cat $R/update.txt
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "^\| (scope|gbuffer \||shadow \||shadow/shadow_rays/trace|ssr \||device_trace \||trace \||hit_shade \||hit_shade/hit_shadow_rays/trace|resolve \|)" $R/scopes.md
  for cfg in hybrid-rt-cuda rt-rt-cuda hybrid-cube-cuda hybrid-rt-gl; do n=0; for f in $R/img-base-$cfg/frame_*.png; do cmp -s $f $R/img-new-$cfg/$(basename $f) && n=$((n+1)) || echo "$cfg DIFFERENT $(basename $f): $(glint compare $f $R/img-new-$cfg/$(basename $f) 2>&1 | tail -1)"; done; echo "$cfg: $n frames byte-equal to base"; done
  for bin in base new; do echo "$bin accel-bench:"; grep -E "^(structure|cuda-)" $R/ab-$bin.txt; grep -iE "refit|rebuild" $R/ab-$bin.txt | grep -E "^cuda|^structure" | head; done
  tail -25 $R/ab-new.txt
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
# m: SSR's silhouette term at 0.7 footprints (new) against the session's first binary (base): hybrid
# against rt on the four scenes of issue 21 at 1280x720 with the cuda backend; tests; frames.
if [ "$STEP" = m ]; then
  ( timeout 300 glint_tests --gtest_brief=1 --gtest_filter='*Ssr*:*SSR*:*Hybrid*:GoldenImage*:*FramePipeline*:*DeterministicFrames*:*Adaptive*:*Auto*:*Tile*:*Glossy*' > $R/tests.log 2>&1; echo "tests rc=$?" >> $R/tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|golden" $R/tests.log | tail -10
  for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    mkdir -p $R/$bin/compare
    for scene in atrium atrium-simple sponza scenes/sponza-all-reflective.scene.json; do name=$(basename $scene .scene.json)
      for mode in hybrid rt; do
        timeout 120 $g render $scene --frames 1800,2100,2300,4400 --width 1280 --height 720 --backend cuda --reflections $mode \
          --overwrite --out $R/$bin/$name-$mode > $R/render.log 2>&1 || { echo "$bin $name $mode failed"; tail -2 $R/render.log; }
      done
      for frame in 1800 2100 2300 4400; do f=$(printf 'frame_%05d.png' $frame)
        $g compare $R/$bin/$name-hybrid/$f $R/$bin/$name-rt/$f --json $R/$bin/compare/${name}_${frame}.json > /dev/null 2>&1 || echo "compare $bin $name $frame failed"
      done
    done
    echo "== $bin"; python3 tools/ssr_trust_table.py $R/$bin 2>&1 | tee $R/trust-$bin.md
  done
  for rep in 1 2; do for bin in base new; do g=glint; [ $bin = base ] && g=/tmp/w/glint-base
    timeout 60 $g render atrium --backend cuda --reflections hybrid --width 1280 --height 720 --frames 2071:2110 --timings-only $common --shadows rt \
      --deform off --out $R/f/$bin-cuda-hybrid-r$rep > $R/f.log 2>&1 || echo "frames $bin failed"
  done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for d in $R/f/*; do echo "$(basename $d): rays $(awk -F, 'NR>11 {s+=$18; n++} END {printf "%.0f", s/n}' $d/timings.csv)"; done
  find $R -name "frame_*.png" -delete
fi
