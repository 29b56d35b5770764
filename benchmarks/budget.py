"""Wall-time budget of design section 6, measured cold (a new process each run), median of 5.

Each command runs once untimed first, so Python's bytecode cache (``__pycache__``, where pytest
also keeps its rewritten test modules) is written as on any checkout after its first run. With
``--no-bytecode-cache`` the runs set PYTHONDONTWRITEBYTECODE=1 instead, and every run compiles
the project and rewrites the tests' assertions anew. The machine's speed (the cost of a bare
Hypothesis example) is printed before and after the runs: a shared machine has slow phases.

Run from the project root:  python benchmarks/budget.py [--runs 5] [--book PATH]
                                                        [--skip-pytest] [--no-bytecode-cache]
Not collected by the default pytest run (testpaths = checks).
"""

from __future__ import annotations

import argparse
import math
import os
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def timed(command: list[str], env: dict[str, str], runs: int) -> tuple[float, list[float], int]:
    times = []
    code = 0
    subprocess.run(command, cwd=ROOT, env=env, capture_output=True, check=False)  # warm-up
    for _ in range(runs):
        start = time.perf_counter()
        done = subprocess.run(command, cwd=ROOT, env=env, capture_output=True, check=False)
        times.append(time.perf_counter() - start)
        code = done.returncode
    return statistics.median(times), times, code


def machine_speed() -> float:
    """Milliseconds per example of a bare one-integer Hypothesis property (2,000 examples, best
    of 3), the kind of work that fills most of the test run: printed before and after the
    runs, so that a slow phase of a shared machine shows beside the figures it slowed."""
    from hypothesis import given, settings
    from hypothesis import strategies as st

    @settings(max_examples=2000, database=None, deadline=None, derandomize=True)
    @given(st.integers(0, 10**9))
    def bare(x: int) -> None:
        del x

    best = math.inf
    for _ in range(3):
        start = time.perf_counter()
        bare()
        best = min(best, time.perf_counter() - start)
    return best / 2000 * 1e3


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--book", default=os.environ.get("BANGCHECK_BOOK"))
    parser.add_argument("--skip-pytest", action="store_true")
    parser.add_argument(
        "--no-bytecode-cache", action="store_true", help="run with PYTHONDONTWRITEBYTECODE=1"
    )
    args = parser.parse_args()
    if not args.book:
        sys.exit("give --book PATH or set BANGCHECK_BOOK")
    env = {**os.environ, "BANGCHECK_BOOK": str(Path(args.book).resolve()), "CI": "true"}
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    if args.no_bytecode_cache:
        env["PYTHONDONTWRITEBYTECODE"] = "1"
    print(f"bytecode cache: {'off' if args.no_bytecode_cache else 'on'}; {os.cpu_count()} CPUs")
    print(f"machine speed before: {machine_speed():.3f} ms per bare Hypothesis example")
    # the console script installed beside this interpreter (a version manager's shim on PATH,
    # such as pyenv's, would add its own start-up to every run)
    beside = Path(sys.executable).parent / "bangcheck"
    bangcheck = str(beside) if beside.exists() else shutil.which("bangcheck")
    if not bangcheck:
        sys.exit("bangcheck is not installed")
    cases = {
        "bangcheck claims --json": ([bangcheck, "claims", "--json"], 2.0),
        "bangcheck scan": ([bangcheck, "scan"], 2.0),
        "bangcheck power --json": ([bangcheck, "power", "--json"], 2.0),
        "bangcheck report": ([bangcheck, "report", "--out", "/tmp/bangcheck-budget-report"], 15.0),
    }
    if not args.skip_pytest:
        cases["pytest (ci profile, serial)"] = (
            [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider"],
            30.0,
        )
        cases["pytest -n 2"] = (
            [sys.executable, "-m", "pytest", "-q", "-n", "2", "-p", "no:cacheprovider"],
            20.0,
        )
    print(f"{'command':<30} {'median s':>9} {'budget s':>9}  runs (exit code)")
    for name, (command, budget) in cases.items():
        median, times, code = timed(command, env, args.runs)
        flag = "" if median <= budget else "  OVER BUDGET"
        shown = " ".join(f"{t:.2f}" for t in times)
        print(f"{name:<30} {median:>9.2f} {budget:>9.1f}  {shown} ({code}){flag}")
    print(f"machine speed after: {machine_speed():.3f} ms per bare Hypothesis example")


if __name__ == "__main__":
    main()
