"""The exponential series e^x = sum_k x^k / k! and the constant e (chapter 10, (10.1)-(10.9)).

Partial sums to precision order o keep the terms k = 0..o (10.6), exact with ``exact=True``
(Fractions) and floats otherwise; e and e^x in mpmath to ``DIGITS`` digits. The coefficients
1/k! of the e-series (10.5a) come from the binomial limit (1 + r t/n)^n (10.4), counted with
Pascal's rule; the series polynomial of e^(r t) and its time rate (10.9) take ``Symbolic``
arguments (a formula claim calls them with sympy symbols). The log potential U = -ln y and its
force 1/y are Fig. 10.1's quarter turn of y = e^x. Pure numbers: no units.
"""

from __future__ import annotations

import cmath
import math
from fractions import Fraction

import mpmath

from mechmodel import inputs
from mechmodel.algebra import polynomial_derivative
from mechmodel.series._common import DIGITS, _mp
from mechmodel.series.binomials import pascal_triangle
from mechmodel.series.phasors import unit_phasor
from mechmodel.typing import Exact, Real, Symbolic


def exp_series_term(x: Real, k: int, *, exact: bool = False) -> Real:
    """The k-th term x^k / k! of the exponential series (10.5b)."""
    inputs.real(x, "x")
    k = inputs.count(k, "k")
    if exact:
        x = Fraction(x)
    return x**k / math.factorial(k)


def exp_partial_sum(x: Real, order: int, *, exact: bool = False) -> Real:
    """Partial sum of e^x to precision order ``order``: sum_{k=0}^{order} x^k / k! (10.6)."""
    order = inputs.count(order, "order")
    return sum(exp_series_term(x, k, exact=exact) for k in range(order + 1))


def euler_number() -> mpmath.mpf:
    """Euler's growth constant e = lim (1 + 1/m)^m (10.1), (10.4), to ``DIGITS`` digits."""
    with mpmath.workdps(DIGITS):
        return +mpmath.e


def exponential(x: Real) -> mpmath.mpf:
    """e^x for a real x, to ``DIGITS`` digits (the function equal to its own slope, (10.1))."""
    inputs.real(x, "x")
    with mpmath.workdps(DIGITS):
        return mpmath.exp(_mp(x))


def exp_pi_multiple(multiple: Real) -> mpmath.mpf:
    """The real pi-exponential e^(multiple * pi), e.g. e^(-pi) of the text after (10.20)."""
    inputs.real(multiple, "multiple")
    with mpmath.workdps(DIGITS):
        return mpmath.exp(_mp(multiple) * mpmath.pi)


def _leading_coefficient(values: list[Fraction]) -> Fraction:
    """Leading coefficient of the polynomial of degree len(values) - 1 through the points
    (j, values[j]), j = 0, 1, ... (Lagrange interpolation, exact)."""
    n = len(values)
    total = Fraction(0)
    for i, y in enumerate(values):
        denominator = 1
        for j in range(n):
            if j != i:
                denominator *= i - j
        total += Fraction(y) / denominator
    return total


def exp_series_coefficient(power: int) -> Fraction:
    """Coefficient of (r t)^k in e^(r t), from the binomial limit (10.4)-(10.5a).

    In (1 + r t/n)^n the term (r t)^k has the coefficient B(n, k) / n^k; as n grows only the
    leading n^k of B(n, k) survives, so the coefficient is the leading coefficient of B(n, k) as a
    polynomial in n ("huge n makes n(n-1) cancel n^2"). The B(n, k) are counted with Pascal's
    rule, not with factorials; the result is the exact Fraction 1/k!.
    """
    k = inputs.count(power, "power")
    triangle = pascal_triangle(k)
    counts = [Fraction(row[k]) if k < len(row) else Fraction(0) for row in triangle]
    return _leading_coefficient(counts)


def inverse_factorial(value: Exact) -> int:
    """The j with j! = value (the smallest such j, so 1 gives 0); ``ValueError`` if none."""
    target = Fraction(value)
    j, f = 0, 1
    while f < target:
        j += 1
        f *= j
    if f != target:
        raise ValueError(f"{value!r} is not a factorial")
    return j


def exp_series_factorial(power: int) -> int:
    """The j of the denominator j! of the (r t)^k term of the e-series (10.5a): the inverse
    factorial of 1 / ``exp_series_coefficient(k)`` (it is k)."""
    k = inputs.count(power, "power")
    return inverse_factorial(1 / exp_series_coefficient(k))


