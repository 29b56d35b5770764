"""The sine and cosine series (chapter 10, (10.13)-(10.16), Fig. 10.4).

sin(w t) and cos(w t) are differentiated with (10.15) (each step one more factor w, the pattern
repeating after four); their Maclaurin coefficients x^(n)(0)/n! give the series (10.16), whose
partial sums, term counts, Lagrange error bounds and largest error over k oscillations (angles
in radians) are computed here. ``sinusoid_series`` and ``sinusoid_coefficient_in_omega`` take
``Symbolic`` arguments (formula claims call them with sympy symbols).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from typing import cast

from mechmodel import inputs
from mechmodel.series.binomials import factorial
from mechmodel.series.derivatives import maclaurin_divisor
from mechmodel.typing import Real, Symbolic

_SINUSOIDS = ("sin", "cos")


def _kind(kind: str) -> str:
    if kind not in _SINUSOIDS:
        raise ValueError(f"kind must be 'sin' or 'cos', got {kind!r}")
    return kind


@dataclass(frozen=True)
class SinusoidDerivative:
    """d^n/dt^n of sin(w t) or cos(w t) = ``sign`` w^``omega_power`` ``function``(w t), and
    ``value_at_zero``: that derivative at t = 0 for w = 1 (the x(0), v(0), a(0)... of (10.16))."""

    sign: int
    omega_power: int
    function: str
    value_at_zero: int


def sinusoid_derivative(kind: str, order: int) -> SinusoidDerivative:
    """Differentiate sin or cos ``order`` times with (10.15): d/dt sin w t = w cos w t,
    d/dt cos w t = -w sin w t (each step one more factor w)."""
    function = _kind(kind)
    n = inputs.count(order, "order")
    sign, power = 1, 0
    for _ in range(n):
        if function == "sin":
            function = "cos"
        else:
            function, sign = "sin", -sign
        power += 1
    at_zero = sign * (1 if function == "cos" else 0)  # cos 0 = 1, sin 0 = 0
    return SinusoidDerivative(sign, power, function, at_zero)


def sinusoid_coefficient(kind: str, power: int) -> Fraction:
    """Maclaurin coefficient c_n = x^(n)(0)/n! of sin t or cos t (w = 1), (10.12), (10.16)."""
    n = inputs.count(power, "power")
    return Fraction(sinusoid_derivative(kind, n).value_at_zero, factorial(n))


def sinusoid_derivative_period(kind: str) -> int:
    """Number of derivatives after which sin or cos repeats: (10.16)'s repeat-after-4 pattern."""
    start = sinusoid_derivative(kind, 0)
    n = 1
    while True:
        d = sinusoid_derivative(kind, n)
        if (d.sign, d.function) == (start.sign, start.function):
            return n
        n += 1


def sinusoid_series_factors(kind: str) -> list[int]:
    """The factors x^(n)(0) of the (w t)^n/n! terms over one period: 0, 1, 0, -1 for sine."""
    return [
        sinusoid_derivative(kind, n).value_at_zero for n in range(sinusoid_derivative_period(kind))
    ]


def sinusoid_powers(kind: str, count: int) -> list[int]:
    """The first ``count`` powers p with a nonzero coefficient: odd for sine, even for cosine."""
    count = inputs.count(count, "count")
    out: list[int] = []
    p = 0
    while len(out) < count:
        if sinusoid_derivative(kind, p).value_at_zero != 0:
            out.append(p)
        p += 1
    return out


def sinusoid_term_count(kind: str, order: int) -> int:
    """Number of nonzero terms of the sine or cosine series up to power ``order``."""
    order = inputs.count(order, "order")
    return sum(1 for p in range(order + 1) if sinusoid_derivative(kind, p).value_at_zero)


@dataclass(frozen=True)
class TermCountFormula:
    """Number of terms n = (o + ``offset``)/``divisor`` for the orders o that end on a term."""

    offset: int
    divisor: int


def sinusoid_term_count_formula(kind: str) -> TermCountFormula:
    """Fit n = (o + offset)/divisor to the counted terms of the orders that end on a nonzero
    term ((o+1)/2 for sine, (o+2)/2 for cosine: Fig. 10.4's text)."""
    orders = sinusoid_powers(kind, 3)
    counts = [sinusoid_term_count(kind, o) for o in orders]
    divisor = Fraction(orders[1] - orders[0], counts[1] - counts[0])
    offset = divisor * counts[0] - orders[0]
    for o, n in zip(orders, counts, strict=True):
        if (o + offset) / divisor != n:
            raise ValueError("the term count is not linear in the order")
    return TermCountFormula(int(offset), int(divisor))


