"""Laws of the series, binomial and phasor models (mechmodel.series): chapter 10.

Floats are compared within 1e-12 of the sum of the magnitudes involved (or of the function's
size); integer and Fraction results must be exact; mpmath results are compared far below their
working precision.
"""

from __future__ import annotations

import cmath
import itertools
import math
from fractions import Fraction

import mpmath
import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from checks.properties.closeness import real
from checks.properties.strategies import (
    binomial_powers,
    compounding_periods,
    phase_angles,
    plane_points,
    rationals,
    series_arguments,
    series_orders,
)
from mechmodel import fields, series
from mechmodel.planar import rotation
from mechmodel.typing import Real

pytestmark = pytest.mark.properties
REL = 1e-12


def _exp_scale(x: float) -> float:
    """Sum of the magnitudes of the e-series terms at x: e^|x| (float rounding scales with it)."""
    return math.exp(abs(x))


def _mp(value: Real) -> mpmath.mpf:
    exact = Fraction(value)  # a Fraction already for the exact partial sums
    return mpmath.mpf(exact.numerator) / exact.denominator


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


# -- compound interest ---------------------------------------------------------------------------


@given(compounding_periods())
@example(1_000_000_000)
def test_compound_interest_halts_just_below_e(m: int) -> None:
    """e/(2m + 2) < e - (1 + 1/m)^m < e/(2m) (10.3); (1 + 1/m)^m shares its first s figures
    with e = 2.71... (its "solid figures", truncated) but not s + 1, leaving a gap below
    10^-(s-1)."""
    figures = series.compound_solid_figures(1, m)
    with mpmath.workdps(series.DIGITS):
        value, e = _mp(series.compound_growth(1, m)), series.euler_number()
        for shared in (figures, figures + 1):  # 2.7182... truncated to so many figures
            same = mpmath.floor(value * 10 ** (shared - 1)) == mpmath.floor(e * 10 ** (shared - 1))
            assert same == (shared == figures)
    assert series.compound_solid_figures(1, m, 1, 3) == figures - 3  # beyond the "2.71"
    assert series.compound_solid_figures(Fraction(1, 2), m, 2) == figures  # r t alone counts
    assert series.compound_solid_figures(3, 1) == 0  # 4 and e^3 = 20.08... share no figure
    with mpmath.workdps(series.DIGITS):
        e = series.euler_number()
        gap = e - _mp(series.compound_growth(1, m))
        assert e / (2 * m + 2) < gap < e / (2 * m)
        assert gap < mpmath.mpf(10) ** (-(figures - 1))


