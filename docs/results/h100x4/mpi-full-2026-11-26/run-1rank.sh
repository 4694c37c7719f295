#!/usr/bin/env bash
# Issue 24: the full 4900-frame paper experiment (--stride 1) with N ranks, resumable across calls:
# a call that finds no folder from an earlier call on this machine starts from the one it carried.
# usage: bash .gpu-run-full.sh N LIMIT_SECONDS [TIMEOUT_SECONDS, default 575]
set -u
N=$1; LIMIT=$2; T=${3:-575}
if [ -n "${PACK_FIRST:-}" ]; then mkdir -p $OUT/prev; fi
R=/tmp/r; mkdir -p $R
if [ ! -x /tmp/w/.gpu/bin/glint ]; then mkdir -p /tmp/w && tar -xJf .gpu.tar.xz -C /tmp/w; fi
source /tmp/w/.gpu/env.sh
[ "$N" = 1 ] || command -v mpirun >/dev/null || { tar -xJkf .gpu-mpi.tar.xz -C / 2>/dev/null; ldconfig; }
O=$R/bench-$N
if [ ! -d $O ] && ls .bench-part/bench-$N.tar.xz.* >/dev/null 2>&1; then
  cat .bench-part/bench-$N.tar.xz.* | tar -xJ -C $R
  echo "resumed from the carried folder: $(ls $O/cells/*.csv 2>/dev/null | wc -l) cells, $(ls $O/cells/parts/*.csv 2>/dev/null | wc -l) ranges"
fi
{ nvidia-smi --query-gpu=index,name,driver_version --format=csv,noheader; date -u; echo "host cores: $(nproc)"; } | tee -a $R/device-$N.txt
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
MPI="mpirun --bind-to none --mca plm_rsh_agent /bin/false --mca btl self,vader --mca pml ob1 -x LD_LIBRARY_PATH -x PATH -x __EGL_VENDOR_LIBRARY_FILENAMES"
G=/tmp/w/.gpu/bin/glint
b="bench --experiment paper --scene atrium --backends cuda,optix --accels lbvh,ploc,sah,trbvh --updates rebuild,refit --no-plot --stride 1"
if [ "$N" = 1 ]; then cmd="$G $b --out $O"; else cmd="$MPI -np $N $G $b --out $O"; fi
s=$(date +%s.%N)
# --time-limit: no cell starts after LIMIT (the cells under way finish: nothing is lost, exit 75);
# the timeout is only a safety net for the call's 10 minutes.
timeout -k 20 -s TERM $T $cmd --time-limit $LIMIT >> $R/bench-$N.log 2>&1; rc=$?
echo "bench $N ranks rc=$rc wall $(awk "BEGIN{print $(date +%s.%N) - $s}") s, ended $(date -u +%H:%M:%S)" | tee -a $R/wall-$N.txt
cat $R/wall-$N.txt
grep -a -v "^\s*$" $R/bench-$N.log | tr '\r' '\n' | grep -a -v "bench \[" | tail -6
echo "cells: $(ls $O/cells/*.csv 2>/dev/null | wc -l), ranges: $(ls $O/cells/parts/*.csv 2>/dev/null | wc -l)"
pack() {  # the report and summary apart (small), the whole folder in pieces under 15 MiB
  tar -C $R -cJf $OUT/report-$1.tar.xz bench-$1/report.md bench-$1/summary.json wall-$1.txt device-$1.txt bench-$1.log 2>/dev/null
  tar -C $R -cf - bench-$1 wall-$1.txt device-$1.txt bench-$1.log | xz -T0 | split -b 15M - $OUT/bench-$1.tar.xz.
}
pack $N
ls -la $OUT
