#!/usr/bin/env python3
"""`mpirun -np N glint bench|render` against one process (docs/scale-out.md), on llvmpipe.

One CTest test per case (cmake/GlintMpi.cmake registers them as Mpi.<case>):
  bench_np2     mpirun -np 2 glint bench --quick: the same cells, rows (timings aside) and images
  bench_np3     -np 3, oversubscribed, every frame-times cell split into ranges of 2 frames
                (GLINT_MPI_PIECE_FRAMES=2): the ranges joined give the same rows
  render_np2    a 12-frame render: byte-identical PNGs (and video, with ffmpeg), the same timings.csv
                and scopes.csv rows
  render_np3    the same with 3 ranks
  failed_rank   -np 3 bench (split) and -np 2 render with rank 1 made to fail
                (GLINT_TEST_MPI_FAIL_RANK=1): reported, and the rest completes with the same results
  interrupted   -np 2 bench sent SIGTERM once its first cell is written: it says it was interrupted
                (no cell called failed, no summary.json) and the same command resumes it to the
                same results as one process; -np 2 bench --time-limit 0 hands out no piece, exits
                with 75 and writes no summary
Exit 77 (skipped) when glint was built without MPI. The one-process runs are made once per binary
and shared by the cases (a lock keeps parallel cases from making them twice).
"""
import csv
import fcntl
import filecmp
import hashlib
import json
import os
import shutil
import signal
import subprocess
import sys
import time

GLINT = os.environ.get("GLINT_CLI", "")
MPIRUN = os.environ.get("GLINT_MPIRUN", "")
WORK = os.environ.get("GLINT_TEST_WORK", "/tmp/glint-mpi-tests")

BENCH = ["bench", "--experiment", "paper", "--quick", "--no-plot"]
RENDER = ["render", "atrium-simple", "--frames", "0:11", "--width", "64", "--height", "36",
          "--shadow-map-size", "64", "--profile-scopes"] + (["--video"] if shutil.which("ffmpeg") else [])


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(command, env=None):
    result = subprocess.run(command, capture_output=True, text=True, env=env, timeout=500)
    if result.returncode != 0:
        fail(f"{' '.join(command)} exited with {result.returncode}:\n{result.stdout}\n{result.stderr}")
    return result


def mpirun_command(ranks, args, out, extra_env=None):
    # As root (containers, CI) Open MPI wants both variables; --oversubscribe lets 3 ranks share 2
    # cores; --bind-to none keeps each rank's threads (llvmpipe, TBB) free to use every core.
    # Containers often forbid the cross-process reads Open MPI uses for large messages on one host
    # (process_vm_readv); copying through shared memory works everywhere.
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_btl_vader_single_copy_mechanism="none", **(extra_env or {}))
    return [MPIRUN, "-np", str(ranks), "--oversubscribe", "--bind-to", "none", GLINT] + args + ["--out", out], env


def mpirun(ranks, args, out, extra_env=None):
    if os.path.exists(out):
        shutil.rmtree(out)
    return run(*mpirun_command(ranks, args, out, extra_env))


def interrupt_after_first_cell(ranks, args, out):
    """Starts the mpirun, sends it SIGTERM (which it passes to every rank) once a cell is finished."""
    if os.path.exists(out):
        shutil.rmtree(out)
    command, env = mpirun_command(ranks, args, out)
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    cells = os.path.join(out, "cells")
    deadline = time.monotonic() + 300
    while process.poll() is None and time.monotonic() < deadline:
        if os.path.isdir(cells) and any(name.endswith(".csv") for name in os.listdir(cells)):
            process.send_signal(signal.SIGTERM)
            break
        time.sleep(0.05)
    stdout, stderr = process.communicate(timeout=300)
    return process.returncode, stdout, stderr


