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
