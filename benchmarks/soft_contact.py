"""Soft-contact collisions: the integrators compared on the book's cases, for cost and error.

Each case is integrated by ``contact.soft_collision`` with each of its integrators
(``contact.INTEGRATORS``: the Fortran DOP853 through scipy.integrate.ode, and scipy's
event-capable ``solve_ivp`` methods) at the same tolerance. Reported per method: CPU time
(median of the runs, both the fine and the tenfold-looser run that make the error estimate),
the relative energy error at the end, the largest error of the final velocities against the
elastic collision map where that is exact (two balls without a floor: a contact force that
depends on the overlap alone conserves energy and momentum), and their largest difference from
the default method's. The default is the one with the best accuracy per cost.

    python benchmarks/soft_contact.py [--runs 3]
"""

from __future__ import annotations

import argparse
import statistics
import time

from mechmodel.collisions import collide
from mechmodel.contact import INTEGRATORS, soft_collision

# (name, masses, positions, velocities, power, floor): Figs. 7.6-7.7 (a 7:1 pair meeting at
# unit closing speed) and Fig. 8.1(a), (c) (the 100/30/10 tower dropped onto the floor)
CASES = (
    ("7:1 pair, quartic (Fig. 7.6)", [7, 1], [0, 0], [1, 0], 4, False),
    ("7:1 pair, linear (Fig. 7.7)", [7, 1], [0, 0], [1, 0], 1, False),
    ("100/30/10 tower, quartic (Fig. 8.1a)", [100, 30, 10], [0, 0, 0], [-1, -1, -1], 4, True),
    ("100/30/10 tower, linear (Fig. 8.1c)", [100, 30, 10], [0, 0, 0], [-1, -1, -1], 1, True),
)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    soft_collision([1, 1], [0, 0], [1, 0], 2)  # import scipy outside the timings
    print(
        f"{'case':<38} {'method':<10} {'CPU ms':>8} {'energy error':>13} {'vs exact':>9} "
        f"{'vs default':>10}"
    )
    for name, masses, positions, velocities, power, floor in CASES:
        exact = (
            None
            if floor or len(masses) != 2
            else [float(v) for v in collide(*masses, *velocities).after]
        )
        reference = None
        for method in INTEGRATORS:
            times = []
            try:
                for _ in range(args.runs):
                    start = time.process_time()
                    result = soft_collision(
                        masses, positions, velocities, power, floor=floor, method=method
                    )
                    times.append(time.process_time() - start)
            except (ValueError, ArithmeticError) as err:
                print(f"{name:<38} {method:<10} failed: {type(err).__name__}: {err}")
                continue
            finals = [e.value for e in result.velocities]
            if reference is None:
                reference = finals
            gap = max(abs(a - b) for a, b in zip(finals, reference, strict=True))
            error = "" if exact is None else f"{_largest_error(finals, exact):.1e}"
            print(
                f"{name:<38} {method:<10} {1000 * statistics.median(times):>8.1f} "
                f"{result.energy_error:>13.2e} {error:>9} {gap:>10.1e}"
            )


def _largest_error(finals: list[float], exact: list[float]) -> float:
    return max(abs(a - b) for a, b in zip(finals, exact, strict=True))


if __name__ == "__main__":
    main()
