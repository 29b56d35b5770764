"""Laws of potentials of analytic fields (mechmodel.complexfields.potentials): chapter 10,
(10.33)-(10.38), (10.44)-(10.47).

The power rule and its one exception, the power potential of a z^n field (exact, Gaussian
rationals), the factors of (10.34) and (10.46)-(10.47); fields and potentials at a point
against central differences.

Shared helpers of the complexfields modules are in ``_complexfields_helpers``.
"""

from __future__ import annotations

import cmath
from fractions import Fraction

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from checks.properties._complexfields_helpers import HALF, NONNEGATIVE_POWERS, view_at, z_derivative
from checks.properties.closeness import assert_close
from checks.properties.strategies import (
    field_powers,
    gaussian_integers,
    off_origin_points,
    small_fractions,
)
from mechmodel import complexfields as cf

pytestmark = pytest.mark.properties
COEFFICIENTS = st.floats(min_value=-5, max_value=5, allow_nan=False)


def combined(*weighted: tuple[Fraction, cf.PolyView]) -> dict[str, Fraction]:
    """The coefficients of sum w_k p_k for printed polynomials p_k (zero terms dropped)."""
    out: dict[str, Fraction] = {}
    for w, view in weighted:
        for name, c in view.coefficients.items():
            out[name] = out.get(name, Fraction(0)) + w * c
    return {k: c for k, c in out.items() if c != 0}


@given(small_fractions())
def test_factor_pairs_of_the_potentials_sum_to_one(f: Fraction) -> None:
    """F = f grad Phi + j curl A for an analytic potential exactly when f + j = 1 (10.34)."""
    pair = cf.complementary_potential_factor(f)
    assert pair.j == 1 - f
    assert pair.total == 1 == cf.potential_factor_sum()


@given(NONNEGATIVE_POWERS, gaussian_integers())
def test_the_power_potential_gives_its_field(n: int, a: tuple[int, int]) -> None:
    """phi = a z^(n+1)/(n+1): grad Phi = curl A = F, the plotted field of f = a z^n (10.35)."""
    if a == (0, 0):
        a = (1, 0)
    p = cf.power_field_potential(n, *a)
    assert (p.grad_x, p.grad_y) == (p.field_x, p.field_y) == (p.curl_x, p.curl_y)


@given(NONNEGATIVE_POWERS, gaussian_integers(), off_origin_points())
def test_the_power_potential_is_linear_in_the_strength_and_plots_its_field(
    n: int, a: tuple[int, int], z: complex
) -> None:
    """phi = a z^(n+1)/(n+1) is linear in the complex strength: Phi_a + i A_a = a (Phi_1 + i A_1)
    with the unit potential of z^n, phi = z^2/2 with Phi = (x^2 - y^2)/2 and A = xy for the
    field z of Fig. 10.7; at every point Phi and A are Re phi and Im phi, and the printed field
    is the plotted F = (Re f*, Im f*) of f = a z^n (10.35)."""
    re_a, im_a = Fraction(a[0]), Fraction(a[1])
    unit, p = cf.power_field_potential(n), cf.power_field_potential(n, *a)
    assert p.phi.coefficients == combined((re_a, unit.phi), (-im_a, unit.a))
    assert p.a.coefficients == combined((im_a, unit.phi), (re_a, unit.a))
    if n == 1:
        assert unit.phi.coefficients == {"x0y2": -HALF, "x2y0": HALF}
        assert unit.a.coefficients == {"x1y1": 1}
    strength = complex(*a)
    tol = 1e-12 * (1 + abs(strength)) * (1 + 2 * abs(z)) ** (n + 1)
    big_phi, big_a = cf.potential_parts(lambda w: strength * w ** (n + 1) / (n + 1), z)
    assert_close(big_phi, view_at(p.phi, z), rel=0, abs=tol)
    assert_close(big_a, view_at(p.a, z), rel=0, abs=tol)
    fx, fy = cf.plot_field(lambda w: strength * w**n, z)
    assert_close(fx, view_at(p.field_x, z), rel=0, abs=tol)
    assert_close(fy, view_at(p.field_y, z), rel=0, abs=tol)


# --- power rule -------------------------------------------------------------------------------


@pytest.mark.parametrize("n", [n for n in range(-8, 9) if n != -1])
def test_the_power_potential_differentiates_back_to_its_field(n: int) -> None:
    """d/dz [z^(n+1)/(n+1)] = z^n for every n but -1 (10.35a), (10.44)."""
    anti = cf.power_antiderivative(n)
    back = cf.laurent_derivative(anti.coefficient, anti.power)
    assert (back.coefficient, back.power) == (Fraction(1), n)