def exp_series_correct_decimals(x: Real, order: int) -> int:
    """Decimal places to which the order-``order`` partial sum of e^x is correct: the largest d
    with |partial sum - e^x| < 10^-d / 2 ("5-figure accuracy" of (10.6))."""
    order = inputs.count(order, "order")
    with mpmath.workdps(DIGITS):
        error = abs(_mp(exp_partial_sum(Fraction(x), order, exact=True)) - exponential(x))
        d = 0
        while error < mpmath.mpf(10) ** (-(d + 1)) / 2:
            d += 1
        return d


def exp_series_additions(order: int) -> int:
    """Additions needed for the order-``order`` partial sum: one fewer than its terms (10.6)."""
    order = inputs.count(order, "order")
    terms = [exp_series_term(1, k, exact=True) for k in range(order + 1)]
    return len(terms) - 1


def exp_series_term_count(order: int) -> int:
    """Number of terms of the order-``order`` partial sum of the e-series: k = 0..order."""
    order = inputs.count(order, "order")
    return len(range(order + 1))


def exp_remainder_bound(x: Real, order: int) -> mpmath.mpf:
    """Lagrange bound on |e^x - partial sum to ``order``|: |x|^(o+1)/(o+1)! e^max(x, 0).

    For x > 0 the next term alone is not a bound (all later terms are positive); the factor
    e^x covers them. For x <= 0 the series alternates and the next term bounds the error.
    """
    order = inputs.count(order, "order")
    inputs.real(x, "x")
    with mpmath.workdps(DIGITS):
        next_term = _mp(abs(x)) ** (order + 1) / math.factorial(order + 1)
        return next_term * (exponential(x) if x > 0 else 1)


def exp_series_polynomial(rate: Symbolic, time: Symbolic, order: int) -> Symbolic:
    """The e-series (10.5a) of e^(r t) cut after its (r t)^``order`` term: sum_k c_k (r t)^k,
    the coefficients c_k those of the binomial limit (``exp_series_coefficient``: counted with
    Pascal's rule, not with factorials). Plain operators: symbols give an expression."""
    order = inputs.count(order, "order")
    x = rate * time
    return sum((exp_series_coefficient(k) * x**k for k in range(order + 1)), 0)


def exp_series_polynomial_rate(rate: Symbolic, time: Symbolic, order: int) -> Symbolic:
    """The time rate d/dt of ``exp_series_polynomial`` (10.9): the power rule (10.8b) applied
    term by term to that polynomial in t, whose coefficients are c_k r^k."""
    order = inputs.count(order, "order")
    coefficients = [exp_series_coefficient(k) * rate**k for k in range(order + 1)]
    return sum((c * time**k for k, c in enumerate(polynomial_derivative(coefficients))), 0)


def exp_to_log_rotation() -> float:
    """The quarter turn that carries the graph of y = e^x onto the log potential U = -ln y
    (Fig. 10.1: "rotate your y = e^x graph by 90 degrees"). Each candidate rotation by j * 90
    degrees is applied to points (x, e^x); the one whose images satisfy Y = -ln X is returned as
    a magnitude in radians (it is clockwise)."""
    quarter = math.pi / 2
    samples = [-1 + j / 4 for j in range(9)]
    for j in (1, -1, 2, 3, -3):
        found = True
        for x in samples:
            z = unit_phasor(j * quarter) * complex(x, math.exp(x))
            if z.real <= 0 or abs(z.imag + math.log(z.real)) > 2**-40:
                found = False
                break
        if found:
            return abs(j) * quarter
    raise ValueError("no quarter turn maps y = e^x onto U = -ln y")


def _log_potential_slope(y: Real) -> mpmath.mpf:
    """dU/dy of U(y) = -ln y by a symmetric difference quotient at high precision."""
    with mpmath.workdps(DIGITS):
        h = mpmath.mpf(10) ** (-(DIGITS // 3))
        yy = _mp(Fraction(y))
        return (-mpmath.log(yy + h) + mpmath.log(yy - h)) / (2 * h)


def log_potential_force(y: Real) -> float:
    """The force F(y) = -dU/dy of the log potential U(y) = -ln y (Fig. 10.1b, c), from the
    slope of U by a difference quotient at high precision (it is 1/y)."""
    inputs.positive(y, "y")
    return float(-_log_potential_slope(y))


def log_potential_normal_angle(y: Real) -> float:
    """Angle (radians) between the hypotenuse of the force triangle (base F(y), altitude 1) and
    the tangent (1, dU/dy) of U = -ln y at y (Fig. 10.1c: "hypotenuse is 90 degrees to U(y)")."""
    inputs.positive(y, "y")
    slope = float(_log_potential_slope(y))
    force = -slope
    hypotenuse = complex(force, 1)  # base F across, altitude 1 up
    tangent = complex(1, slope)
    return abs(cmath.phase(hypotenuse / tangent))
