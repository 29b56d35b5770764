"""Laurent coefficients and Cauchy's formulas by contour integration (10.44)-(10.45):
a_n = (1/(2 pi i)) loop z^(-n-1) f(z) dz, checked on a test series with known coefficients, and
f^(n)(a) = (n!/(2 pi i)) loop f(z)/(z - a)^(n+1) dz, checked on g(z) = 1/(b - z) whose
derivatives are known in closed form; the kernel and weight powers are found by search.
Results are ``Estimate`` values (value and numerical error). Dimensionless.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cache

import mpmath
import numpy as np

from mechmodel import inputs
from mechmodel.complexfields._common import _integer, _point
from mechmodel.complexfields._quadrature import (
    DIGITS,
    LAURENT_POINTS,
    POINTS,
    ComplexArray,
    _contour,
    _float_contour,
)
from mechmodel.typing import Estimate, Real


def _test_laurent_coefficients(lowest: int, highest: int) -> dict[int, complex]:
    """Known, distinct, generic coefficients c_k of a test Laurent series."""
    return {k: complex(1 / (k - lowest + 1), (k % 3) / 7) for k in range(lowest, highest + 1)}


@dataclass(frozen=True)
class LaurentCoefficientCheck:
    """For a_n = (1/(2 pi i)) loop z^(-n-1) f(z) dz (10.44): ``weight_power`` = -n-1, and
    ``two_pi`` = Im of (loop z^(-n-1) f dz) / a_n for a test series with known a_n (the 2 pi of
    the normalizer 2 pi i; its real part is ``residual``)."""

    index: int
    weight_power: int
    two_pi: Estimate
    residual: Estimate


def laurent_coefficient_check(index: int) -> LaurentCoefficientCheck:
    """Recover a known Laurent coefficient a_index by contour integration (10.44)."""
    n = int(index)
    coeffs = _test_laurent_coefficients(-5, 5)
    if n not in coeffs:
        raise ValueError(f"index must be in [-5, 5], got {n}")

    lowest = min(coeffs)
    ordered = [coeffs[k] for k in sorted(coeffs, reverse=True)]
    weight = -n - 1

    def weighted(z: mpmath.mpc) -> mpmath.mpc:
        total = mpmath.mpc(0)
        for c in ordered:  # Horner: sum c_k z^(k - lowest)
            total = total * z + c
        return total * z ** (lowest + weight)

    value, error = _contour(weighted, 0j, 1.0, LAURENT_POINTS)
    with mpmath.workdps(DIGITS):
        ratio = value / mpmath.mpc(coeffs[n])
        err = float(error / abs(mpmath.mpc(coeffs[n])))
    return LaurentCoefficientCheck(
        n, weight, Estimate(float(ratio.imag), err), Estimate(float(ratio.real), err)
    )


# Cauchy's formulas (10.45) with the test function g(z) = 1/(b - z), analytic inside the
# contour, whose derivatives are known in closed form: g^(n)(a) = n! / (b - a)^(n+1).
_CAUCHY_POLE = 3
_CAUCHY_CENTER = complex(1 / 4, 1 / 8)
_CAUCHY_RADIUS = 1 / 2  # well inside |b - a|: the rule with 32 points is already at 1e-23


def _cauchy_data(order: int, kernel_power: int) -> tuple[mpmath.mpc, mpmath.mpf, mpmath.mpc]:
    """(integral of g/(z-a)^kernel_power dz, its error, g^(order)(a)), at 30 digits."""
    a = _CAUCHY_CENTER

    def integrand(z: mpmath.mpc) -> mpmath.mpc:
        return 1 / ((_CAUCHY_POLE - z) * (z - a) ** kernel_power)

    value, error = _contour(integrand, a, _CAUCHY_RADIUS, POINTS)
    with mpmath.workdps(DIGITS):
        exact = mpmath.factorial(order) / (_CAUCHY_POLE - mpmath.mpc(a)) ** (order + 1)
    return value, error, exact


@dataclass(frozen=True)
class CauchyDerivative:
    """Cauchy's formula f^(n)(a) = (n!/(2 pi i)) loop f(z)/(z-a)^(n+1) dz (10.45), checked
    numerically for a test function: ``two_pi`` = Im(n! I / f^(n)(a)) where I is the loop
    integral, ``numerator`` = Re(2 pi i f^(n)(a) / I) (the n!: 1, 2, 3! = 6 ...),
    ``taylor_numerator`` = Re(a_n n! / f^(n)(a)) with a_n = I/(2 pi i) (the 1 of 1/n!)."""

    order: int
    two_pi: Estimate
    numerator: Estimate
    taylor_numerator: Estimate


def cauchy_derivative(order: int) -> CauchyDerivative:
    """The n-th Cauchy formula by numerical contour integration (10.45a-c)."""
    n = inputs.count(order, "order")
    value, error, exact = _cauchy_data(n, n + 1)
    with mpmath.workdps(DIGITS):
        rel = error / abs(value)
        k = mpmath.factorial(n) * value / exact
        two_pi_i = 2j * mpmath.pi
        numerator = two_pi_i * exact / value
        taylor = (value / two_pi_i) * mpmath.factorial(n) / exact
        return CauchyDerivative(
            n,
            Estimate(float(k.imag), float(abs(k) * rel)),
            Estimate(float(numerator.real), float(abs(numerator) * rel)),
            Estimate(float(taylor.real), float(abs(taylor) * rel)),
        )


@dataclass(frozen=True)
class CauchyKernel:
    """The power p of (z - a)^p in the n-th Cauchy formula, found by trying p = 1, 2, ...;
    ``shift`` = p - n (the "+1" of (z - a)^(n+1))."""

    order: int
    power: int
    shift: int


def cauchy_kernel(order: int) -> CauchyKernel:
    """Search the kernel power p for which (n!/(2 pi i)) loop g/(z-a)^p dz = g^(n)(a)."""
    n = inputs.count(order, "order")
    a = _CAUCHY_CENTER
    exact = math.factorial(n) / (_CAUCHY_POLE - a) ** (n + 1)
    matches = []
    for p in range(1, n + 4):

        def kernel(z: ComplexArray, p: int = p) -> ComplexArray:
            return 1 / ((_CAUCHY_POLE - z) * (z - a) ** p)

        value, error = _float_contour(kernel, a, _CAUCHY_RADIUS, POINTS)
        guess = math.factorial(n) * value / (2j * math.pi)
        if abs(guess - exact) <= 10**3 * error + 10.0**-12 * abs(exact):
            matches.append(p)
    if len(matches) != 1:
        raise ArithmeticError(f"expected one kernel power, found {matches}")
    return CauchyKernel(n, matches[0], matches[0] - n)


@cache
def laurent_weight_power(index: int) -> int:
    """The power p for which (1/(2 pi i)) loop z^p f(z) dz around the origin returns the
    Laurent coefficient a_index of f (10.44): searched over p = -8 ... 8 by contour integration
    (double precision) of a test series with known, distinct coefficients; the one p that
    recovers a_index."""
    n = _integer(index, "index")
    coeffs = _test_laurent_coefficients(-5, 5)
    if n not in coeffs:
        raise ValueError(f"index must be in [-5, 5], got {n}")
    found = []
    for p in range(-8, 9):

        def weighted(z: ComplexArray, p: int = p) -> ComplexArray:
            return sum((c * z ** (k + p) for k, c in coeffs.items()), start=np.zeros_like(z))

        value, error = _float_contour(weighted, 0j, 1.0, LAURENT_POINTS)
        if abs(value / (2j * math.pi) - coeffs[n]) <= 10**3 * error + 10.0**-12:
            found.append(p)
    if len(found) != 1:
        raise ArithmeticError(f"expected one weight power, found {found}")
    return found[0]


def laurent_weight_at(index: int, x: Real, y: Real) -> complex:
    """The weight z^p of f(z) in the loop integral that gives a_index (``laurent_weight_power``),
    at z = x + i y."""
    p = laurent_weight_power(index)
    return _point(x, y) ** p
