"""Laws of the power rule, slopes and the Maclaurin series (mechmodel.series.derivatives):
chapter 10, (10.7)-(10.12).

Floats are compared within 1e-12 of the sum of the magnitudes involved (or of the function's
size); integer and Fraction results must be exact; mpmath results are compared far below their
working precision.
"""

from __future__ import annotations

import itertools
import math
from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

from checks.properties.strategies import rationals
from mechmodel import fields, series

pytestmark = pytest.mark.properties


# -- the formulas of the text, as functions (formula claims, design 2a) --------------------------


@given(st.integers(min_value=0, max_value=8), rationals(-5, 5, 6), rationals(1, 3, 6))
def test_the_nth_difference_quotient_of_t_to_the_n_is_n_factorial(
    n: int, t: Fraction, h: Fraction
) -> None:
    """Leibniz's d^n x/dt^n (10.12b) divides the n-th difference by dt^n, its denominator: the
    n-th forward difference of x = t^n over steps h is n! h^n whatever t and h, so the quotient
    is the n-th derivative n! exactly; one dt fewer leaves a factor h."""
    values = [(t + j * h) ** n for j in range(n + 1)]
    for _ in range(n):  # the n-th forward difference
        values = [b - a for a, b in itertools.pairwise(values)]
    (difference,) = values
    assert series.nth_difference_quotient(difference, h, n) == math.factorial(n)
    if n:
        assert series.nth_difference_quotient(difference, h, n - 1) == math.factorial(n) * h
    # the denominator dt^n: the quotient times it gives the difference back
    assert series.leibniz_denominator(h, n) == h**n
    assert series.nth_difference_quotient(difference, h, n) * series.leibniz_denominator(h, n) == (
        difference
    )


@given(rationals(-5, 5, 8), rationals(-2, 2, 8), st.integers(min_value=0, max_value=10))
def test_the_secant_slope_tends_to_the_power_rule(t: Fraction, h: Fraction, n: int) -> None:
    """x(t + dt) - x(t) for x = t^n is the binomial expansion less t^n ((10.7a), (10.8a)); the
    secant slope exceeds the tangent slope n t^(n-1) (10.8b) by the higher terms
    B(n, j) t^(n-j) dt^(j-1), j >= 2, which vanish with dt."""
    assert series.power_increment(t, h, n) == (t + h) ** n - t**n
    assert series.power_derivative(t, n) == (n * t ** (n - 1) if n else 0)
    assert series.power_derivative(t, n, coefficient=h) == h * series.power_derivative(t, n)
    if h:
        higher = sum(
            (math.comb(n, j) * t ** (n - j) * h ** (j - 1) for j in range(2, n + 1)), Fraction(0)
        )
        assert series.secant_slope(t, h, n) - series.power_derivative(t, n) == higher


@given(st.lists(rationals(-9, 9, 6), min_size=0, max_size=9), rationals(-3, 3, 8))
def test_the_maclaurin_series_of_a_polynomial_is_the_polynomial(
    coefficients: list[Fraction], t: Fraction
) -> None:
    """A polynomial sum c_k t^k has the derivatives k! c_k at t = 0 ((10.11)); the Maclaurin
    series (10.12a) built from them gives the polynomial back, exactly."""
    derivatives = [math.factorial(k) * c for k, c in enumerate(coefficients)]
    expected = sum((c * t**k for k, c in enumerate(coefficients)), Fraction(0))
    assert series.maclaurin_polynomial(derivatives, t) == expected


@given(rationals(Fraction(1, 8), 8, 8), rationals(-5, 5, 8), rationals(Fraction(1, 64), 1, 8))
def test_the_parabola_slope_is_x_over_lambda(lam: Fraction, x: Fraction, h: Fraction) -> None:
    """The parabola 2 lambda y = x^2 of Fig. 9.4 has the slope dy/dx = x/lambda (after
    (10.7b)): for a quadratic the centred difference quotient is the slope exactly, for any
    step h."""
    height = fields.parabola_height_for_latus
    slope = series.parabola_slope(lam, x)
    assert slope == (height(lam, x + h) - height(lam, x - h)) / (2 * h)
    assert slope == x / lam


@given(
    st.lists(rationals(-9, 9, 6), min_size=0, max_size=9),
    rationals(-3, 3, 8),
    st.integers(min_value=0, max_value=10),
)
def test_repeated_derivatives_of_a_power_series(
    coefficients: list[Fraction], t: Fraction, d: int
) -> None:
    """d derivatives of sum c_k t^k ((10.11c)-(10.11i)) give sum c_k k!/(k-d)! t^(k-d), term by
    term: each term's general form is the falling factorial k(k-1)...(k-d+1) c_k t^(k-d)."""
    expected = sum(
        (c * math.perm(k, d) * t ** (k - d) for k, c in enumerate(coefficients) if k >= d),
        Fraction(0),
    )
    assert series.polynomial_rate(coefficients, t, d) == expected
    terms = sum(
        (series.power_term_rate(t, k, d, coefficient=c) for k, c in enumerate(coefficients)),
        Fraction(0),
    )
    assert terms == expected
