#!/usr/bin/env bash
# Session 12's GPU calls (H100): --primary auto and the gl backend's GPU update policies. Result files
# are named <step><call>-*. Steps: a (tests, FILTER=), d (the defaults against pinned choices: atrium
# 1280x720, gl and cuda, static and deforming), s (other scenes and 2560x1440 under the defaults), e
# (the SSR march before the inline shadow rays, throwaway binaries), q (the gl SAH kernel, old against
# new), m (the matrix), b (the world bounds cached), c (the whole suite). Calls: 1 11:08 UTC H200 (a, d, s), 2 11:12 H200 (e), 3
# 11:31 H100 (a, q, d, s), 4 11:33 H100 (m gl), 5 11:35 H100 (m cuda), 6 H100 (b, c).
set -u
STEP=$1
R=/tmp/r-$STEP; rm -rf $R; mkdir -p $R
if [ ! -x /tmp/w/.gpu/bin/glint ]; then mkdir -p /tmp/w && tar -xJf .gpu.tar.xz -C /tmp/w; fi
source /tmp/w/.gpu/env.sh
export GLINT_CLI=/tmp/w/.gpu/bin/glint GLINT_SOURCE_DIR=$PWD GLINT_ASSETS=/tmp/w/.gpu/assets PATH=/tmp/w/.gpu/bin:$PATH
pack() { tar -C /tmp -cJf $OUT/r-$STEP.tar.xz r-$STEP; }
trap pack EXIT
{ nvidia-smi --query-gpu=name,driver_version --format=csv,noheader; date -u; } | tee $R/device.txt
# choice DIR: run.json's primary_visibility and the tracer's rebuilds/refits, one line.
choice() { python3 -c "
import json,sys; d=json.load(open(sys.argv[1]+'/run.json')); p=d.get('primary_visibility'); t=d.get('ray_tracer',{})
print(sys.argv[1].split('/')[-1], json.dumps(p), 'update', t.get('update'), 'rebuilds', t.get('rebuilds'), 'refits', t.get('refits'), 'deform_on', d['options'].get('deform_on'))" $1; }
if [ "$STEP" = a ]; then
  ( timeout 540 glint_tests --gtest_brief=1 --gtest_filter="${FILTER:-PrimaryVisibility*:GlRenderer*:RenderPrimaryComputeCli*:ComputeVisibility*:GpuTimer*}" > $R/tests.log 2>&1; echo "tests rc=$?" >> $R/tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|SKIPPED \]" $R/tests.log | tail -30
fi
# d: glint render's defaults (only --backend, the size, frames and --deform given) against the same
# with --primary pinned; gl also with --update refit. Two repetitions, frames 2071-2110.
if [ "$STEP" = d ]; then
  for rep in 1 2; do for be in gl cuda; do for deform in off on; do for p in auto compute raster; do
    [ $p = raster ] && [ $deform = on ] && continue
    out=$R/f/$be-deform-$deform-primary-$p-r$rep
    timeout 120 glint render atrium --backend $be --width 1280 --height 720 --frames 2071:2110 --timings-only \
      --deform $deform $([ $p = auto ] || echo --primary $p) --out $out > $R/f.log 2>&1 || { echo "$out failed"; tail -2 $R/f.log; }
    choice $out
  done; done; done
  for extra in "--update refit" "--update rebuild"; do
    out=$R/f/gl-deform-on-primary-auto-$(echo $extra | tr -d ' -')-r$rep
    timeout 120 glint render atrium --backend gl --width 1280 --height 720 --frames 2071:2110 --timings-only --deform on $extra --out $out > $R/f.log 2>&1 || { echo "$out failed"; tail -2 $R/f.log; }
    choice $out
  done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
fi
# s: other scenes and 2560x1440 under the defaults (deforming), gl and cuda, and the choice each made.
if [ "$STEP" = s ]; then
  for cfg in atrium-simple:1280x720 sponza:1280x720 atrium:2560x1440; do IFS=: read scene size <<< "$cfg"; for be in gl cuda; do
    out=$R/f/$scene-$size-$be
    timeout 120 glint render $scene --backend $be --width ${size%x*} --height ${size#*x} --frames 2071:2110 --timings-only --out $out > $R/f.log 2>&1 || { echo "$out failed"; tail -2 $R/f.log; }
    choice $out
  done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
fi
# e: the SSR march issued before the gl backend's inline shadow rays (throwaway binaries, timing
# only): earlyA keeps the barrier after the march, earlyB drops it (the shadow dispatch may then
# overlap the march; its own barrier covers both). Against the tree's binary; images compared.
if [ "$STEP" = e ]; then
  for v in earlyA earlyB; do [ -x /tmp/w/glint-$v ] || { xz -dc .exp/glint-$v.xz > /tmp/w/glint-$v; chmod +x /tmp/w/glint-$v; }; done
  for rep in 1 2; do for v in tree earlyA earlyB; do g=glint; [ $v = tree ] || g=/tmp/w/glint-$v
    for deform in off on; do
      timeout 90 $g render atrium --backend gl --width 1280 --height 720 --frames 2071:2110 --timings-only \
        --update refit --deform $deform --out $R/f/$v-deform-$deform-r$rep > $R/f.log 2>&1 || { echo "$v failed"; tail -2 $R/f.log; }
    done
  done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for v in tree earlyB; do g=glint; [ $v = tree ] || g=/tmp/w/glint-$v
    timeout 90 $g render atrium --backend gl --width 1280 --height 720 --frames 2096:2103 --update refit --out $R/img-$v > $R/img.log 2>&1 || echo "images $v failed"
  done
  n=0; for f in $R/img-tree/frame_*.png; do cmp -s $f $R/img-earlyB/$(basename $f) && n=$((n+1)); done; echo "earlyB: $n of 8 frames byte-equal to the tree's"
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
# q: the gl SAH cost's kernel, one work group per BLAS (oldsah: the binary of calls 1-2) against two
# dispatches over many groups (the tree), deforming with --update auto and refit; scopes and frames.
if [ "$STEP" = q ]; then
  [ -x /tmp/w/glint-oldsah ] || { xz -dc .exp/glint-oldsah.xz > /tmp/w/glint-oldsah; chmod +x /tmp/w/glint-oldsah; }
  for rep in 1 2; do for v in tree oldsah; do g=glint; [ $v = tree ] || g=/tmp/w/glint-$v
    for up in auto refit; do
      timeout 90 $g render atrium --backend gl --width 1280 --height 720 --frames 2071:2110 --timings-only \
        --update $up --out $R/f/$v-$up-r$rep > $R/f.log 2>&1 || { echo "$v $up failed"; tail -2 $R/f.log; }
    done
  done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for v in tree oldsah; do g=glint; [ $v = tree ] || g=/tmp/w/glint-$v
    timeout 90 $g render atrium --backend gl --width 1280 --height 720 --frames 2071:2110 --timings-only \
      --update auto --profile-scopes --out $R/s/$v-auto > $R/s.log 2>&1 || echo "scopes $v failed"
  done
  python3 tools/scope_table.py $R/s/* > $R/scopes.md 2>&1; grep -E "^\| (scope|deform|accel)" $R/scopes.md
fi
# m: issue 19's matrix under the new defaults (--primary auto, --deform-on gpu for gl), BACKEND=gl|cuda,
# atrium 1280x720 (tools/frame_matrix.sh: every mode, shadow method, G-buffer and update policy).
if [ "$STEP" = m ]; then
  GLINT=glint timeout 560 bash tools/frame_matrix.sh $R/m --backend ${BACKEND:-gl} > $R/m.log 2>&1; echo "matrix rc=$?"
  rm -f $R/m/*/frame_*.png
  python3 tools/frame_table.py $R/m > $R/matrix.md 2>&1; cat $R/matrix.md
fi
# b: the frame's world bounds from cached per-mesh boxes (the tree) against every vertex scanned each
# frame (prebounds: the binary of calls 3-5); frames where the host may pace the loop (off and ssr with
# rt shadows) and the defaults; images compared.
if [ "$STEP" = b ]; then
  [ -x /tmp/w/glint-prebounds ] || { xz -dc .exp/glint-prebounds.xz > /tmp/w/glint-prebounds; chmod +x /tmp/w/glint-prebounds; }
  for rep in 1 2; do for v in tree prebounds; do g=glint; [ $v = tree ] || g=/tmp/w/glint-$v
    for cfg in gl:off:off gl:ssr:off gl:hybrid:off gl:hybrid:on cuda:off:off cuda:hybrid:off cuda:hybrid:on; do IFS=: read be mode deform <<< "$cfg"
      timeout 90 $g render atrium --backend $be --reflections $mode --width 1280 --height 720 --frames 2071:2110 --timings-only \
        --deform $deform --out $R/f/$v-$be-$mode-deform-$deform-r$rep > $R/f.log 2>&1 || { echo "$v $cfg failed"; tail -2 $R/f.log; }
    done
  done; done
  python3 tools/frame_table.py $R/f > $R/frames.md 2>&1; cat $R/frames.md
  for v in tree prebounds; do g=glint; [ $v = tree ] || g=/tmp/w/glint-$v
    timeout 90 $g render atrium --backend gl --width 1280 --height 720 --frames 2096:2103 --out $R/img-$v > $R/img.log 2>&1 || echo "images $v failed"
  done
  n=0; for f in $R/img-tree/frame_*.png; do cmp -s $f $R/img-prebounds/$(basename $f) && n=$((n+1)); done; echo "tree: $n of 8 frames byte-equal to prebounds'"
  rm -rf $R/img-* $R/f/*/frame_*.png
fi
if [ "$STEP" = c ]; then
  ( cd $R && timeout 560 glint_tests --gtest_brief=1 > tests.log 2>&1; echo "tests rc=$?" >> tests.log )
  grep -E "FAILED|PASSED|tests from|rc=|SKIPPED \]" $R/tests.log | tail -30
fi
