"""Laws of Euler's formula, phasors and complex products (mechmodel.series.phasors):
chapter 10, (10.17)-(10.30), Fig. 10.5.

Floats are compared within 1e-12 of the sum of the magnitudes involved (or of the function's
size); integer and Fraction results must be exact; mpmath results are compared far below their
working precision.
"""

from __future__ import annotations

import cmath
import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from checks.properties._series_helpers import _exp_scale
from checks.properties.strategies import phase_angles, plane_points
from mechmodel import series
from mechmodel.planar import rotation

pytestmark = pytest.mark.properties
REL = 1e-12


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


# -- the formulas of the text, as functions (formula claims, design 2a) --------------------------


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


@given(plane_points(), phase_angles(), st.floats(min_value=0, max_value=1e3))
def test_the_polar_radius_of_a_phasor(point: tuple[float, float], phi: float, r: float) -> None:
    """The modulus |psi| of (10.19b) is the distance of psi_x + i psi_y from 0 (Pythagoras),
    and A e^(i phi) has modulus A (the polar form of Fig. 10.5)."""
    x, y = point
    assert math.isclose(series.phasor_modulus(x, y), math.hypot(x, y), rel_tol=1e-15)
    z = r * series.unit_phasor(phi)
    assert math.isclose(series.phasor_modulus(z.real, z.imag), r, rel_tol=1e-14, abs_tol=1e-300)
