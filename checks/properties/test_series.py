"""Laws of the series, binomial and phasor models (mechmodel.series): chapter 10.

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

from checks.properties.strategies import (
    binomial_powers,
    compounding_periods,
    phase_angles,
    plane_points,
    series_arguments,
    series_orders,
)
from mechmodel import series

pytestmark = pytest.mark.properties
REL = 1e-12


def _exp_scale(x: float) -> float:
    """Sum of the magnitudes of the e-series terms at x: e^|x| (float rounding scales with it)."""
    return math.exp(abs(x))


def _mp(value: Fraction) -> mpmath.mpf:
    return mpmath.mpf(value.numerator) / value.denominator


# -- the exponential series ------------------------------------------------------------------


@given(series_arguments(), series_orders())
@example(1.0, 8)  # the nine terms of (10.6)
def test_exp_partial_sum_lies_within_its_taylor_remainder_bound(x: float, order: int) -> None:
    """|e^x - S_o(x)| <= |x|^(o+1)/(o+1)! e^max(x, 0) (Lagrange's remainder of (10.5)); for
    x > 0 every omitted term is positive, so the next term alone is never a bound."""
    error = abs(series.exp_partial_sum(x, order) - math.exp(x))
    bound = float(series.exp_remainder_bound(x, order))
    assert error <= bound * (1 + REL) + REL * _exp_scale(x)
    if x >= 0.01:
        exact = Fraction(x)
        with mpmath.workdps(200):  # the error can be as small as 1e-96: work far below it
            gap = mpmath.exp(_mp(exact)) - _mp(series.exp_partial_sum(exact, order, exact=True))
            assert gap >= _mp(series.exp_series_term(exact, order + 1, exact=True))


@given(st.integers(min_value=1, max_value=20))
def test_binomial_limit_gives_the_e_series_and_its_derivative(k: int) -> None:
    """lim B(n, k)/n^k = 1/k! (10.4)-(10.5a); d/dt of r^k t^k/k! is r times the (k-1)-th term
    (10.9)."""
    assert series.exp_series_coefficient(k) == Fraction(1, math.factorial(k))
    assert series.exp_series_coefficient(0) == 1
    if k >= 2:
        assert series.exp_series_factorial(k) == k
    term = series.exp_series_derivative_term(k)
    assert Fraction(term.numerator, math.factorial(term.factorial)) == Fraction(
        1, math.factorial(term.reduced_factorial)
    )
    assert (term.r_power, term.t_power) == (k, k - 1)


# -- compound interest ---------------------------------------------------------------------------


@given(compounding_periods())
@example(1_000_000_000)
def test_compound_interest_halts_just_below_e(m: int) -> None:
    """e/(2m + 2) < e - (1 + 1/m)^m < e/(2m) (10.3); s solid figures shared with e = 2.71...
    leave a gap below 10^-(s-1)."""
    figures = series.compound_solid_figures(1, m)
    with mpmath.workdps(series.DIGITS):
        e = series.euler_number()
        gap = e - _mp(series.compound_growth(1, m))
        assert e / (2 * m + 2) < gap < e / (2 * m)
        assert gap < mpmath.mpf(10) ** (-(figures - 1))


@given(
    st.fractions(min_value=0, max_value=3, max_denominator=10),
    st.integers(min_value=1, max_value=24),
    st.integers(min_value=1, max_value=24),
)
def test_compounding_more_often_pays_more(rate: Fraction, m: int, extra: int) -> None:
    """(1 + r/m)^m grows with m and stays below e^r; mpmath and exact Fractions agree."""
    low = series.compound_growth_exact(rate, m)
    high = series.compound_growth_exact(rate, m + extra)
    assert low <= high
    assert (low < high) == (rate > 0)
    with mpmath.workdps(series.DIGITS):
        assert _mp(high) <= series.continuous_growth(rate)
        assert abs(series.compound_growth(rate, m) - low) < Fraction(1, 10**30)


# -- binomials and Pascal's triangle -----------------------------------------------------------


@given(binomial_powers())
def test_pascal_rule_builds_the_factorial_binomials(n: int) -> None:
    """Pascal's rule (Table 1) gives B(n, k) = n!/(k!(n-k)!), symmetric, summing to 2^n (8);
    it is the expansion of (x + y)^n; the row's q - p runs from -n to n."""
    triangle = series.pascal_triangle(n)
    row = triangle[n]
    assert row == [series.binomial(n, k) for k in range(n + 1)]
    assert row == row[::-1]
    assert sum(row) == 2**n == series.binomial_term_count(n) == series.pascal_row_sum(n)
    assert row == series.binomial_expansion(n)
    assert series.pascal_row_span(n) == {"min": -n, "max": n}
    assert series.pascal_row_length(n) == n + 1
    if n >= 1:
        above = triangle[n - 1]
        assert all(row[k] == above[k - 1] + above[k] for k in range(1, n))


@given(st.integers(min_value=0, max_value=12), st.integers(min_value=0, max_value=12))
def test_falling_factorials_of_binomials_and_derivatives(k: int, d: int) -> None:
    """B(n, k) = n(n-1)...(n-k+1)/k! (the expansion after (10.4)); d^d/dt^d t^k = k!/(k-d)!
    t^(k-d), 0 when d > k (10.11); the Maclaurin divisor of c_k is k!."""
    poly = series.binomial_polynomial(k)
    assert poly.roots == list(range(k))
    assert poly.offsets == [-r for r in range(k)]
    for n in range(k, k + 4):
        product = math.prod(n - r for r in poly.roots)
        assert Fraction(product, math.factorial(poly.factorial)) == series.binomial(n, k)
    term = series.derivative_term(k, d)
    if d > k:
        assert term.factor == 0
    else:
        assert term.factor == math.factorial(k) // math.factorial(k - d)
        assert term.power == k - d
        assert term.factors == list(range(k - d + 1, k + 1))
    assert series.maclaurin_divisor(k) == math.factorial(k)
    assert series.falling_factorial(d).roots == list(range(d))


@given(st.integers(min_value=5, max_value=100).map(lambda h: 2 * h), st.data())
def test_gauss_approximates_the_binomial_near_its_peak(n: int, data: st.DataObject) -> None:
    """B(n, n/2 + x)/B(n, n/2) = e^(-2x^2/n) up to log-errors 4x^4/n^3 + 2x^2/n^2."""
    x = data.draw(st.integers(min_value=0, max_value=math.isqrt(n)))
    both = series.binomial_gaussian(n, x)
    error = abs(math.log(both["binomial"]) - math.log(both["gauss"]))
    assert error <= 1.1 * (4 * x**4 / n**3 + 2 * x**2 / n**2) + 1e-12


@given(
    st.lists(st.integers(min_value=-50, max_value=50), min_size=1, max_size=8),
    st.integers(min_value=-5, max_value=5),
)
def test_polynomial_derivative_matches_a_difference_quotient(
    coefficients: list[int], t0: int
) -> None:
    """The power-rule derivative (10.8b) is the limit of the difference quotient: exact
    arithmetic, error O(h^2)."""
    t, h = Fraction(t0), Fraction(1, 10**6)

    def x(s: Fraction) -> Fraction:
        return sum((c * s**k for k, c in enumerate(coefficients)), Fraction(0))

    slope = sum(
        (c * t**k for k, c in enumerate(series.polynomial_derivative(coefficients))), Fraction(0)
    )
    quotient = (x(t + h) - x(t - h)) / (2 * h)
    assert abs(quotient - slope) <= sum(abs(c) for c in coefficients) * 6**10 * h * h


# -- sine and cosine --------------------------------------------------------------------------


@given(st.sampled_from(["sin", "cos"]), series_arguments(), series_orders())
@example("sin", 0.5, 2)  # the bound is nearly attained when x^(o+1) is the first omitted term
@example("cos", -0.25, 1)
def test_sinusoid_partial_sum_lies_within_its_remainder_bounds(
    kind: str, x: float, order: int
) -> None:
    """|f(x) - S_o(x)| <= |x|^(o+1)/(o+1)! for f = sin, cos (all derivatives are at most 1);
    once the order exceeds |x| the terms of (10.16) shrink and alternate, and the next nonzero
    term alone bounds the error."""
    f = math.sin if kind == "sin" else math.cos
    error = abs(series.sinusoid_partial_sum(kind, x, order) - f(x))
    slack = REL * _exp_scale(x)
    assert error <= series.sinusoid_remainder_bound(x, order) * (1 + REL) + slack
    if order > abs(x):
        nxt = order + 1
        while series.sinusoid_derivative(kind, nxt).value_at_zero == 0:
            nxt += 1
        assert error <= abs(x) ** nxt / math.factorial(nxt) * (1 + REL) + slack


@given(st.sampled_from(["sin", "cos"]), st.integers(min_value=0, max_value=40))
def test_sinusoid_derivatives_repeat_after_four(kind: str, n: int) -> None:
    """d^(n+4) = d^n (10.16's pattern); d/dt adds one w and turns sin -> cos -> -sin (10.15),
    as a difference quotient confirms; n = (o + offset)/divisor counts the terms."""
    a, b = series.sinusoid_derivative(kind, n), series.sinusoid_derivative(kind, n + 4)
    assert (a.sign, a.function, a.omega_power + 4) == (b.sign, b.function, b.omega_power)
    assert series.sinusoid_derivative_period(kind) == 4
    f = {"sin": math.sin, "cos": math.cos}
    nxt = series.sinusoid_derivative(kind, n + 1)
    t, h = 0.7, 1e-6
    quotient = a.sign * (f[a.function](t + h) - f[a.function](t - h)) / (2 * h)
    assert math.isclose(quotient, nxt.sign * f[nxt.function](t), abs_tol=1e-8)
    formula = series.sinusoid_term_count_formula(kind)
    if a.value_at_zero:
        assert n + formula.offset == formula.divisor * series.sinusoid_term_count(kind, n)


# -- Euler's formula, phasors, complex products -----------------------------------------------


@given(phase_angles(), st.integers(min_value=0, max_value=200))
def test_euler_formula_and_the_powers_of_i(theta: float, k: int) -> None:
    """e^(i theta) summed as a series (10.17) is cos theta + i sin theta, of modulus 1; i^k
    repeats after 4 and multiplies exactly; (10.20b) and (10.21) hold at theta."""
    z = series.euler_series(theta, 60)
    w = series.unit_phasor(theta)
    assert abs(z - w) <= REL * _exp_scale(theta)
    assert math.isclose(abs(w), 1, rel_tol=REL)
    assert series.imaginary_unit_power(k + 4) == series.imaginary_unit_power(k)
    assert series.imaginary_unit_power(k) * series.imaginary_unit_power(
        3
    ) == series.imaginary_unit_power(k + 3)
    assert series.imaginary_unit_period() == 4
    for sign in (-1, 1):
        psi = series.opposite_phasor_angle(theta, exponent_sign=sign)
        assert abs(-series.unit_phasor(sign * psi) - w) < 1e-12
    assert abs(series.unit_phasor(-series.clockwise_angle(theta)) - w) < 1e-12
    if abs(math.sin(theta)) > 0.05 and abs(math.cos(theta)) > 0.05:
        inverse = series.euler_inverse(theta)
        assert abs(inverse.cos_denominator - 2) < 1e-12
        assert abs(inverse.sin_denominator - 2j) < 1e-12


@given(plane_points(), phase_angles(), phase_angles(), st.floats(min_value=0.1, max_value=10))
def test_complex_products_rotate_and_sums_obey_the_cosine_laws(
    point: tuple[float, float], a: float, b: float, r: float
) -> None:
    """e^(i phi)(x + i y) = R_phi (x, y) (10.27): lengths are kept and rotations compose
    (10.26); |z +- z'|^2 = r^2 + r'^2 +- 2 r r' cos(phi - phi') (10.25)."""
    x, y = point
    rx, ry = series.rotate(x, y, a)
    (m11, m12), (m21, m22) = series.rotation_matrix(a)
    scale = abs(x) + abs(y)
    assert math.isclose(rx, m11 * x + m12 * y, abs_tol=REL * scale)
    assert math.isclose(ry, m21 * x + m22 * y, abs_tol=REL * scale)
    assert math.isclose(math.hypot(rx, ry), math.hypot(x, y), abs_tol=REL * scale)
    twice = series.rotate(*series.rotate(x, y, a), b)
    once = series.rotate(x, y, a + b)
    assert math.isclose(twice[0], once[0], abs_tol=1e-11 * scale)
    assert math.isclose(twice[1], once[1], abs_tol=1e-11 * scale)
    if abs(math.cos(a - b)) > 0.1:
        law = series.cosine_law(r, a, 1.7, b)
        assert math.isclose(law.sum_coefficient, 2, rel_tol=1e-9)
        assert math.isclose(law.difference_coefficient, 2, rel_tol=1e-9)


@given(st.floats(min_value=-3, max_value=3), st.sampled_from([1e-2, 1e-4, 1e-6, 1e-9]))
def test_the_minimum_order_is_the_first_within_the_tolerance(x: float, tolerance: float) -> None:
    """exp_min_order gives the least order o whose partial sum (10.5b) is within the tolerance of
    e^x: that order is, and the one before is not."""
    order = series.exp_min_order(x, tolerance)
    target = math.exp(x)
    assert abs(series.exp_partial_sum(x, order) - target) <= tolerance * (1 + 1e-9) + 1e-15
    if order:
        assert abs(series.exp_partial_sum(x, order - 1) - target) > tolerance * (1 - 1e-9)
