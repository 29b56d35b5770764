"""Laws of a uniform Earth's field and potential, inside and out (mechmodel.fields.earth):
chapter 9, (9.4)-(9.12), Figs. 9.6-9.7.

Floats are compared within 1e-12 of the sum of the magnitudes involved (a few ulps more where a
square root or a trigonometric function of a large phase intervenes, as said); Fraction inputs
must give exact equality.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import assume, example, given
from hypothesis import strategies as st

from checks.properties.closeness import assert_close
from checks.properties.strategies import (
    fraction_coefficients,
    oscillator_frequencies,
    planet_radii,
    radial_fractions,
    rationals,
    surface_gravities,
)
from mechmodel import fields

pytestmark = pytest.mark.properties
REL = 1e-12


# --- the uniform Earth's field and potential, inside and out (9.4), Fig. 9.7 -----------------


@given(surface_gravities(), planet_radii())
def test_field_and_potential_are_continuous_at_the_surface(g: float, radius: float) -> None:
    """Inside and outside formulas meet at the surface: the field is -g on both sides and the
    potential -gR (Fig. 9.7: UIN(1) = -1 = UEX(1), FIN(1) = -1 = FEX(1))."""
    just_out = math.nextafter(radius, math.inf)
    inside_f = fields.gravity_field(g, radius, radius)
    outside_f = fields.gravity_field(g, radius, just_out)
    inside_u = fields.gravity_potential(g, radius, radius)
    outside_u = fields.gravity_potential(g, radius, just_out)
    assert_close(inside_f, -g, scale=g)
    assert_close(outside_f, -g, rel=4 * REL, scale=g)
    assert_close(inside_u, -g * radius, scale=g * radius)
    assert_close(outside_u, -g * radius, scale=g * radius)


@given(surface_gravities(), planet_radii())
def test_the_centre_feels_no_pull_and_is_the_bottom_of_the_well(g: float, radius: float) -> None:
    """At the centre the linear field -g r / R (9.4a) vanishes and the parabolic potential has
    its bottom, -3 g R / 2 (Fig. 9.7: (x^2 - 3)/2 at x = 0); r is a distance, never negative."""
    assert fields.gravity_field(g, radius, 0.0) == 0
    assert_close(fields.gravity_potential(g, radius, 0.0), -1.5 * g * radius, scale=g * radius)
    for law in (fields.gravity_field, fields.gravity_potential):
        with pytest.raises(ValueError, match="distance"):
            law(g, radius, -radius / 2)


@given(surface_gravities(), planet_radii(), radial_fractions())
def test_field_is_minus_the_slope_of_the_potential(g: float, radius: float, x: float) -> None:
    """F = -dU/dr inside and outside (Force = -Slope, (6.9); (9.2b)), by a central difference."""
    assume(abs(x - 1) > 1e-3 and x > 1e-3)
    r = x * radius
    h = 1e-6 * radius
    slope = (
        fields.gravity_potential(g, radius, r + h) - fields.gravity_potential(g, radius, r - h)
    ) / (2 * h)
    assert_close(-slope, fields.gravity_field(g, radius, r), rel=1e-6, scale=g)


@given(surface_gravities(), planet_radii(), radial_fractions())
def test_the_field_inside_is_linear_and_outside_inverse_square(
    g: float, radius: float, x: float
) -> None:
    """Inside only the mass within r pulls, M(r) = M r^3/R^3, so F = -g r/R (9.4a); outside the
    whole mass pulls as from the centre, F = -g R^2/r^2."""
    assume(x > 1e-3)
    r = x * radius
    enclosed = min(x, 1.0) ** 3  # fraction of the planet's mass within r
    expected = -g * enclosed / (x * x)
    assert_close(fields.gravity_field(g, radius, r), expected, scale=g * (1 + enclosed / x**2))


@given(fraction_coefficients())
@example(Fraction(1))  # the Earth of Fig. 9.7, in Earth radii
def test_interior_potential_meets_the_exterior_exactly(surface: Fraction) -> None:
    """The parabola inside meets -1/x at the surface with the same slope (Fig. 9.7, GM = 1)."""
    pot = fields.interior_potential(surface)
    assert pot.surface_potential == -1 / surface
    assert pot.surface_force == -1 / surface**2
    assert pot.surface_slope == 1 / surface**2 == -pot.surface_force
    assert pot.quadratic * surface**2 + pot.offset == pot.surface_potential


@given(fraction_coefficients())
def test_escape_takes_three_equal_steps(surface: Fraction) -> None:
    """Centre to surface, surface to grazing orbit, orbit to escape: three equal steps of
    GM/(2R), 1/2 mgR each ("Starlet escapes! (In 3 equal steps)", (9.11))."""
    ladder = fields.escape_ladder(surface)
    assert ladder.steps[0] == ladder.steps[1] == ladder.steps[2] == 1 / (2 * surface)
    assert ladder.equal_steps == 3


@given(surface_gravities(), planet_radii())
def test_escape_speed_is_root_two_times_orbit_speed(g: float, radius: float) -> None:
    """Ve = v0 sqrt(2) = sqrt(2gR) (9.11a): the kinetic energy of escape is twice the orbit's."""
    speeds = fields.surface_speeds(g, radius)
    assert_close(speeds.escape, speeds.orbit * math.sqrt(2), rel=4 * REL, scale=speeds.escape)
    assert_close(speeds.escape_over_orbit, math.sqrt(2), rel=4 * REL, scale=1.0)
    assert_close(speeds.orbit_over_escape, math.sqrt(0.5), rel=4 * REL, scale=1.0)
    assert_close(speeds.escape_factor, 2.0, rel=4 * REL, scale=1.0)  # Ve^2 = 2 g R
    assert_close(
        speeds.escape, fields.escape_speed_from_orbit_speed(speeds.orbit), scale=speeds.escape
    )


