"""Laws of factorials, binomials and Pascal's triangle (mechmodel.series.binomials): chapter 10,
Table 1.

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

from checks.properties.closeness import real
from checks.properties.strategies import binomial_powers, rationals
from mechmodel import series

pytestmark = pytest.mark.properties


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


# -- the formulas of the text, as functions (formula claims, design 2a) --------------------------


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


@given(rationals(-3, 3, 6), rationals(-3, 3, 6), st.integers(min_value=0, max_value=20))
def test_the_multiplication_box_multiplies_by_x_plus_y(x: Fraction, y: Fraction, n: int) -> None:
    """The rows of the multiplication box of (2)-(5) are x (x + y)^n and y (x + y)^n, and
    their sum is (x + y)^(n + 1), exactly."""
    assert series.binomial_box_row(x, y, n, "x") == x * (x + y) ** n
    assert series.binomial_box_row(x, y, n, "y") == y * (x + y) ** n
    assert series.binomial_box_product(x, y, n) == (x + y) ** (n + 1)
