"""Loop integrals of f(z) dz around a circle (10.37)-(10.39), (10.44), by numerical contour
integration: the power z^p (2 pi i a for p = -1, zero otherwise), a Laurent polynomial (2 pi i
c_-1 when the circle encloses the pole, zero when not: Cauchy's theorem), the line source a/z
with its flux and circulation (Figs. 10.9-10.10), and the scan for the one power with a non-zero
loop integral. Results are ``Estimate`` values (value and numerical error). Dimensionless.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import mpmath
import numpy as np

from mechmodel import inputs
from mechmodel.complexfields._quadrature import (
    MONOMIAL_POINTS,
    ComplexArray,
    _contour,
    _float_contour,
)
from mechmodel.typing import Estimate, Real


@dataclass(frozen=True)
class LoopIntegral:
    """A loop integral of f(z) dz counterclockwise around a circle (10.37): ``imag`` counts the
    real source (flux), ``real`` the imaginary source (vorticity, work around the loop)."""

    real: Estimate
    imag: Estimate


def _numeric_parts(value: mpmath.mpc, error: mpmath.mpf) -> LoopIntegral:
    err = float(error)
    return LoopIntegral(Estimate(float(value.real), err), Estimate(float(value.imag), err))


def power_loop_integral(
    power: int,
    strength_re: Real = 1,
    strength_im: Real = 0,
    center_re: Real = 0,
    center_im: Real = 0,
    radius: Real = 1,
) -> LoopIntegral:
    """Loop integral of a (z - c)^p dz around a circle about c (10.39): 2 pi i a for p = -1,
    zero for every other integer power."""
    p = int(power)
    inputs.positive(radius, "radius")
    a = complex(float(strength_re), float(strength_im))
    c = complex(float(center_re), float(center_im))
    if not -MONOMIAL_POINTS // 2 < p + 1 < MONOMIAL_POINTS // 2:
        raise ValueError(
            f"power must be in ({-MONOMIAL_POINTS // 2 - 1}, {MONOMIAL_POINTS // 2 - 1})"
        )
    value, error = _contour(lambda z: a * (z - c) ** p, c, float(radius), MONOMIAL_POINTS)
    return _numeric_parts(value, error)


def laurent_loop_integral(
    terms: Sequence[Sequence[Real]],
    center_re: Real,
    center_im: Real,
    radius: Real,
    points: int = 2**7,
) -> LoopIntegral:
    """Loop integral of f(z) = sum c_k z^k, terms [[re, im, k], ...], around the circle
    |z - c| = radius (10.39), (10.44): 2 pi i c_-1 when the circle encloses the origin, zero
    when it does not (Cauchy's theorem). Trapezoid rule in double precision (numpy); the error
    estimate is the difference from the rule with half the nodes plus a rounding bound. The
    circle must keep clear of the pole at the origin."""
    inputs.positive(radius, "radius")
    c = complex(float(center_re), float(center_im))
    r = float(radius)
    if abs(abs(c) - r) < r / 10:
        raise ValueError("the circle passes too close to the pole at the origin")
    coeffs = [(complex(float(re), float(im)), int(k)) for re, im, k in terms]

    def f(z: ComplexArray) -> ComplexArray:
        return sum((a * z**k for a, k in coeffs), start=np.zeros_like(z))

    value, error = _float_contour(f, c, r, points)
    return LoopIntegral(Estimate(value.real, error), Estimate(value.imag, error))


@dataclass(frozen=True)
class LineSource:
    """A line source of complex strength a (10.38), Figs. 10.9-10.10: field f(z) = a/z, plotted
    f*(z*) = a*/z*, potential phi = a ln z. ``star_numerator_re``/``_im``: the numerator a* of
    f*; ``flux`` = Im of the loop integral (2 pi Re a, the jump of A around the source),
    ``circulation`` = Re of it (-2 pi Im a, the jump of Phi)."""

    star_numerator_re: float
    star_numerator_im: float
    flux: Estimate
    circulation: Estimate


def line_source(strength_re: Real = 1, strength_im: Real = 0) -> LineSource:
    """Field, plot numerator and loop integrals of the line source a = strength_re + i
    strength_im (a = q real: line charge; a = i J: line current, a vortex)."""
    inputs.real(strength_re, "strength_re")
    inputs.real(strength_im, "strength_im")
    a = complex(float(strength_re), float(strength_im))
    loop = power_loop_integral(-1, strength_re, strength_im)
    star = a.conjugate()
    return LineSource(star.real, star.imag, loop.imag, loop.real)


@dataclass(frozen=True)
class LoopPowers:
    """Which powers z^n have a non-zero loop integral around the origin (10.39), (10.44)."""

    powers: tuple[int, ...]
    field_power: int
    m: int  # multipole index of that term, m = n + 1 (the 2^|m|-pole labelling of (10.44))


def nonzero_loop_powers(lowest: int = -6, highest: int = 6) -> LoopPowers:
    """Scan n in [lowest, highest] by numerical contour integration (double precision: only
    zero and non-zero need telling apart)."""
    found = []
    for n in range(int(lowest), int(highest) + 1):
        if not -MONOMIAL_POINTS // 2 < n + 1 < MONOMIAL_POINTS // 2:
            raise ValueError("the scan range must keep |n + 1| below 8")

        def power(z: ComplexArray, n: int = n) -> ComplexArray:
            return z**n

        value, error = _float_contour(power, 0j, 1.0, MONOMIAL_POINTS)
        if abs(value) > 10**3 * error:
            found.append(n)
    if len(found) != 1:
        raise ArithmeticError(f"expected one power with a loop integral, found {found}")
    return LoopPowers(tuple(found), found[0], found[0] + 1)
