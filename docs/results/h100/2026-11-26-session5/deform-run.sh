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
