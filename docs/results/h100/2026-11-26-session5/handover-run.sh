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
