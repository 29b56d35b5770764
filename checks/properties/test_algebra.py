"""Laws of the exact algebra (mechmodel.algebra): Gaussian rationals, Laurent polynomials in
named variables and coefficient lists.

The algebra is exact, so its laws hold with equality; a float evaluation agrees with the exact
one within 1e-12 of the sizes of the terms.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from checks.properties.strategies import (
    fraction_quantities,
    gaussian_integers,
    laurent_polynomials,
    small_fractions,
    xy_polynomials,
)
from mechmodel.algebra import (
    I_UNIT,
    Gaussian,
    Laurent,
    exact,
    polynomial_derivative,
    polynomial_integral,
)

pytestmark = pytest.mark.properties
ONES = {(i, j): (1, 1) for i in range(3) for j in range(3)}  # every term (1 + i) x^i y^j


def gaussian(parts: tuple[int, int]) -> Gaussian:
    return Gaussian(Fraction(parts[0]), Fraction(parts[1]))


def xy_poly(terms: dict[tuple[int, int], tuple[int, int]]) -> Laurent:
    return Laurent.from_powers(("x", "y"), {k: gaussian(c) for k, c in terms.items()})


@given(gaussian_integers(), gaussian_integers(), small_fractions(), st.integers(-4, 4))
def test_gaussian_rationals_are_a_field(
    u: tuple[int, int], v: tuple[int, int], q: Fraction, n: int
) -> None:
    """Exact complex arithmetic: (u v)/v = u, u - u = 0, u u* = |u|^2 real, i^2 = -1, powers
    add their exponents; a Gaussian with no imaginary part equals its real number, and floats
    and complex numbers convert exactly."""
    a, b = gaussian(u), gaussian(v)
    assert I_UNIT * I_UNIT == -1
    assert a - a == 0
    assert (a + b) - b == a
    assert (a * a.conjugate()).im == 0
    if not b.is_zero():
        assert (a * b) / b == a
        assert b ** (n + 1) == b**n * b
        assert 1 / b * b == 1
    assert Gaussian(q, 0) == q
    assert q == Gaussian(q, 0)
    assert exact(Gaussian(q, 0)) == q
    assert isinstance(exact(Gaussian(q, 0)), Fraction)
    x, y = u
    half = Fraction(x, 2)
    assert Gaussian.of(float(half)) == Gaussian(half, 0)  # floats convert exactly
    assert Gaussian.of(complex(x, y) / 4) == Gaussian(Fraction(x, 4), Fraction(y, 4))


@given(xy_polynomials(), xy_polynomials(), gaussian_integers(), gaussian_integers())
@example(ONES, ONES, (2, 1), (0, 3))
def test_polynomials_evaluate_as_the_functions_they_stand_for(
    p_terms: dict, q_terms: dict, u: tuple[int, int], v: tuple[int, int]
) -> None:
    """Evaluation is a ring homomorphism: the variables take the values u and v, sums and
    products evaluate to sums and products of the values, and the float evaluation agrees with
    the exact one; the coefficients read back by their exponents rebuild the polynomial, and
    p = Re p + i Im p with Re p* = Re p, Im p* = -Im p."""
    p, q = xy_poly(p_terms), xy_poly(q_terms)
    at = {"x": gaussian(u), "y": gaussian(v)}
    assert Laurent.var("x").evaluate(at) == at["x"]
    assert Laurent.var("y").evaluate(at) == at["y"]
    assert (p + q).evaluate(at) == p.evaluate(at) + q.evaluate(at)
    assert (p * q).evaluate(at) == p.evaluate(at) * q.evaluate(at)
    cu, cv = complex(*u), complex(*v)
    terms = p.powers("x", "y")
    scale = sum(abs(complex(c)) * abs(cu) ** a * abs(cv) ** b for (a, b), c in terms.items())
    floats = p.evaluate({"x": cu, "y": cv})
    assert abs(complex(floats) - complex(p.evaluate(at))) <= 1e-12 * (1 + scale)
    assert Laurent.from_powers(("x", "y"), terms) == p
    assert p.real_part() + p.imag_part() * I_UNIT == p
    conjugate = p.conjugate_coefficients()
    assert (conjugate.real_part(), conjugate.imag_part()) == (p.real_part(), -p.imag_part())
    with pytest.raises(ValueError, match="alone"):
        (p + Laurent.var("w")).powers("x", "y")


@given(laurent_polynomials(), laurent_polynomials())
def test_laurent_derivative_obeys_leibniz(p: Laurent, q: Laurent) -> None:
    """d(pq)/dx = p dq/dx + q dp/dx, and differentiation undoes integration, exactly (the
    calculus behind every derived coefficient of chapter 12)."""
    assert (p * q).diff("x") == p * q.diff("x") + q * p.diff("x")
    if all(dict(k).get("x", 0) != -1 for k in p.terms):
        assert p.integrate("x").diff("x") == p


@given(laurent_polynomials())
@example(Laurent.var("x") + Laurent.var("y", 2) / 2)
def test_laurent_prints_the_polynomial_it_holds(p: Laurent) -> None:
    """The printed form c*x^i*y^j + ... of a Laurent polynomial, read back by sympy, is the
    polynomial itself (x^1 printed as x): the coefficients and exponents the chapter 12
    derivations report can be read off their printout."""
    import sympy

    real = {k: c for k, c in p.terms.items() if isinstance(c, Fraction)}
    assert len(real) == len(p.terms)  # the polynomials printed here have real coefficients
    x, y = sympy.symbols("x y")
    want = sum(
        (
            sympy.Rational(c.numerator, c.denominator)
            * x ** dict(k).get("x", 0)
            * y ** dict(k).get("y", 0)
            for k, c in real.items()
        ),
        sympy.Integer(0),
    )
    got = sympy.sympify(repr(p).replace("^", "**"), locals={"x": x, "y": y})
    assert sympy.expand(got - want) == 0


@given(st.integers(0, 4), st.integers(0, 5), st.floats(min_value=-3, max_value=3))
def test_trig_reduction_keeps_values(i: int, j: int, angle: float) -> None:
    """Rewriting sin^2 = 1 - cos^2 changes the form, not the value, of cos^i sin^j."""
    p = Laurent.var("c", i) * Laurent.var("s", j)
    values = {"c": math.cos(angle), "s": math.sin(angle)}
    reduced, direct = p.reduce_trig("c", "s").evaluate(values), p.evaluate(values)
    assert abs(complex(reduced) - complex(direct)) <= 1e-12 * 2**j


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

    slope = sum((c * t**k for k, c in enumerate(polynomial_derivative(coefficients))), Fraction(0))
    quotient = (x(t + h) - x(t - h)) / (2 * h)
    assert abs(float(quotient - slope)) <= sum(abs(c) for c in coefficients) * 6**10 * h * h


@given(st.lists(fraction_quantities(), min_size=1, max_size=6), fraction_quantities())
def test_the_integral_of_a_derivative_is_the_change(
    coefficients: list[Fraction], x: Fraction
) -> None:
    """The power rule and its inverse, exactly: the integral from 0 to x of dp/dx is
    p(x) - p(0) for any polynomial (force is minus the slope of the potential and the potential
    minus the integral of the force, (6.9), (6.12))."""
    derivative = polynomial_derivative(coefficients)
    assert len(derivative) == len(coefficients) - 1
    value = sum(c * x**k for k, c in enumerate(coefficients))
    assert polynomial_integral(derivative, x) == value - coefficients[0]
