"""The trapezoid rule on a circle for contour integrals (private to ``mechmodel.complexfields``).

``_contour`` integrates f(z) dz around |z - c| = r with mpmath at ``DIGITS`` digits and
``_float_contour`` in double precision (numpy); each returns (value, error estimate), the error
being the difference from the rule on every other node plus a rounding bound. The rule is
spectrally accurate for functions analytic on an annulus around the circle and exact for
Laurent polynomials of degree below the number of nodes. Dimensionless.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import cache
from typing import TypeAlias

import mpmath
import numpy as np
import numpy.typing as npt

DIGITS = 30
POINTS = 64  # nodes for the Cauchy formulas (a pole 2.75 away from a contour of radius 0.5)
MONOMIAL_POINTS = 16  # exact for z^p with |p + 1| < 8 (the coarse rule has 8 nodes)
LAURENT_POINTS = 32  # exact for the degree range of the test Laurent series of ``cauchy``

# the points of a circle (and a function's values there) as numpy complex arrays
ComplexArray: TypeAlias = npt.NDArray[np.complex128]


@cache
def _unit_nodes(points: int) -> tuple[mpmath.mpc, ...]:
    """The ``points`` roots of unity exp(2 pi i k / points), at the working precision."""
    with mpmath.workdps(DIGITS):
        return tuple(mpmath.expj(2 * mpmath.pi * k / points) for k in range(points))


def _contour(
    func: Callable[[mpmath.mpc], mpmath.mpc], center: complex, radius: float, points: int
) -> tuple[mpmath.mpc, mpmath.mpf]:
    """Trapezoid rule for the integral of func(z) dz around the circle |z - center| = radius,
    with ``points`` nodes and (for the error estimate) with every other one: (value, error
    estimate). Spectrally accurate for
    functions analytic on an annulus around the circle; exact for Laurent polynomials of
    degree below ``points``."""

    with mpmath.workdps(DIGITS):
        c = mpmath.mpc(center)
        terms = [func(c + radius * e) * (1j * radius * e) for e in _unit_nodes(points)]
        fine = mpmath.fsum(terms) * 2 * mpmath.pi / points
        coarse = mpmath.fsum(terms[::2]) * 4 * mpmath.pi / points  # the rule on every other node
        rounding = mpmath.mpf(10) ** (5 - DIGITS) * (1 + abs(fine))
        return fine, abs(fine - coarse) + rounding


def _float_contour(
    func: Callable[[ComplexArray], ComplexArray], center: complex, radius: float, points: int
) -> tuple[complex, float]:
    """The same trapezoid rule in double precision (numpy), for decisions that only need to
    tell zero from non-zero or one power from another: (value, error estimate)."""
    nodes = np.exp(2j * np.pi * np.arange(points) / points)
    weighted = func(center + radius * nodes) * (1j * radius * nodes) * (2 * np.pi / points)
    fine = complex(weighted.sum())
    coarse = 2 * complex(weighted[::2].sum())
    rounding = 4 * points * np.finfo(float).eps * float(np.abs(weighted).sum())
    return fine, float(abs(fine - coarse) + rounding)
