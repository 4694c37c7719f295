#!/bin/bash
# usage: eval.sh NAME [SHADER_DIR]   renders hybrid (with the shader dir) for every scene/frame and compares with rt
export GLINT_ASSETS=/work/shared/assets
N=$1; SD=${2:-}
for sc in atrium atrium-simple sponza /work/main/scenes/sponza-all-reflective.scene.json; do
  tag=$(basename $sc .scene.json)
  for m in rt $N; do
    [ -d out/$m-$tag ] && continue
    mode=hybrid; [ $m = rt ] && mode=rt
    env ${SD:+GLINT_SHADER_DIR=$SD} /work/main/build/glint render $sc --backend cpu --reflections $mode --width 1280 --height 720 --frames 1800,2100,2300,4400 --gbuffer visibility --shadows rt --primary compute --out out/$m-$tag > /dev/null 2>&1 || echo "fail $m $tag"
  done
  for f in 1800 2100 2300 4400; do
    echo "$N $tag $f $(/work/main/build/glint compare out/$N-$tag/frame_0$f.png out/rt-$tag/frame_0$f.png | awk '/buckets/{b=$5} /SSIM/{s=$5} /PSNR/{p=$5} END{print b, s, p}')"
  done
done
