"""Laws of the sine and cosine series (mechmodel.series.sinusoids): chapter 10,
(10.13)-(10.16), Fig. 10.4.

Floats are compared within 1e-12 of the sum of the magnitudes involved (or of the function's
size); integer and Fraction results must be exact; mpmath results are compared far below their
working precision.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from checks.properties._series_helpers import _exp_scale
from checks.properties.strategies import rationals, series_arguments, series_orders
from mechmodel import series

pytestmark = pytest.mark.properties
REL = 1e-12


# -- sine and cosine --------------------------------------------------------------------------


@given(st.sampled_from(["sin", "cos"]), series_arguments(), series_orders())
@example("sin", 0.5, 2)  # the bound is nearly attained when x^(o+1) is the first omitted term
@example("cos", -0.25, 1)
def test_sinusoid_partial_sum_lies_within_its_remainder_bounds(
    kind: str, x: float, order: int
) -> None:
    """|f(x) - S_o(x)| <= |x|^(o+1)/(o+1)! for f = sin, cos (all derivatives are at most 1),
    nearly an equality for |x| <= 1 when x^(o+1) is a term of (10.16); once the order exceeds
    |x| the terms shrink and alternate, and the next nonzero term alone bounds the error."""
    f = math.sin if kind == "sin" else math.cos
    error = abs(series.sinusoid_partial_sum(kind, x, order) - f(x))
    slack = REL * _exp_scale(x)
    bound = series.sinusoid_remainder_bound(x, order)
    assert error <= bound * (1 + REL) + slack
    if series.sinusoid_derivative(kind, order + 1).value_at_zero and abs(x) <= 1:
        # the first omitted term is x^(o+1)/(o+1)! itself, and the next is smaller by
        # x^2/((o+2)(o+3)): the bound is all but attained
        assert error >= bound * (1 - x * x / ((order + 2) * (order + 3))) * (1 - REL) - slack
    if order > abs(x):
        nxt = order + 1
        while series.sinusoid_derivative(kind, nxt).value_at_zero == 0:
            nxt += 1
        assert error <= abs(x) ** nxt / math.factorial(nxt) * (1 + REL) + slack


@given(st.sampled_from(["sin", "cos"]), st.integers(min_value=0, max_value=40))
def test_sinusoid_derivatives_repeat_after_four(kind: str, n: int) -> None:
    """d^(n+4) = d^n (10.16's pattern); d/dt adds one w and turns sin -> cos -> -sin (10.15),
    as a difference quotient confirms; the n-th derivative at 0 is f(n pi/2) (the shift
    d^n/dt^n f(t) = f(t + n pi/2)), giving the Maclaurin coefficients f(n pi/2)/n! (10.12); the
    terms up to order o number floor((o + offset)/divisor), one more at each nonzero power."""
    a, b = series.sinusoid_derivative(kind, n), series.sinusoid_derivative(kind, n + 4)
    assert (a.sign, a.function, a.omega_power + 4) == (b.sign, b.function, b.omega_power)
    assert a.omega_power == n
    f = {"sin": math.sin, "cos": math.cos}
    shifted = f[kind](n * math.pi / 2)
    assert a.value_at_zero == round(shifted)
    assert series.sinusoid_coefficient(kind, n) == Fraction(round(shifted), math.factorial(n))
    first = 1 if kind == "sin" else 0
    assert series.sinusoid_powers(kind, 3) == [first, first + 2, first + 4]
    assert series.sinusoid_series_factors(kind) == [
        round(f[kind](j * math.pi / 2)) for j in range(4)
    ]
    assert series.sinusoid_derivative_period(kind) == 4
    nxt = series.sinusoid_derivative(kind, n + 1)
    t, h = 0.7, 1e-6
    quotient = a.sign * (f[a.function](t + h) - f[a.function](t - h)) / (2 * h)
    assert math.isclose(quotient, nxt.sign * f[nxt.function](t), abs_tol=1e-8)
    formula = series.sinusoid_term_count_formula(kind)
    count = series.sinusoid_term_count(kind, n)
    if a.value_at_zero:
        assert n + formula.offset == formula.divisor * count
    assert count == (n + formula.offset) // formula.divisor
    if n:
        assert count - series.sinusoid_term_count(kind, n - 1) == abs(a.value_at_zero)


@given(st.sampled_from(["sin", "cos"]), st.sampled_from([1.5, 1e-1, 1e-2, 1e-3, 1e-4, 1e-6]))
def test_the_sinusoid_minimum_order_is_the_first_within_the_tolerance(
    kind: str, tolerance: float
) -> None:
    """Over one oscillation, t in [-pi, pi] (Fig. 10.4), the least-order partial sum of (10.16)
    within the tolerance ends on a nonzero term (or is the empty sum 0 of order 0): it is
    within, no lower one is; over k oscillations the error grows to the ends t = +-k pi, below
    the Lagrange bound (k pi)^(o+1)/(o+1)!."""
    order = series.sinusoid_min_order(kind, tolerance)
    error = series.sinusoid_max_error(kind, order)
    assert error <= tolerance
    assert error == series.sinusoid_max_error(kind, order, 1)
    assert order == 0 or series.sinusoid_derivative(kind, order).value_at_zero != 0
    for lower in range(order):  # every lower partial sum: the empty sum 0 and the nonzero terms
        if lower == 0 or series.sinusoid_derivative(kind, lower).value_at_zero:
            assert series.sinusoid_max_error(kind, lower, 1) > tolerance
    assert series.sinusoid_min_terms(kind, tolerance) == series.sinusoid_term_count(kind, order)
    f = math.sin if kind == "sin" else math.cos
    at_end = abs(series.sinusoid_partial_sum(kind, math.pi, order) - f(math.pi))
    assert at_end <= error <= series.sinusoid_remainder_bound(math.pi, order) * (1 + REL)
    if order:
        assert error == at_end  # the largest error is at the ends, t = +-pi
    two = 2 * math.pi  # two oscillations, t in [-2 pi, 2 pi]
    at_end = abs(series.sinusoid_partial_sum(kind, two, order) - f(two))
    error = series.sinusoid_max_error(kind, order, 2)
    assert at_end <= error <= series.sinusoid_remainder_bound(two, order) * (1 + REL)


# -- the formulas of the text, as functions (formula claims, design 2a) --------------------------


@given(
    st.sampled_from(["sin", "cos"]),
    rationals(-3, 3, 8),
    rationals(-3, 3, 8),
    st.integers(min_value=0, max_value=14),
)
def test_the_sinusoid_series_in_w_and_t(kind: str, w: Fraction, t: Fraction, order: int) -> None:
    """The series (10.16) of sin(w t), cos(w t) is the partial sum at x = w t, exactly; it is
    odd in t for the sine, even for the cosine."""
    value = series.sinusoid_series(kind, w, t, order)
    assert value == series.sinusoid_partial_sum(kind, w * t, order)
    assert series.sinusoid_series(kind, w, -t, order) == (-value if kind == "sin" else value)


@given(st.sampled_from(["sin", "cos"]), rationals(-3, 3, 8), st.integers(min_value=0, max_value=14))
def test_the_sinusoid_coefficients_scale_as_w_to_the_n(kind: str, w: Fraction, n: int) -> None:
    """c_n of sin(w t) or cos(w t) is w^n times the c_n of sin t or cos t (each derivative
    (10.15) brings one w), and the c_n t^n add up to the series (10.16)."""
    coefficient = series.sinusoid_coefficient_in_omega(kind, w, n)
    assert coefficient == series.sinusoid_coefficient(kind, n) * w**n
    t = Fraction(3, 7)
    terms = sum(series.sinusoid_coefficient_in_omega(kind, w, k) * t**k for k in range(n + 1))
    assert terms == series.sinusoid_series(kind, w, t, n)
