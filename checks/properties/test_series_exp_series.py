"""Laws of the exponential series (mechmodel.series.exp_series): chapter 10, (10.1),
(10.4)-(10.6), (10.9).

Floats are compared within 1e-12 of the sum of the magnitudes involved (or of the function's
size); integer and Fraction results must be exact; mpmath results are compared far below their
working precision.
"""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from checks.properties._series_helpers import _exp_scale, _mp
from checks.properties.strategies import rationals, series_arguments, series_orders
from mechmodel import series

pytestmark = pytest.mark.properties
REL = 1e-12


# -- the exponential series ------------------------------------------------------------------


@given(series_arguments(), series_orders())
@example(1.0, 8)  # the nine terms of (10.6)
def test_exp_partial_sum_lies_within_its_taylor_remainder_bound(x: float, order: int) -> None:
    """|e^x - S_o(x)| <= |x|^(o+1)/(o+1)! e^max(x, 0) (Lagrange's remainder of (10.5)); for
    x > 0 every omitted term is positive, so the next term alone is never a bound; for
    -(o + 2) < x < 0 the omitted terms alternate and shrink, and the bound is nearly attained."""
    error = abs(series.exp_partial_sum(x, order) - math.exp(x))
    bound = float(series.exp_remainder_bound(x, order))
    assert error <= bound * (1 + REL) + REL * _exp_scale(x)
    exact = Fraction(x)
    with mpmath.workdps(200):  # the error can be as small as 1e-96: work far below it
        gap = mpmath.exp(_mp(exact)) - _mp(series.exp_partial_sum(exact, order, exact=True))
        following = _mp(series.exp_series_term(exact, order + 1, exact=True))
        if x >= 0.01:
            assert gap >= following
        elif x <= -0.01 and -x < order + 2:
            # alternating terms that shrink by |x|/(k+1): the first omitted term nearly is
            # the error, and it is the bound
            assert abs(gap) >= abs(following) * (1 - abs(exact) / (order + 2))
            assert abs(gap) >= _mp(Fraction(bound)) * (1 - abs(exact) / (order + 2)) * (1 - REL)


@given(st.integers(min_value=1, max_value=20))
def test_binomial_limit_gives_the_e_series_and_its_derivative(k: int) -> None:
    """lim B(n, k)/n^k = 1/k! (10.4)-(10.5a); d/dt of r^k t^k/k! is r times the (k-1)-th term
    (10.9)."""
    assert series.exp_series_coefficient(k) == Fraction(1, math.factorial(k))
    assert series.exp_series_coefficient(0) == 1
    if k >= 2:
        assert series.exp_series_factorial(k) == k
    # the power rule's k cancels against k!: k c_k = c_(k-1), the (k-1)-th term (10.9)
    assert k * series.exp_series_coefficient(k) == series.exp_series_coefficient(k - 1)


@given(rationals(Fraction(1, 2), 3, 8), st.booleans(), st.integers(min_value=0, max_value=12))
@example(Fraction(1), True, 8)  # nine terms give 5-figure accuracy (10.6)
def test_the_e_series_is_correct_to_its_counted_decimals(
    size: Fraction, positive: bool, order: int
) -> None:
    """The order-o partial sum of (10.5) has o + 1 terms and takes o additions (10.6); it is
    correct to d decimals: its error is below half a unit of the d-th decimal and not below
    half a unit of the next (d = 0 when even the units are off)."""
    x = size if positive else -size
    d = series.exp_series_correct_decimals(x, order)
    with mpmath.workdps(2 * series.DIGITS):
        partial = _mp(series.exp_partial_sum(x, order, exact=True))
        error = abs(partial - mpmath.exp(_mp(x)))
        half_unit = mpmath.mpf(10) ** -d / 2
        assert error < half_unit or d == 0  # an error of 1/2 or more: no decimal is right
        assert half_unit <= 10 * error
    assert series.exp_series_term_count(order) == order + 1
    assert series.exp_series_additions(order) == order


@given(rationals(-20, 20, 12), rationals(-20, 20, 12))
def test_the_exponential_turns_sums_into_products(a: Fraction, b: Fraction) -> None:
    """e^(a + b) = e^a e^b, the growth law of e^x (10.1); e^(k pi) (the e^(-pi) after
    (10.20)) is e^x at x = k pi."""
    with mpmath.workdps(series.DIGITS):
        both = series.exponential(a + b)
        assert abs(both - series.exponential(a) * series.exponential(b)) <= both * 1e-35
        power = series.exp_pi_multiple(a)
        assert abs(power - mpmath.exp(_mp(a) * mpmath.pi)) <= power * 1e-35
        assert abs(power * series.exp_pi_multiple(b) - series.exp_pi_multiple(a + b)) <= (
            series.exp_pi_multiple(a + b) * 1e-35
        )


@given(st.floats(min_value=-3, max_value=3).map(lambda k: 10.0**k))
@example(1e-3)
def test_the_log_potential_pushes_with_force_one_over_y(y: float) -> None:
    """The e^x graph turned a quarter turn clockwise is U(y) = -ln y (Fig. 10.1), whose force
    F = -dU/dy = 1/y has y F(y) = 1; the triangle of base F and unit altitude has its
    hypotenuse normal to the curve (Fig. 10.1c)."""
    assert series.exp_to_log_rotation() == math.pi / 2
    assert math.isclose(series.log_potential_normal_angle(y), math.pi / 2, rel_tol=1e-15)


# -- the formulas of the text, as functions (formula claims, design 2a) --------------------------


@given(st.floats(min_value=-3, max_value=3).map(lambda k: 10.0**k))
def test_the_log_potential_force_is_one_over_y(y: float) -> None:
    """F(y) = -dU/dy of U = -ln y is 1/y (Fig. 10.1c): the force times y is the moment 1, and
    the force halves where y doubles."""
    force = series.log_potential_force(y)
    assert math.isclose(force, 1 / y, rel_tol=1e-15)
    assert math.isclose(series.log_potential_force(2 * y), force / 2, rel_tol=1e-14)


@given(rationals(-3, 3, 8), rationals(-3, 3, 8), st.integers(min_value=0, max_value=12))
def test_the_e_series_polynomial_and_its_rate(r: Fraction, t: Fraction, order: int) -> None:
    """The e-series of e^(r t) cut at (r t)^o is the partial sum of (10.6) at x = r t, and its
    time rate is r times the series cut one order lower: d/dt e^(r t) = r e^(r t) (10.9)."""
    polynomial = series.exp_series_polynomial(r, t, order)
    assert polynomial == series.exp_partial_sum(r * t, order, exact=True)
    rate = series.exp_series_polynomial_rate(r, t, order)
    assert rate == (r * series.exp_series_polynomial(r, t, order - 1) if order else 0)