@given(surface_gravities(), planet_radii(), surface_gravities())
def test_light_cannot_escape_from_the_black_hole_radius(g: float, mass: float, c: float) -> None:
    """At R = 2GM/c^2 (9.12b) the escape speed sqrt(2GM/R) (9.11b) is c (9.12a)."""
    big_g = 6.5e-11 * g  # any positive G
    radius = fields.schwarzschild_radius(big_g, mass, c)
    assert_close(math.sqrt(2 * big_g * mass / radius), c, rel=4 * REL, scale=c)


@given(oscillator_frequencies(), oscillator_frequencies(), oscillator_frequencies())
def test_shell_elements_cancel(solid_angle: float, near: float, far: float) -> None:
    """The shell elements cut by a cone of sight pull equally and oppositely: m/d^2 = M/D^2
    since both masses grow as distance squared (Fig. 9.6)."""
    assert_close(fields.shell_pair_pull(solid_angle, near, far), 0.0, scale=2 * solid_angle)


@given(
    surface_gravities(), planet_radii(), radial_fractions(), st.floats(min_value=0.1, max_value=10)
)
def test_potential_energy_is_mass_times_potential_and_its_slope_the_force(
    g: float, radius: float, fraction: float, mass: float
) -> None:
    """U = m Phi, and the field is minus the slope of the potential, -dPhi/dr = F/m, inside and
    outside a uniform Earth (Fig. 9.7)."""
    r = 2 * radius * fraction + radius / 100
    energy = fields.potential_energy(mass, g, radius, r)
    assert math.isclose(energy, mass * fields.gravity_potential(g, radius, r), rel_tol=1e-12)
    h = r * 1e-6
    phi = fields.gravity_potential
    slope = (phi(g, radius, r + h) - phi(g, radius, r - h)) / (2 * h)
    # the central difference cancels digits of a potential far larger than its slope near r = 0
    cancellation = 1e-9 * abs(float(phi(g, radius, r))) / h
    field = fields.gravity_field(g, radius, r)
    assert math.isclose(-slope, field, rel_tol=1e-6, abs_tol=cancellation)


# --- the formulas of chapter 9 as the book writes them: the interior, the starlet, escape -----


@given(fraction_coefficients(), rationals(-1, 1, 12))
@example(Fraction(1), Fraction(1))  # Fig. 9.7: U(1) = -1 = -1/x at the surface
def test_interior_curve_is_the_parabola_under_the_surface(surface: Fraction, u: Fraction) -> None:
    """The interior potential at x (|x| <= surface) is its spring part x^2 / (2 s^3), zero at
    the centre, plus the offset; it meets -1/x at the surface, exactly. Its parabola's
    half-width at the focus is s^3 (lambda = 1 in Fig. 9.7)."""
    x = u * surface
    curve = fields.interior_potential_at(surface, x)
    pot = fields.interior_potential(surface)
    assert curve.spring == x * x / (2 * surface**3)
    assert curve.value - curve.spring == pot.offset
    assert fields.interior_potential_at(surface, surface).value == -1 / surface
    assert fields.interior_potential_at(surface, 0).spring == 0
    assert fields.interior_parabola(surface).semi_latus_rectum == surface**3
    with pytest.raises(ValueError, match="outside"):
        fields.interior_potential_at(surface, 2 * surface)


@given(surface_gravities(), planet_radii(), st.floats(min_value=0.1, max_value=10))
def test_the_starlet_keeps_its_energy_from_surface_to_centre(
    g: float, radius: float, mass: float
) -> None:
    """Dropped from rest at the surface, the starlet passes the centre with v^2 = g R, the
    grazing orbit's speed squared ((9.6)-(9.7)): its energy KE + PE is the same at both."""
    v2 = fields.centre_speed_squared(g, radius)
    assert math.isclose(v2, fields.circular_orbit_speed(g, radius) ** 2, rel_tol=4 * REL)
    at_surface = fields.starlet_energy(mass, g, radius, radius, 0)
    at_centre = fields.starlet_energy(mass, g, radius, 0, math.sqrt(v2))
    assert math.isclose(at_surface, at_centre, rel_tol=8 * REL)
    assert math.isclose(at_surface, -mass * g * radius, rel_tol=8 * REL)


@given(surface_gravities(), planet_radii(), surface_gravities())
def test_escape_speed_three_ways(g: float, radius: float, c: float) -> None:
    """The escape speed from the grazing orbit speed (9.11a), from G M and R (9.11b) and from
    g and R agree; it falls as 1/sqrt(R); at the black-hole radius it is c (9.12), which is
    the Schwarzschild radius 2GM/c^2."""
    big_g = 6.7e-11
    mass = g * radius * radius / big_g
    escape = fields.escape_speed(g, radius)
    orbit = fields.circular_orbit_speed(g, radius)
    assert math.isclose(fields.escape_speed_of_orbit(orbit), escape, rel_tol=4 * REL)
    assert math.isclose(fields.escape_speed_gm(big_g, mass, radius), escape, rel_tol=8 * REL)
    quarter = fields.escape_speed_gm(big_g, mass, 4 * radius)
    assert math.isclose(quarter, escape / 2, rel_tol=8 * REL)
    hole = fields.black_hole_radius(big_g, mass, c)
    assert math.isclose(fields.escape_speed_gm(big_g, mass, hole), c, rel_tol=8 * REL)
    assert math.isclose(hole, fields.schwarzschild_radius(big_g, mass, c), rel_tol=8 * REL)