@given(st.integers(-8, 6), st.integers(-8, 6))
@example(-1, -1)
@example(-8, -2)
@example(-1, 6)  # the scan's whole range
def test_only_z_to_the_minus_one_lacks_a_power_potential(first: int, second: int) -> None:
    """In every range of powers the logarithmic case n = -1 is the one exception to the power
    rule (10.38), and the one power whose loop integral around the origin is not zero (10.39):
    the 2^0-pole, m = n + 1 = 0 (10.44); a range without it has neither."""
    lowest, highest = sorted((first, second))
    assert cf.exceptional_power(-20, 20) == -1
    if lowest <= -1 <= highest:
        assert cf.exceptional_power(lowest, highest) == -1
        loop = cf.nonzero_loop_powers(lowest, highest)
        assert (loop.powers, loop.field_power, loop.m) == ((-1,), -1, 0)
        return
    with pytest.raises(ArithmeticError, match="found"):
        cf.exceptional_power(lowest, highest)
    with pytest.raises(ArithmeticError, match="found"):
        cf.nonzero_loop_powers(lowest, highest)


# --- the factors of the source definitions (10.46)-(10.47) ------------------------------------


def test_the_definition_factors_make_rho_the_divergence() -> None:
    """s* = 2 df*/dz and f* = 2 dphi*/dz* (10.46)-(10.47): both factors are 2, and phi takes
    the prefactor 1/2."""
    factors = cf.source_field_factors()
    assert (factors.source, factors.potential, factors.potential_prefactor) == (
        Fraction(2),
        Fraction(2),
        HALF,
    )


# --- formulas at a point (the models of the formula claims) -----------------------------------


@given(field_powers(), gaussian_integers(), off_origin_points())
def test_power_potentials_differentiate_to_their_fields(
    n: int, a: tuple[int, int], z: complex
) -> None:
    """The potential of f = a z^n has dphi/dz = f along x and along y (10.33a): a z^(n+1)/(n+1),
    and a ln z for n = -1 (10.38); Phi and A are its real and imaginary parts and the plotted
    vector is f* (10.33b); the polar form gives the same point (Figs. 10.9-10.14)."""
    if a == (0, 0):
        a = (1, 0)
    p = cf.power_field_at(n, z.real, z.imag, *a)
    assert p.field == complex(*a) * z**n
    assert p.plotted == p.field.conjugate()
    assert (p.phi, p.a) == (p.potential.real, p.potential.imag)

    def potential(w: complex) -> complex:
        return cf.power_field_at(n, w.real, w.imag, *a).potential

    scale = abs(p.field) + abs(p.potential) / abs(z)
    for derivative in z_derivative(potential, z):
        assert abs(derivative - p.field) <= 1e-5 * scale
    q = cf.power_field_polar(n, abs(z), cmath.phase(z), *a)
    assert abs(q.potential - p.potential) <= 1e-12 * (abs(p.potential) + 1)
    assert abs(q.field - p.field) <= 1e-12 * abs(p.field)
    with pytest.raises(ValueError, match="origin"):
        cf.power_field_at(n, 0, 0)


@given(st.lists(COEFFICIENTS, min_size=1, max_size=8), st.integers(-4, 1), off_origin_points())
def test_laurent_potentials_differentiate_to_their_series(
    coeffs: list[float], lowest: int, z: complex
) -> None:
    """The potential series of (10.44) differentiates term by term to the field series
    sum a_n z^n; with z replaced by w = 1/z it is the same series evaluated at w."""
    total = cf.laurent_potential_at(coeffs, lowest, z.real, z.imag)
    series = sum(c * z ** (lowest + j) for j, c in enumerate(coeffs))

    def potential(w: complex) -> complex:
        return cf.laurent_potential_at(coeffs, lowest, w.real, w.imag)

    scale = sum(abs(c) * abs(z) ** (lowest + j) for j, c in enumerate(coeffs))
    for derivative in z_derivative(potential, z):
        assert abs(derivative - series) <= 1e-5 * (scale + abs(total) / abs(z) + 1)
    w = 1 / z
    inverted = cf.inverted_laurent_potential_at(coeffs, lowest, z.real, z.imag)
    assert inverted == cf.laurent_potential_at(coeffs, lowest, w.real, w.imag)


@given(st.lists(COEFFICIENTS, min_size=1, max_size=6), off_origin_points())
def test_a_polynomial_is_its_own_taylor_series(coeffs: list[float], z: complex) -> None:
    """f(z) = sum c_k z^k, k >= 0: f(0) = c_0 (the n = 0 term of (10.45c)) and f'(0) = c_1."""
    f = cf.analytic_polynomial_at(coeffs, z.real, z.imag)
    assert abs(f - sum(c * z**k for k, c in enumerate(coeffs))) <= 1e-9 * (1 + abs(f))
    assert cf.analytic_polynomial_at(coeffs, 0, 0) == coeffs[0]
    h = 1e-6
    slope = cf.analytic_polynomial_at(coeffs, h, 0) - cf.analytic_polynomial_at(coeffs, -h, 0)
    c1 = coeffs[1] if len(coeffs) > 1 else 0.0
    assert abs(slope / (2 * h) - c1) <= 1e-6 * (1 + sum(map(abs, coeffs)))
