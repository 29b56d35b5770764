"""Laws of Coulomb's and Newton's inverse-square forces (mechmodel.fields.inverse_square_laws):
chapter 9, (9.1)-(9.4).

Floats are compared within 1e-12 of the sum of the magnitudes involved (a few ulps more where a
square root or a trigonometric function of a large phase intervenes, as said); Fraction inputs
must give exact equality.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

from checks.properties.strategies import (
    fraction_coefficients,
    fraction_quantities,
    lengths,
    planet_radii,
    surface_gravities,
)
from mechmodel import fields

pytestmark = pytest.mark.properties
REL = 1e-12


# --- spheres and Newton's inverse square (9.3), after Fig. 9.5 --------------------------------


@given(lengths())
def test_sphere_area_is_the_slope_of_its_volume(radius: float) -> None:
    """A sphere of radius r has the area 4 pi r^2 (the bang-ball count falls off as its
    inverse, after Fig. 9.5) and the ball the volume 4 pi r^3 / 3 (7.4): the area is dV/dr, a
    shell's volume per unit thickness, and doubling the radius quadruples the area."""
    area = fields.sphere_area(radius)
    h = radius * 1e-6
    slope = (fields.sphere_volume(radius + h) - fields.sphere_volume(radius - h)) / (2 * h)
    assert math.isclose(slope, area, rel_tol=1e-9)
    assert math.isclose(fields.sphere_area(2 * radius), 4 * area, rel_tol=4 * REL)


@given(fraction_quantities(), fraction_quantities(), fraction_quantities(), fraction_quantities())
def test_gravity_falls_off_as_the_inverse_square(
    big_g: Fraction, m1: Fraction, m2: Fraction, r: Fraction
) -> None:
    """Newton's F = G m1 m2 / r^2 (9.3), exactly: symmetric in the masses, a quarter at twice the
    distance, and at a planet's surface the weight m g with g = G M / R^2."""
    force = fields.gravitational_force(big_g, m1, m2, r)
    assert force * r * r == big_g * m1 * m2
    assert fields.gravitational_force(big_g, m2, m1, r) == force
    assert fields.gravitational_force(big_g, m1, m2, 2 * r) == force / 4
    assert fields.weight(m2, fields.gravitational_force(big_g, m1, 1, r)) == force


# --- calculus of powers and Coulomb's law (9.1)-(9.2) -----------------------------------------


@given(fraction_coefficients())
def test_antiderivative_undoes_the_derivative(n: Fraction) -> None:
    """d/dr r^n = n r^(n-1) and the antiderivative of r^(n-1) is r^n / n ((9.2b)-(9.2c))."""
    assume(n != 0)
    down = fields.power_law_calculus(n)
    up = fields.power_law_calculus(down.derivative_exponent)
    assert up.antiderivative_exponent == n
    assert up.antiderivative_coefficient is not None  # n - 1 != -1: a power, not a log
    assert up.antiderivative_coefficient * down.derivative_coefficient == 1


@given(st.floats(min_value=0.1, max_value=10), st.floats(min_value=0.1, max_value=10))
def test_coulomb_force_is_minus_the_slope_of_coulomb_energy(q: float, r: float) -> None:
    """F = k q1 q2 / r^2 is -dU/dr of U = k q1 q2 / r (9.1)-(9.2a): halving r quadruples F."""
    k = 1.0
    h = r * 1e-6
    slope = (fields.coulomb_energy(k, q, q, r + h) - fields.coulomb_energy(k, q, q, r - h)) / (
        2 * h
    )
    force = fields.coulomb_force(k, q, q, r)
    assert math.isclose(-slope, force, rel_tol=1e-6)
    assert math.isclose(fields.coulomb_force(k, q, q, r / 2), 4 * force, rel_tol=1e-12)


# --- the formulas of chapter 9 as the book writes them: Coulomb, a ball, units ----------------


@given(
    st.floats(min_value=-10, max_value=10).filter(lambda q: abs(q) > 1e-3),
    st.floats(min_value=0.1, max_value=10),
    st.floats(min_value=0.1, max_value=10),
    st.floats(min_value=0.1, max_value=10),
)
def test_coulomb_force_and_potential_by_calculus(
    q: float, big_q: float, epsilon0: float, r: float
) -> None:
    """(9.2b)-(9.2c): the force found as -dU/dr of the potential, and the potential found as
    minus the integral of the force from infinity, are Coulomb's k q Q / r^2 and k q Q / r
    with k = 1/(4 pi eps0); the potential's slope is minus the force."""
    k = 1 / (4 * math.pi * epsilon0)
    force = fields.coulomb_force_from_potential(q, big_q, epsilon0, r)
    potential = fields.coulomb_potential_from_force(q, big_q, epsilon0, r)
    assert math.isclose(force, fields.coulomb_force(k, q, big_q, r), rel_tol=4 * REL)
    assert math.isclose(potential, fields.coulomb_energy(k, q, big_q, r), rel_tol=4 * REL)
    h = r * 1e-6
    slope = (
        fields.coulomb_potential_from_force(q, big_q, epsilon0, r + h)
        - fields.coulomb_potential_from_force(q, big_q, epsilon0, r - h)
    ) / (2 * h)
    assert math.isclose(-slope, force, rel_tol=1e-6)


@given(surface_gravities(), planet_radii(), st.floats(min_value=0.01, max_value=1))
def test_a_uniform_ball_pulls_linearly_inside(g: float, radius: float, fraction: float) -> None:
    """Inside a uniform ball only the mass within r pulls (9.4a): the pull grows linearly with
    r, reaches the surface gravity G R 4 pi rho / 3 at r = R (9.4b), and matches the field of a
    uniform Earth of that surface gravity; the inside mass is the density times the volume."""
    big_g = 6.7e-11
    density = g / (big_g * radius * 4 * math.pi / 3)  # the density that gives the gravity g
    r = fraction * radius
    assert math.isclose(
        fields.inside_mass(density, r), density * fields.sphere_volume(r), rel_tol=4 * REL
    )
    pull = fields.inside_gravity_force(big_g, density, 1.0, r)
    half = fields.inside_gravity_force(big_g, density, 1.0, r / 2)
    assert math.isclose(half, pull / 2, rel_tol=8 * REL)
    surface = fields.uniform_surface_gravity(big_g, density, radius)
    assert math.isclose(surface, g, rel_tol=8 * REL)
    assert math.isclose(pull, -fields.gravity_field(g, radius, r), rel_tol=8 * REL)
    assert math.isclose(fields.inside_gravity_force(big_g, density, 3.0, r), 3 * pull, rel_tol=REL)


@given(fraction_quantities(), fraction_quantities(), fraction_quantities(), fraction_quantities())
def test_constant_units_keep_the_laws_in_any_units(
    newton: Fraction, metre: Fraction, kilogram: Fraction, coulomb: Fraction
) -> None:
    """Measured in other units (a newton, metre, kilogram, coulomb worth the given numbers, a
    joule a newton metre), G and Coulomb's constant take the factors of their units, and
    Newton's law (9.3) and the potential (9.2a) hold unchanged, exactly: N = [G] kg^2/m^2 and
    J = [k] C^2/m."""
    g_unit = fields.gravitational_constant_unit(newton, metre, kilogram)
    assert g_unit * kilogram * kilogram / (metre * metre) == newton
    joule = newton * metre
    k_unit = fields.coulomb_constant_unit(joule, metre, coulomb)
    assert k_unit * coulomb * coulomb / metre == joule
    assert fields.gravitational_constant_unit(1, 1, 1) == fields.coulomb_constant_unit(1, 1, 1) == 1
