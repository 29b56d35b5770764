"""The O(1) bang counter against the bang-by-bang event loop.

A heavy ball of mass ratio 100^k drives a light ball at rest against a wall (the ceiling):
``bangs.bang_count`` (the rotation picture) and ``bangs.ceiling_sequence`` (one collision after
another) must agree; the counts are the first k+1 digits of pi. Prints the counts for
k = 0..8 and, for k = 3, 4, 5, the median times of both and their ratio.

    python benchmarks/bang_counter.py [--runs 5]
"""

from __future__ import annotations

import argparse
import functools
import math
import statistics
import time
from collections.abc import Callable

from mechmodel.bangs import bang_count, ceiling_sequence


def median_time(function: Callable[[], object], runs: int) -> float:
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def loop_count(mass_ratio: int) -> int:
    """The bangs counted by the event loop, one collision after another."""
    return ceiling_sequence(mass_ratio, 1, 1, 0).count


def fast_count(mass_ratio: int) -> int:
    """The bangs counted by the O(1) counter."""
    return bang_count(mass_ratio, 1, 1, 0).total


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    digits = str(math.pi).replace(".", "")
    bang_count(1, 1, 1, 0)  # import mpmath once, outside the timings
    print("k  mass ratio      bangs (O(1) counter)  pi digits")
    for k in range(9):
        count = bang_count(100**k, 1, 1, 0).total
        print(f"{k}  100^{k:<10} {count:>22,}  {'ok' if str(count) == digits[: k + 1] else 'NO'}")
    print("\nk  event loop (s)  counter (s)    ratio")
    for k in (3, 4, 5):
        loop = median_time(functools.partial(loop_count, 100**k), args.runs)
        fast = median_time(functools.partial(fast_count, 100**k), args.runs)
        same = loop_count(100**k) == fast_count(100**k)
        verdict = "agree" if same else "DIFFER"
        print(f"{k}  {loop:>14.4f}  {fast:>11.2e}  {loop / fast:>8.0f}  {verdict}")


if __name__ == "__main__":
    main()