@given(
    rationals(0, 3, 10),
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


@given(
    rationals(0, 3, 10),
    rationals(0, 10, 12),
    rationals(Fraction(1, 100), 10_000, 100),
    st.integers(min_value=1, max_value=24),
)
@example(Fraction(1), Fraction(1), Fraction(1), 2)  # $1 at 100% for a year, twice: $2.25
def test_interest_is_the_principal_times_a_growth_factor_of_r_t(
    rate: Fraction, time: Fraction, principal: Fraction, m: int
) -> None:
    """p(t) = (1 + r t/m)^m p(0) (10.3) is p(0) times a factor that depends on r t alone; one
    period is simple interest (1 + r t) p(0); each of the m periods ends t/m later and
    multiplies by 1 + r t/m; the 40-digit value agrees; the limit is p(0) e^(r t) (10.4),
    above every compounding."""
    grown = series.compound_growth_exact(rate, m, time, principal)
    assert grown == principal * series.compound_growth_exact(rate * time, m)
    assert series.simple_interest(rate, time, principal) == series.compound_growth_exact(
        rate, 1, time, principal
    )
    period = series.compound_period(m, time)
    assert m * period == series.compound_period(m, time, m) == time
    assert series.compound_period(m, time, 2) == 2 * period
    assert m * series.compound_period(m) == 1  # a year by default
    factor = series.compound_factor(rate, m, time)
    assert factor == 1 + rate * period == series.compound_factor(rate * time, m)
    assert factor**m * principal == grown
    as_float = series.compound_factor(float(rate), m, float(time))
    assert math.isclose(as_float, float(factor), rel_tol=REL)
    with mpmath.workdps(series.DIGITS):
        assert abs(series.compound_growth(rate, m, time, principal) - grown) < grown / 10**30
        limit = series.continuous_growth(rate, time, principal)
        exact_limit = _mp(principal) * mpmath.exp(_mp(rate * time))
        assert abs(limit - exact_limit) <= exact_limit * mpmath.mpf(10) ** -35
        assert abs(series.continuous_growth(rate * time) * _mp(principal) - limit) <= (
            exact_limit * mpmath.mpf(10) ** -35
        )
        assert _mp(grown) <= limit


# -- binomials and Pascal's triangle -----------------------------------------------------------


@given(binomial_powers())
@example(0)
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
    assert series.binomial_box_power(n) == n + 1
    if n >= 1:
        above = triangle[n - 1]
        assert all(row[k] == above[k - 1] + above[k] for k in range(1, n))


@given(st.integers(min_value=0, max_value=30), st.integers(min_value=0, max_value=30))
@example(4, 0)  # k = n: all heads, no tails
def test_choosing_p_of_n_leaves_the_q_others(p: int, q: int) -> None:
    """Picking p x's from n = p + q factors (x + y) leaves q y's: B(n, p) = B(n, q) =
    n!/(p! q!) = n(n-1)...(q+1)/p! (after (9)); n! = n (n-1)!; a deck of p x-cards and q
    y-cards has n cards, and n - p of them are y-cards."""
    n = series.card_deck_size(p, q)
    assert n == series.card_deck_size(q, p) == p + q
    assert series.binomial_complement(n, p) == q
    assert series.binomial_complement(n, q) == p
    with pytest.raises(ValueError, match="exceeds"):
        series.binomial_complement(n, n + 1)
    assert series.binomial_pq(p, q) == series.binomial_pq(q, p) == series.binomial(n, p)
    assert series.binomial(n, q) == series.binomial(n, p)
    assert series.binomial(n, -1) == series.binomial(n, n + 1) == 0
    factors = series.falling_factors_pq(p, q)
    assert factors == series.falling_factors(n, p) == sorted(factors, reverse=True)
    assert len(factors) == p
    assert all(f > q for f in factors)
    assert Fraction(math.prod(factors), series.factorial(p)) == series.binomial(n, p)
    assert series.factorial(n + 1) == (n + 1) * series.factorial(n)
    assert series.factorial(0) == 1


@given(st.integers(min_value=-6, max_value=6), st.integers(0, 12), st.integers(0, 12))
def test_integer_powers_obey_the_law_of_exponents(base: int, a: int, b: int) -> None:
    """b^(a + c) = b^a b^c, b^0 = 1, b^1 = b for the repeated products of (9) (2^2 = 4, ...);
    2^n counts the terms of the product of n factors (x + y) (7)-(8)."""
    power = series.integer_power
    assert power(base, a + b) == power(base, a) * power(base, b)
    assert power(base, 0) == 1
    assert power(base, 1) == base
    assert power(2, a) == series.binomial_term_count(a) == sum(series.binomial_expansion(a))


@given(st.integers(min_value=0, max_value=12), st.integers(min_value=0, max_value=12))
@example(3, 3)  # as many derivatives as the power: a constant is left
def test_falling_factorials_of_binomials_and_derivatives(k: int, d: int) -> None:
    """B(n, k) = n(n-1)...(n-k+1)/k! (the expansion after (10.4)); d^d/dt^d t^k = k!/(k-d)!
    t^(k-d), 0 when d > k (10.11); the Maclaurin divisor of c_k is k!."""
    for n in range(k, k + 4):
        product = math.prod(n - r for r in range(k))
        assert Fraction(product, math.factorial(k)) == series.binomial(n, k)
    term = series.derivative_term(k, d)
    if d > k:
        assert (term.factor, term.power) == (0, 0)  # the zero function, 0 t^0
    else:
        assert term.factor == math.factorial(k) // math.factorial(k - d)
        assert term.power == k - d
        assert term.factors == list(range(k - d + 1, k + 1))
    assert series.maclaurin_divisor(k) == math.factorial(k)
    assert math.factorial(series.maclaurin_factorial(k)) == math.factorial(k)
    assert series.inverse_factorial(1) == 0  # the smallest j with j! = 1
    if k >= 2:
        assert series.maclaurin_factorial(k) == series.inverse_factorial(math.factorial(k)) == k
        with pytest.raises(ValueError, match="not a factorial"):
            series.inverse_factorial(math.factorial(k) + 1)
    rule = series.power_rule(k)
    assert (rule.factor, rule.power + rule.drop) == ((k, k) if k else (0, 0))
    if k >= 1:
        assert rule.drop == 1
        assert series.power_rule_drop([k, k + 1]) == 1  # d/dt t^n = n t^(n-1) (10.8)
    if k >= d >= 1:
        assert series.power_rule_drop([k], d) == d
        assert series.power_rule_drop([d, k, k + 5], d) == d


@given(st.integers(min_value=5, max_value=100).map(lambda h: 2 * h), st.data())
def test_gauss_approximates_the_binomial_near_its_peak(n: int, data: st.DataObject) -> None:
    """B(n, n/2 + x)/B(n, n/2) = e^(-2x^2/n) up to log-errors 4x^4/n^3 + 2x^2/n^2."""
    x = data.draw(st.integers(min_value=0, max_value=math.isqrt(n)))
    # the binomial variance n p (1 - p) = n/4 of n fair tosses: c = 1/(2 n/4), from one toss on
    assert series.gaussian_exponent_coefficient(n) == Fraction(2, n)
    assert series.gaussian_exponent_coefficient(1) == 2
    assert series.binomial_gaussian(1, 0) == {"binomial": 1, "gauss": 1}  # the peak
    both = series.binomial_gaussian(n, x)
    error = abs(math.log(both["binomial"]) - math.log(both["gauss"]))
    assert error <= 1.1 * (4 * x**4 / n**3 + 2 * x**2 / n**2) + 1e-12


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


# -- Euler's formula, phasors, complex products -----------------------------------------------


@given(phase_angles(), st.integers(min_value=0, max_value=200))
def test_euler_formula_and_the_powers_of_i(theta: float, k: int) -> None:
    """e^(i theta) summed as a series (10.17) is cos theta + i sin theta, of modulus 1, term by
    term the cosine series plus i times the sine series (10.16); i^k repeats after 4 and
    multiplies exactly; (10.20b) and (10.21) hold at theta and at theta + (k/8) pi, the angle
    given in radians plus a multiple of pi; each derivative of e^(-i w t) multiplies by
    -i w = i^3 w (10.22b); Re psi of psi = e^(-i w t) runs a quarter cycle behind Im psi
    (Fig. 10.5b)."""
    z = series.euler_series(theta, 60)
    w = series.unit_phasor(theta)
    assert abs(z - w) <= REL * _exp_scale(theta)
    # the even terms of (10.17) are the cosine series, the odd ones i times the sine series
    order = k % 24
    parts = complex(
        series.sinusoid_partial_sum("cos", theta, order),
        series.sinusoid_partial_sum("sin", theta, order),
    )
    assert abs(series.euler_series(theta, order) - parts) <= REL * _exp_scale(theta)
    assert math.isclose(abs(w), 1, rel_tol=REL)
    assert series.imaginary_unit_power(k + 4) == series.imaginary_unit_power(k)
    assert series.imaginary_unit_power(k) * series.imaginary_unit_power(
        3
    ) == series.imaginary_unit_power(k + 3)
    assert series.imaginary_unit_period() == 4
    derivative = series.phasor_derivative(k)
    assert derivative.factor == series.imaginary_unit_power(3 * k)
    assert derivative.omega_power == k
    # psi = A e^(-i w t) at w = 2 pi: Re psi runs s of a cycle behind Im psi (Fig. 10.5b)
    lag = series.phasor_quarter_cycle()
    psi = cmath.exp(-2j * math.pi * theta)
    assert abs((psi * cmath.exp(-2j * math.pi * lag)).real - psi.imag) < 1e-12
    assert 0 <= lag < 1
    multiple = k / 8
    phi = theta + multiple * math.pi
    v = series.unit_phasor(theta, multiple)
    assert abs(v - cmath.exp(1j * phi)) < 1e-12
    assert series.unit_phasor() == 1
    assert math.isclose(series.unit_circle_radius(k % 16 + 1), 1, rel_tol=REL)
    assert series.unit_phasor(pi_multiple=multiple) == series.unit_phasor(multiple * math.pi, 0)
    assert series.opposite_phasor_angle(theta) == series.opposite_phasor_angle(theta, 0, -1)
    assert series.opposite_phasor_angle(pi_multiple=multiple) == series.opposite_phasor_angle(
        multiple * math.pi
    )
    assert series.clockwise_angle(pi_multiple=multiple) == series.clockwise_angle(
        multiple * math.pi
    )
    for sign in (-1, 1):
        psi = series.opposite_phasor_angle(theta, exponent_sign=sign)
        assert abs(-series.unit_phasor(sign * psi) - w) < 1e-12
        psi = series.opposite_phasor_angle(theta, multiple, sign)
        assert 0 <= psi <= 2 * math.pi  # [0, 2 pi) up to rounding of a tiny -psi
        assert abs(-series.unit_phasor(sign * psi) - v) < 1e-12
    assert abs(series.unit_phasor(-series.clockwise_angle(theta)) - w) < 1e-12
    clockwise = series.clockwise_angle(theta, multiple)
    assert 0 <= clockwise <= 2 * math.pi
    assert abs(series.unit_phasor(-clockwise) - v) < 1e-12
    r = 1 + k / 10
    a, b = r * math.cos(theta), r * math.sin(theta)
    assert abs(series.phasor_divisor(a, b, theta) - r) < 1e-12 * r
    assert abs(series.phasor_divisor(-a, -b, theta, 1, -1) - r) < 1e-12 * r
    assert abs(series.phasor_divisor(a, -b, theta, -1) - r) < 1e-12 * r
    conjugate = series.unit_phasor(-theta)  # (10.20b): cos and sin from e^(+-i theta)
    assert abs((w + conjugate) / 2 - math.cos(theta)) < 1e-12
    assert abs((w - conjugate) / 2j - math.sin(theta)) < 1e-12


@given(plane_points(), phase_angles(), phase_angles(), st.floats(min_value=0.1, max_value=10))
def test_complex_products_rotate_and_sums_obey_the_cosine_laws(
    point: tuple[float, float], a: float, b: float, r: float
) -> None:
    """e^(i phi)(x + i y) = R_phi (x, y) (10.27): lengths are kept and rotations compose
    (10.26); |z +- z'|^2 = r^2 + r'^2 +- 2 r r' cos(phi - phi') (10.25)."""
    x, y = point
    rx, ry = series.rotate(x, y, a)
    (m11, m12), (m21, m22) = rotation(a)
    scale = abs(x) + abs(y)
    assert math.isclose(rx, m11 * x + m12 * y, abs_tol=REL * scale)
    assert math.isclose(ry, m21 * x + m22 * y, abs_tol=REL * scale)
    assert math.isclose(math.hypot(rx, ry), math.hypot(x, y), abs_tol=REL * scale)
    twice = series.rotate(*series.rotate(x, y, a), b)
    once = series.rotate(x, y, a + b)
    assert math.isclose(twice[0], once[0], abs_tol=1e-11 * scale)
    assert math.isclose(twice[1], once[1], abs_tol=1e-11 * scale)
    z1, z2 = r * series.unit_phasor(a), 1.7 * series.unit_phasor(b)
    base, cross_term = r**2 + 1.7**2, 2 * r * 1.7 * math.cos(a - b)
    assert math.isclose(abs(z1 + z2) ** 2, base + cross_term, abs_tol=1e-12 * base)
    assert math.isclose(abs(z1 - z2) ** 2, base - cross_term, abs_tol=1e-12 * base)


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


@given(st.floats(min_value=-3, max_value=3).map(lambda k: 10.0**k))
def test_the_log_potential_force_is_one_over_y(y: float) -> None:
    """F(y) = -dU/dy of U = -ln y is 1/y (Fig. 10.1c): the force times y is the moment 1, and
    the force halves where y doubles."""
    force = series.log_potential_force(y)
    assert math.isclose(force, 1 / y, rel_tol=1e-15)
    assert math.isclose(series.log_potential_force(2 * y), force / 2, rel_tol=1e-14)


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


@given(rationals(-3, 3, 8), rationals(-3, 3, 8), st.integers(min_value=0, max_value=12))
def test_the_e_series_polynomial_and_its_rate(r: Fraction, t: Fraction, order: int) -> None:
    """The e-series of e^(r t) cut at (r t)^o is the partial sum of (10.6) at x = r t, and its
    time rate is r times the series cut one order lower: d/dt e^(r t) = r e^(r t) (10.9)."""
    polynomial = series.exp_series_polynomial(r, t, order)
    assert polynomial == series.exp_partial_sum(r * t, order, exact=True)
    rate = series.exp_series_polynomial_rate(r, t, order)
    assert rate == (r * series.exp_series_polynomial(r, t, order - 1) if order else 0)


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


@given(st.floats(min_value=0.01, max_value=10), plane_points(), st.integers(0, 12))
def test_each_phasor_derivative_multiplies_by_minus_i_w(
    w: float, point: tuple[float, float], n: int
) -> None:
    """x(t) = x(0) e^(-i w t) has d^n x/dt^n = (-i w)^n x(t) ((10.22)); the second derivative
    is -w^2 x, the Newton-Hooke equation (10.23a)."""
    x = complex(*point)
    expected = (-1j * w) ** n * x
    rate = series.phasor_rate(w, x, n)
    assert isinstance(rate, complex)
    assert cmath.isclose(rate, expected, rel_tol=1e-12, abs_tol=1e-300)
    assert series.phasor_rate(w, x, 2) == -(w**2) * x


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
    rationals(-3, 3, 6),
    rationals(-3, 3, 6),
    binomial_powers().filter(lambda n: n <= 25),
    st.data(),
)
def test_binomial_terms_sum_to_the_power(
    x: Fraction, y: Fraction, n: int, data: st.DataObject
) -> None:
    """All the terms of the binomial series (after (10.4)) add up to (x + y)^n; counted from the
    y^n end they are the terms of (y + x)^n counted from its first; the series of (1 + r t/n)^n
    is the one at x = 1, y = r t/n."""
    assert series.binomial_terms(x, y, n, 0, n) == (x + y) ** n
    a = data.draw(st.integers(0, n))
    b = data.draw(st.integers(a, n))
    assert series.binomial_terms(x, y, n, a, b, end="y") == series.binomial_terms(y, x, n, a, b)
    if a < n:  # the first a + 1 terms and the last n - a terms
        head = series.binomial_terms(x, y, n, 0, a)
        assert head + series.binomial_terms(x, y, n, 0, n - a - 1, "y") == (x + y) ** n
    if n:
        assert series.compound_binomial_terms(x, y, n, n) == (1 + x * y / n) ** n