def baseline(name, args):
    """The one-process run of `args`, made once per glint binary."""
    stat = os.stat(GLINT)
    key = hashlib.sha1(f"{GLINT}:{stat.st_mtime_ns}:{stat.st_size}:{name}".encode()).hexdigest()[:12]
    out = os.path.join(WORK, f"one-process-{name}-{key}")
    os.makedirs(WORK, exist_ok=True)
    with open(os.path.join(WORK, f".lock-{name}"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not os.path.exists(out + ".complete"):
            if os.path.exists(out):
                shutil.rmtree(out)
            run([GLINT] + args + ["--out", out])
            open(out + ".complete", "w").close()
    return out


def files_under(folder):
    found = set()
    for root, _, names in os.walk(folder):
        for name in names:
            found.add(os.path.relpath(os.path.join(root, name), folder))
    return found


def rows_without_timings(path):
    """The CSV's rows without the columns that are times or memory (they differ between runs)."""
    with open(path, newline="") as file:
        rows = list(csv.reader(file))
    keep = [i for i, name in enumerate(rows[0]) if not (name.endswith("_ms") or name.endswith("_mb") or name == "ms")]
    return [[row[i] for i in keep] for row in rows]


def same_csv(a, b):
    if rows_without_timings(a) != rows_without_timings(b):
        fail(f"{b}: rows differ from the one-process run's {a}")


def same_bytes(a, b):
    if not filecmp.cmp(a, b, shallow=False):
        fail(f"{b}: not byte-identical to the one-process run's {a}")


def check_bench(one, shared, ranks):
    expected = {f for f in files_under(one) if f.startswith("cells/")}
    got = {f for f in files_under(shared) if f.startswith("cells/")}
    if expected != got:
        fail(f"cells/ holds other files than one process's: missing {sorted(expected - got)}, extra {sorted(got - expected)}")
    for name in sorted(expected):
        if name.endswith(".csv"):
            same_csv(os.path.join(one, name), os.path.join(shared, name))
        elif name.endswith(".png"):
            same_bytes(os.path.join(one, name), os.path.join(shared, name))
    a = json.load(open(os.path.join(one, "summary.json")))
    b = json.load(open(os.path.join(shared, "summary.json")))
    keys = ("id", "status", "reason", "frames")
    for cell_a, cell_b in zip(a["cells"], b["cells"]):
        for key in keys:
            if cell_a.get(key) != cell_b.get(key):
                fail(f"summary.json cell {cell_a['id']}: {key} {cell_b.get(key)!r}, one process {cell_a.get(key)!r}")
    if len(a["cells"]) != len(b["cells"]):
        fail("summary.json: another number of cells")
    if "distribution" in a:
        fail("one process's summary.json has a distribution entry")
    if b.get("distribution", {}).get("ranks") != ranks:
        fail(f"summary.json: distribution.ranks is not {ranks}: {b.get('distribution')}")
    report = open(os.path.join(shared, "report.md")).read()
    if f"Shared over {ranks} MPI ranks" not in report:
        fail("report.md does not say how many ranks shared the run")
    return b


def check_render(one, shared, ranks):
    expected, got = files_under(one), files_under(shared)
    if expected != got:
        fail(f"{shared} holds other files than one process's: missing {sorted(expected - got)}, extra {sorted(got - expected)}")
    for name in sorted(expected):
        if name.endswith(".png") or name.endswith(".mp4"):  # the video is made from the same PNGs, in order
            same_bytes(os.path.join(one, name), os.path.join(shared, name))
    for name in ("timings.csv", "scopes.csv"):
        same_csv(os.path.join(one, name), os.path.join(shared, name))
    a = json.load(open(os.path.join(one, "run.json")))
    b = json.load(open(os.path.join(shared, "run.json")))
    if set(b) - set(a) != {"distribution"} or set(a) - set(b):
        fail(f"run.json keys differ beyond distribution: {sorted(set(a) ^ set(b))}")
    for key in ("frames", "frames_rendered", "scene", "options", "resolution"):
        if a[key] != b[key]:
            fail(f"run.json {key}: {b[key]!r}, one process {a[key]!r}")
    if set(a["mean_per_frame"]) != set(b["mean_per_frame"]):
        fail("run.json mean_per_frame has other columns")
    if b["distribution"]["ranks"] != ranks:
        fail(f"run.json distribution.ranks is not {ranks}")
    return b


def main():
    case = sys.argv[1]
    if not MPIRUN:
        print("SKIP: glint was built without MPI (GLINT_MPI=OFF or no libopenmpi-dev)")
        sys.exit(77)
    if not GLINT:
        fail("GLINT_CLI is not set")
    shared = os.path.join(WORK, case)
    if case in ("bench_np2", "bench_np3"):
        ranks = 2 if case == "bench_np2" else 3
        env = {"GLINT_MPI_PIECE_FRAMES": "2"} if ranks == 3 else {}
        mpirun(ranks, BENCH, shared, env)
        summary = check_bench(baseline("bench", BENCH), shared, ranks)
        if ranks == 3 and summary["distribution"]["split_cells"] == 0:
            fail("GLINT_MPI_PIECE_FRAMES=2 split no cell")
        if os.path.isdir(os.path.join(shared, "cells", "parts")) and os.listdir(os.path.join(shared, "cells", "parts")):
            fail("cells/parts/ still holds ranges of joined cells")
    elif case in ("render_np2", "render_np3"):
        ranks = 2 if case == "render_np2" else 3
        mpirun(ranks, RENDER, shared)
        run_json = check_render(baseline("render", RENDER), shared, ranks)
        if {piece["rank"] for piece in run_json["distribution"]["pieces"]} == {0} and ranks > 1:
            print("note: rank 0 rendered every piece (the others were slow to start)")
    elif case == "failed_rank":
        result = mpirun(3, BENCH, shared + "-bench", {"GLINT_MPI_PIECE_FRAMES": "2", "GLINT_TEST_MPI_FAIL_RANK": "1"})
        if "rank 1" not in result.stderr or "failed" not in result.stderr:
            fail(f"the failed rank is not reported on stderr:\n{result.stderr}")
        summary = check_bench(baseline("bench", BENCH), shared + "-bench", 3)
        ranks = summary["distribution"]["per_rank"]
        if "GLINT_TEST_MPI_FAIL_RANK" not in ranks[1].get("failure", "") or ranks[1]["pieces_done"] != 0:
            fail(f"summary.json does not report rank 1's failure: {ranks[1]}")
        if "made to fail" not in open(os.path.join(shared + "-bench", "report.md")).read():
            fail("report.md does not report rank 1's failure")
        result = mpirun(2, RENDER, shared + "-render", {"GLINT_TEST_MPI_FAIL_RANK": "1"})
        if "rank 1" not in result.stderr:
            fail(f"the failed rank is not reported on stderr:\n{result.stderr}")
        run_json = check_render(baseline("render", RENDER), shared + "-render", 2)
        if "failure" not in run_json["distribution"]["per_rank"][1]:
            fail("run.json does not report rank 1's failure")
    elif case == "interrupted":
        # Long enough cells that the signal lands while most of them are still to run.
        args = BENCH + ["--frames", "12", "--stride", "1"]
        code, _, stderr = interrupt_after_first_cell(2, args, shared)
        if code == 0:
            fail("the interrupted run exited with 0")
        if "interrupted by SIGTERM" not in stderr or "the same command resumes" not in stderr:
            fail(f"the interruption is not reported as one:\n{stderr}")
        if " failed" in stderr:
            fail(f"an interrupted run calls cells failed:\n{stderr}")
        if os.path.exists(os.path.join(shared, "summary.json")):
            fail("the interrupted run wrote summary.json")
        kept = [name for name in os.listdir(os.path.join(shared, "cells")) if name.endswith(".csv")]
        result = run(*mpirun_command(2, args, shared))
        if len(kept) > 0 and "kept from an earlier run" not in result.stdout:
            fail(f"the resumed run kept none of the {len(kept)} finished cells:\n{result.stdout}")
        check_bench(baseline("bench-frames-12", args), shared, 2)
        limited = shared + "-time-limit"
        if os.path.exists(limited):
            shutil.rmtree(limited)
        command, env = mpirun_command(2, args + ["--time-limit", "0"], limited)
        result = subprocess.run(command, capture_output=True, text=True, env=env, timeout=300)
        if result.returncode != 75:
            fail(f"--time-limit 0 under mpirun exited with {result.returncode}, not 75:\n{result.stderr}")
        if "time limit (0) has passed; 0 of" not in result.stderr:
            fail(f"--time-limit 0 under mpirun does not say the limit stopped it:\n{result.stderr}")
        if os.path.exists(os.path.join(limited, "summary.json")):
            fail("the run stopped by its time limit wrote summary.json")
    else:
        fail(f"unknown case {case}")
    print(f"{case}: same results as one process")


if __name__ == "__main__":
    main()
