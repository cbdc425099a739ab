#!/usr/bin/python3
"""Ensemble scaling: wall time and efficiency for 1 and 2 OpenMP threads and 1 and 2 MPI ranks on
one study, measured back to back, and a weak-scaling projection to 64 ranks from the measured
per-realisation cost and reduction cost. CSV on stdout (projection rows have kind=projection).

  /usr/bin/python3 bench/engine/bench_scaling.py [STUDY] [--realisations K] [--release BIN] [--mpi BIN]

Projection (weak scaling, K = k P realisations on P ranks of 1 thread): T(P) = k c + r (K / C) + l log2 P,
with c the measured seconds per realisation (1 rank, 1 thread), r the measured reduction seconds per
chunk (gather + pairwise sums on rank 0, from /run/reduce_seconds at 2 ranks), C the chunk size and
l the measured latency of one collective step (2-rank run minus its compute and reduction, halved).
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile
import time

import h5py


def timed(cmd, env):
    t0 = time.perf_counter()
    r = subprocess.run(cmd, capture_output=True, text=True, env=env)
    dt = time.perf_counter() - t0
    if r.returncode != 0:
        sys.exit(f"failed: {' '.join(cmd)}\n{r.stderr}")
    return dt


def main():
    p = argparse.ArgumentParser()
    p.add_argument("study", nargs="?", default="studies/seed002-rig-1ms.ini")
    p.add_argument("--realisations", type=int, default=400)
    p.add_argument("--chunk", type=int, default=16)
    p.add_argument("--release", default="build/release/rollspec")
    p.add_argument("--mpi", default="build/mpi/rollspec")
    a = p.parse_args()
    base = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    sets = ["--set", f"study.realisations={a.realisations}", "--set", f"ensemble.chunk_size={a.chunk}", "--quiet"]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "r.h5")
        runs = [("threads", 1, 1, [a.release, "run", a.study, "--out", out, *sets]),
                ("threads", 1, 2, [a.release, "run", a.study, "--out", out, *sets]),
                ("ranks", 1, 1, ["mpirun", "-np", "1", a.mpi, "run", a.study, "--out", out, *sets]),
                ("ranks", 2, 1, ["mpirun", "-np", "2", "--oversubscribe", a.mpi, "run", a.study, "--out", out, *sets])]
        for kind, ranks, threads, cmd in runs:
            wall = timed(cmd, dict(base, OMP_NUM_THREADS=str(threads)))
            with h5py.File(out) as f:
                reduce_s = float(f["/run/reduce_seconds"][0])
                ens = float(f["/run/wall_seconds"][0])
            rows.append(dict(kind=kind, ranks=ranks, threads=threads, wall=wall, ensemble=ens, reduce=reduce_s))
    c = rows[0]["ensemble"] / a.realisations
    print("kind,ranks,threads,realisations,wall_seconds,ensemble_seconds,reduce_seconds,efficiency")
    ref = {"threads": rows[0]["ensemble"], "ranks": rows[2]["ensemble"]}
    for r in rows:
        eff = ref[r["kind"]] / (r["ensemble"] * r["ranks"] * r["threads"])
        print(f"{r['kind']},{r['ranks']},{r['threads']},{a.realisations},{r['wall']:.4f},{r['ensemble']:.4f},"
              f"{r['reduce']:.6f},{eff:.3f}")
    two = rows[3]
    chunks = math.ceil(a.realisations / a.chunk)
    r_chunk = two["reduce"] / chunks
    latency = max(0.0, (two["ensemble"] - c * a.realisations / 2 - two["reduce"]) / 2)
    k = a.realisations // 2
    for P in (1, 2, 4, 8, 16, 32, 64):
        t = k * c + r_chunk * (k * P / a.chunk) + latency * math.log2(P) if P > 1 else k * c
        print(f"projection,{P},1,{k * P},,{t:.4f},{r_chunk * (k * P / a.chunk):.6f},{k * c / t:.3f}")


sys.dont_write_bytecode = True  # nothing written into the sources
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../python-post"))
from rollspec_post.script_main import script_main  # noqa: E402  (one line per failure, no traceback)


if __name__ == "__main__":
    script_main(main)