@given(st.integers(min_value=0, max_value=12), st.integers(min_value=1, max_value=10**6))
def test_the_falling_factorial_grows_like_its_leading_power(k: int, n: int) -> None:
    """n(n-1)...(n-k+1) has the leading term n^k ("huge n makes n(n-1) cancel n^2", after
    (10.4)): for n >= k the ratio of the product to n^k lies between 1 - k(k-1)/(2n) and 1."""
    assert series.falling_factorial_leading_term(n, k) == n**k
    product = math.prod(n - j for j in range(k))
    if n >= k:
        ratio = Fraction(product, int(real(series.falling_factorial_leading_term(n, k))))
        assert 1 - Fraction(k * (k - 1), 2 * n) <= ratio <= 1


@given(st.sampled_from(["sin", "cos"]), rationals(-3, 3, 8), st.integers(min_value=0, max_value=14))
def test_the_sinusoid_coefficients_scale_as_w_to_the_n(kind: str, w: Fraction, n: int) -> None:
    """c_n of sin(w t) or cos(w t) is w^n times the c_n of sin t or cos t (each derivative
    (10.15) brings one w), and the c_n t^n add up to the series (10.16)."""
    coefficient = series.sinusoid_coefficient_in_omega(kind, w, n)
    assert coefficient == series.sinusoid_coefficient(kind, n) * w**n
    t = Fraction(3, 7)
    terms = sum(series.sinusoid_coefficient_in_omega(kind, w, k) * t**k for k in range(n + 1))
    assert terms == series.sinusoid_series(kind, w, t, n)


