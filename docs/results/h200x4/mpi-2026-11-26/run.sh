#!/usr/bin/env bash
# Run 9 of 2026-11-26 (session 2), 4 GPUs: mpirun -np 4 of glint render (images against one process) and
# glint bench --experiment paper at --stride 14 with 1, 2 and 4 ranks (wall time, speed-up).
set -u
R=/tmp/r; rm -rf $R; mkdir -p $R
mkdir -p /tmp/w && tar -xJf .gpu.tar.xz -C /tmp/w && source /tmp/w/.gpu/env.sh
tar -xJkf .gpu-mpi.tar.xz -C / 2>/dev/null; ldconfig
pack() { tar -C /tmp -cJf $OUT/r.tar.xz r; }
trap pack EXIT
{ nvidia-smi --query-gpu=index,name,driver_version --format=csv,noheader; date -u; } > $R/device.txt; cat $R/device.txt
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 NCCL_NVLS_ENABLE=0
MPI="mpirun --bind-to none --mca plm_rsh_agent /bin/false --mca btl self,vader --mca pml ob1 -x LD_LIBRARY_PATH -x PATH -x __EGL_VENDOR_LIBRARY_FILENAMES"
G=/tmp/w/.gpu/bin/glint
# render: 2 ranks against 1 process, 48 frames, PNGs compared byte for byte
r="render atrium --backend cuda --frames 2000:2047 --width 640 --height 360"
( time $G $r --out $R/render-1 ) > $R/render-1.log 2>&1; echo "render 1 rc=$?"
( time $MPI -np 4 $G -v $r --out $R/render-2 ) > $R/render-2.log 2>&1; echo "render 2 rc=$?"; tail -5 $R/render-2.log
n=0; d=0; for f in $R/render-1/frame_*.png; do n=$((n+1)); cmp -s $f $R/render-2/$(basename $f) || d=$((d+1)); done; echo "render: $n frames, $d differ" | tee $R/render-compare.txt
python3 - $R/render-1/timings.csv $R/render-2/timings.csv <<'PY' | tee -a $R/render-compare.txt
import csv, sys
a, b = (list(csv.DictReader(open(f))) for f in sys.argv[1:3])
keys = ["frame", "triangles", "reflective_pixels", "ssr_failed_pixels", "rays_traced"]
same = [tuple(r[k] for k in keys) for r in a] == [tuple(r[k] for k in keys) for r in b]
print(f"timings rows: {len(a)} vs {len(b)}; frame, triangles, reflective, ssr failed, rays equal: {same}")
PY
# bench: the paper's experiment, stride 14, 1 rank then 2 ranks
b="bench --experiment paper --scene atrium --backends cuda,optix --accels lbvh,ploc,sah,trbvh --updates rebuild,refit --no-plot --stride 14"
s=$(date +%s.%N); timeout 280 $G $b --out $R/bench-1 > $R/bench-1.log 2>&1; echo "bench 1 rank rc=$? wall $(awk "BEGIN{print $(date +%s.%N) - $s}") s" | tee -a $R/wall.txt
for n in 2 4; do s=$(date +%s.%N); timeout 200 $MPI -np $n $G $b --out $R/bench-$n > $R/bench-$n.log 2>&1; echo "bench $n ranks rc=$? wall $(awk "BEGIN{print $(date +%s.%N) - $s}") s" | tee -a $R/wall.txt; done
tail -3 $R/bench-4.log; grep -A12 -i "^## Ranks" $R/bench-4/report.md | head -16
rm -rf $R/bench-*/cells/*/ $R/render-*/frame_0200[2-9]*.png $R/render-*/frame_020[1-4]*.png
