#!/usr/bin/env bash
# CPU machine (llvmpipe) comparison: the binary before issue 19 (ca00c54) against HEAD, atrium 640x360, --backend cpu
set -u
OLD=/tmp/glint-base/build-cpu/glint NEW=/work/main/build/glint
F=2096:2108
for round in 1 2; do
for mode in off ssr hybrid rt; do
  $OLD render atrium --reflections $mode --deform off --width 640 --height 360 --frames $F --timings-only --overwrite --out r$round/old-$mode > /dev/null 2>&1
  $NEW render atrium --reflections $mode --deform off --width 640 --height 360 --frames $F --timings-only --overwrite --shadows cube --gbuffer raster --out r$round/new-paper-$mode > /dev/null 2>&1
  $NEW render atrium --reflections $mode --deform off --width 640 --height 360 --frames $F --timings-only --overwrite --out r$round/new-default-$mode > /dev/null 2>&1
done; done