@given(rationals(-3, 3, 6), rationals(-3, 3, 6), st.integers(min_value=0, max_value=20))
def test_the_multiplication_box_multiplies_by_x_plus_y(x: Fraction, y: Fraction, n: int) -> None:
    """The rows of the multiplication box of (2)-(5) are x (x + y)^n and y (x + y)^n, and
    their sum is (x + y)^(n + 1), exactly."""
    assert series.binomial_box_row(x, y, n, "x") == x * (x + y) ** n
    assert series.binomial_box_row(x, y, n, "y") == y * (x + y) ** n
    assert series.binomial_box_product(x, y, n) == (x + y) ** (n + 1)


@given(plane_points(), phase_angles(), st.floats(min_value=0, max_value=1e3))
def test_the_polar_radius_of_a_phasor(point: tuple[float, float], phi: float, r: float) -> None:
    """The modulus |psi| of (10.19b) is the distance of psi_x + i psi_y from 0 (Pythagoras),
    and A e^(i phi) has modulus A (the polar form of Fig. 10.5)."""
    x, y = point
    assert math.isclose(series.phasor_modulus(x, y), math.hypot(x, y), rel_tol=1e-15)
    z = r * series.unit_phasor(phi)
    assert math.isclose(series.phasor_modulus(z.real, z.imag), r, rel_tol=1e-14, abs_tol=1e-300)


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
