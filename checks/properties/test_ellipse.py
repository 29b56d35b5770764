"""Laws of the kinetic energy and its ellipses (mechmodel.ellipse): (3.5b), (3.7), Figs. 3.1,
4.7c, 4.9 and 12.2.

Exact (Fraction) inputs give exact equalities; floats are compared within 1e-12 of the
magnitudes involved.
"""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from checks.properties.closeness import assert_close
from checks.properties.strategies import (
    angles,
    fraction_masses,
    fraction_velocities,
    masses,
    velocities,
)
from mechmodel.ellipse import (
    ellipse_outline,
    ellipse_point,
    ellipse_radii,
    energy_ellipse,
    kinetic_energy,
    momentum_radius,
    velocity_radius,
)

pytestmark = pytest.mark.properties
REL = 1e-12
FLOOR = 1e-300  # below this, subnormal products carry no relative precision: an absolute floor


@given(masses(), masses(), velocities(), velocities(), angles())
@example(4.0, 1.0, 60.0, 10.0, 0.0)  # the KE = 7,250 ellipse of Fig. 3.1
@example(4.0, 1.0, 0.0, 0.0, 1.0)  # at rest: the ellipse shrinks to the origin
def test_the_ellipse_radii_and_points_satisfy_the_energy_equation(
    m1: float, m2: float, v1: float, v2: float, angle: float
) -> None:
    """The radii (a, b) = (sqrt(2KE/m1), sqrt(2KE/m2)) of (3.7b) give 1/2 m1 a^2 = 1/2 m2 b^2
    = KE, and every (a cos s, b sin s) (Exercise Fig. 3.7) has that KE; with an mpmath angle
    the point is the same to float precision."""
    ke = kinetic_energy((m1, m2), (v1, v2))
    a, b = ellipse_radii(m1, m2, ke)
    assert energy_ellipse(m1, m2, v1, v2).radii == (a, b)
    assert_close(m1 * a * a / 2, ke, scale=ke, abs=FLOOR)
    assert_close(m2 * b * b / 2, ke, scale=ke, abs=FLOOR)
    if ke == 0:
        assert (a, b) == (0, 0)
        return
    x, y = ellipse_point(a, b, angle)
    assert_close(kinetic_energy((m1, m2), (x, y)), ke, scale=4 * ke, abs=FLOOR)
    xm, ym = ellipse_point(a, b, mpmath.mpf(angle))
    assert_close(float(xm), x, scale=4 * a, abs=FLOOR)
    assert_close(float(ym), y, scale=4 * b, abs=FLOOR)


@given(fraction_masses(), fraction_masses(), fraction_velocities(), fraction_velocities())
@example(Fraction(7), Fraction(1), Fraction(1), Fraction(-1))  # the X2 start of Fig. 4.7c
def test_the_energy_ellipse_is_the_kinetic_energy_through_the_state(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction
) -> None:
    """The KE ellipse m1 v1^2 + m2 v2^2 = 2 KE (3.7b), Fig. 4.7c: its energy is the balls'
    kinetic energy exactly, it passes through the state (v1, v2), and its shorter semi-axis
    lies along the heavier ball's velocity."""
    ellipse = energy_ellipse(m1, m2, v1, v2)
    assert ellipse.energy == kinetic_energy((m1, m2), (v1, v2))
    if ellipse.twice_energy:
        on = float(v1) ** 2 / ellipse.radius_v1**2 + float(v2) ** 2 / ellipse.radius_v2**2
        assert math.isclose(on, 1, rel_tol=REL)
        heavy, light = (
            (ellipse.radius_v1, ellipse.radius_v2)
            if m1 >= m2
            else (ellipse.radius_v2, ellipse.radius_v1)
        )
        assert (ellipse.minor_radius, ellipse.major_radius) == (heavy, light)


@given(fraction_masses(), st.integers(min_value=0, max_value=40), st.integers(1, 40))
@example(Fraction(2), 1, 1)  # 2E/m = 1: the unit circle of the quasi-velocities (12.5)
def test_the_radii_of_one_energy_are_exact_for_squares(mass: Fraction, top: int, q: int) -> None:
    """sqrt(2E/m) along a velocity axis and sqrt(2Em) along a momentum axis (3.7b), Fig. 12.2:
    1/2 m a^2 = E = a_p^2/(2m), and the momentum radius is m times the velocity radius; both
    are exact where 2E/m is a rational square. A negative energy has no ellipse."""
    energy = mass * Fraction(top, q) ** 2 / 2  # 2E/m = (top/q)^2
    a, a_p = velocity_radius(mass, energy), momentum_radius(mass, energy)
    assert a == Fraction(top, q)
    assert mass * a * a / 2 == energy
    assert_close(a_p, mass * a)
    assert_close(a_p * a_p / (2 * mass), energy)
    with pytest.raises(ValueError, match="not negative"):
        velocity_radius(mass, -energy - 1)


@given(masses(), masses(), velocities(), velocities(), st.integers(min_value=2, max_value=50))
def test_the_outline_is_the_closed_ellipse(
    m1: float, m2: float, v1: float, v2: float, points: int
) -> None:
    """The drawn outline of an energy ellipse lies on it, (x/a)^2 + (y/b)^2 = 1, every point at
    the energy KE, and it closes: its last point is its first."""
    ellipse = energy_ellipse(m1, m2, v1, v2)
    a, b = ellipse.radii
    xs, ys = ellipse_outline(a, b, points)
    assert len(xs) == len(ys) == points
    assert_close((xs[0], ys[0]), (xs[-1], ys[-1]), scale=4 * (a + b), abs=FLOOR)
    if ellipse.energy:
        for x, y in zip(xs, ys, strict=True):
            assert_close((x / a) ** 2 + (y / b) ** 2, 1.0, scale=4)
            assert_close(kinetic_energy((m1, m2), (x, y)), ellipse.energy, scale=4 * ellipse.energy)
