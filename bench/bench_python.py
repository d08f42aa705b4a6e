#!/usr/bin/env python3
"""Overhead of the Python module against sbanalyze: S(Q) (--compute sq) on the same packing, the
two interleaved in one run, R each (best and median) (bench/RESULTS.md, "Python module").

  Python: wall time of sbpack.StructureFactor(...).compute(packing) (the run's checks, the stage,
          the conversion of the results to numpy), the packing read beforehand;
  CLI:    the results file's runtime_s of `sbanalyze FILE --compute sq --out R.h5` (reading and
          checking the input, the stage, the ensemble; the process start and the writing of the
          file are not in it).
Both report the stage's own runtime_s too.

usage: PYTHONPATH=build/python /usr/bin/python3 bench/bench_python.py [FILE.h5] [--repeat R]
"""
import argparse
import os
import statistics
import subprocess
import tempfile
import time

import sbpack

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def python_run(packing, threads):
    analysis = sbpack.StructureFactor(threads=threads)
    start = time.perf_counter()
    analysis.compute(packing)
    return time.perf_counter() - start, analysis.runtime_s


def cli_run(sbanalyze, path, threads, out):
    subprocess.run([sbanalyze, path, "--compute", "sq", "--threads", str(threads), "--quiet",
                    "--out", out], check=True)
    r = sbpack.read_results(out)
    return r["runtime_s"], r["files"][0]["structure_factor"]["runtime_s"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("packing", nargs="?",
                        default=os.path.join(ROOT, "data", "mrj-spheres-5000.h5"))
    parser.add_argument("--repeat", type=int, default=9)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--sbanalyze", default=os.path.join(ROOT, "build", "analysis",
                                                            "sbanalyze"))
    args = parser.parse_args()
    packing = sbpack.Packing.read(args.packing)
    py, cli = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(args.repeat):
            py.append(python_run(packing, args.threads))
            cli.append(cli_run(args.sbanalyze, args.packing, args.threads,
                               os.path.join(tmp, "r.h5")))
    best_py, best_cli = min(py), min(cli)
    print(f"{args.packing}: N = {len(packing)}, S(Q) up to Q w = 30, {args.threads} threads, "
          f"best of {args.repeat}")
    print(f"  Python compute(): {best_py[0]:.4f} s (stage {best_py[1]:.4f} s)")
    print(f"  sbanalyze run:    {best_cli[0]:.4f} s (stage {best_cli[1]:.4f} s)")
    median_py = statistics.median(t for t, _ in py)
    median_cli = statistics.median(t for t, _ in cli)
    print(f"  ratio Python / CLI: {best_py[0] / best_cli[0]:.3f} (best), "
          f"{median_py / median_cli:.3f} (median: {median_py:.4f} s / {median_cli:.4f} s)")
    print(f"  all Python: {' '.join(f'{t:.4f}' for t, _ in py)}")
    print(f"  all CLI:    {' '.join(f'{t:.4f}' for t, _ in cli)}")


if __name__ == "__main__":
    main()