def _sinusoid_terms(kind: str, order: int) -> list[tuple[int, int]]:
    """(power, x^(power)(0)) of the nonzero terms up to ``order``."""
    out = []
    for p in range(order + 1):
        c = sinusoid_derivative(kind, p).value_at_zero
        if c:
            out.append((p, c))
    return out


def _sum_terms(terms: list[tuple[int, int]], x: Real) -> Real:
    total: Real = 0
    for p, c in terms:
        total += c * x**p / math.factorial(p)
    return total


def sinusoid_partial_sum(kind: str, x: Real, order: int) -> Real:
    """Partial sum of the sine or cosine series (10.16) up to power ``order`` at x = w t."""
    inputs.real(x, "x")
    order = inputs.count(order, "order")
    return _sum_terms(_sinusoid_terms(kind, order), x)


def sinusoid_coefficient_in_omega(kind: str, omega: Symbolic, power: int) -> Symbolic:
    """Maclaurin coefficient c_n = x^(n)(0)/n! of sin(w t) or cos(w t) as a function of w (the
    list after (10.15)): the n-th derivative of (10.15) at t = 0, sign w^n (cos 0) or 0 (sin 0),
    over the divisor D_n of (10.11). Plain operators: a symbol w gives an expression."""
    n = inputs.count(power, "power")
    d = sinusoid_derivative(kind, n)
    return Fraction(d.value_at_zero, maclaurin_divisor(n)) * omega**d.omega_power


def sinusoid_series(kind: str, omega: Symbolic, t: Symbolic, order: int) -> Symbolic:
    """The sine or cosine series (10.16) of sin(w t) or cos(w t) up to the power ``order``, its
    zero terms included: sum_n x^(n)(0) t^n / D_n with the derivatives x^(n)(0) = sign w^n
    (cos 0) or 0 (sin 0) of (10.15) (``sinusoid_derivative``) and the Maclaurin divisors D_n
    (10.11). Plain operators: symbols give an expression."""
    order = inputs.count(order, "order")
    total: Symbolic = 0
    for n in range(order + 1):
        d = sinusoid_derivative(kind, n)
        total += Fraction(d.value_at_zero, maclaurin_divisor(n)) * omega**d.omega_power * t**n
    return total


def sinusoid_remainder_bound(x: Real, order: int) -> Real:
    """Lagrange bound |x|^(o+1)/(o+1)! on |sin x - partial sum| and |cos x - partial sum|
    (every derivative of sin and cos is at most 1 in size)."""
    inputs.real(x, "x")
    order = inputs.count(order, "order")
    size = cast(Real, abs(x))  # mypy joins abs over the union Real to object
    return size ** (order + 1) / math.factorial(order + 1)


def sinusoid_max_error(
    kind: str, order: int, oscillations: Real = 1, samples: int = 2**10 + 1
) -> float:
    """Largest |partial sum - function| over ``oscillations`` full periods centred on t = 0,
    t in [-pi k, pi k] (on ``samples`` points; the error grows toward the ends)."""
    inputs.positive(oscillations, "oscillations")
    order = inputs.count(order, "order")
    reference = math.sin if _kind(kind) == "sin" else math.cos
    terms = _sinusoid_terms(kind, order)
    half = math.pi * oscillations
    points = [half * (2 * j / (samples - 1) - 1) for j in range(samples)]
    return max(abs(_sum_terms(terms, t) - reference(t)) for t in points)


def sinusoid_min_order(kind: str, tolerance: Real, oscillations: Real = 1) -> int:
    """Lowest order o whose partial sum stays within ``tolerance`` (an absolute error, the
    amplitude being 1) over ``oscillations`` full periods centred on t = 0 (Fig. 10.4)."""
    inputs.positive(tolerance, "tolerance")
    order = 0
    while sinusoid_max_error(kind, order, oscillations) > tolerance:
        order += 1
    # report the order of the last nonzero term used (order o and o+1 may give the same sum)
    while order > 0 and sinusoid_derivative(kind, order).value_at_zero == 0:
        order -= 1
    return order


def sinusoid_min_terms(kind: str, tolerance: Real, oscillations: Real = 1) -> int:
    """Nonzero terms of the lowest-order partial sum within ``tolerance`` (see above)."""
    return sinusoid_term_count(kind, sinusoid_min_order(kind, tolerance, oscillations))
