"""Laws of rotating point masses and rods, impulses, percussion and cycloids
(mechmodel.rotation): chapter 11.

Fraction inputs must give exact equality; floats are compared within 1e-12 of the magnitudes
involved (1e-9 for the bisection of the sweet spot and for sines of the rod's turn).
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import example, given

from checks.properties.strategies import (
    exact_radii,
    hit_fractions,
    orbit_fractions,
    riemann_steps,
)
from mechmodel import rotation

pytestmark = pytest.mark.properties
REL = 1e-12


@given(exact_radii(), exact_radii(), exact_radii())
def test_point_mass_energy_and_momentum_take_angular_form(
    m: Fraction, r: Fraction, w: Fraction
) -> None:
    """With V = w r: 1/2 m V^2 = 1/2 m r^2 w^2 = 1/2 I w^2 and m V r = m r^2 w = I w, where
    I = m r^2 replaces m and w replaces V ((11.23)-(11.24))."""
    inertia = rotation.point_inertia(m, r)
    assert inertia == m * r * r
    assert rotation.rotation_energy(m, r, w) == inertia * w * w / 2
    assert rotation.point_angular_momentum(m, r, w) == inertia * w


@given(exact_radii(), exact_radii(), riemann_steps())
@example(Fraction(1), Fraction(1), 1)
def test_rod_inertia_is_the_limit_of_slices(rho: Fraction, length: Fraction, n: int) -> None:
    """The midpoint sum of rho r^2 dr over n slices of a rod of length l is exactly
    rho l^3 (1/3 - 1/(12 n^2)): it closes in on the integral rho l^3/3 of (11.25)."""
    dr = length / n
    midpoint_sum = sum(rho * ((k + Fraction(1, 2)) * dr) ** 2 * dr for k in range(n))
    integral = rotation.rod_inertia_about_end(rho, length)
    assert integral - midpoint_sum == rho * length**3 / (12 * n * n)


@given(exact_radii(), exact_radii())
def test_free_rod_inertia_is_m_l_squared_over_twelve(mass: Fraction, half: Fraction) -> None:
    """Two rods of length l welded end to end turn about the weld with I = M l^2/3, the
    M L^2/12 of a rod of length L = 2l about its centre (text before Fig. 11.9)."""
    assert rotation.free_rod_inertia(mass, half) == mass * (2 * half) ** 2 / 12


@given(exact_radii(), exact_radii(), exact_radii(), hit_fractions())
@example(Fraction(1), Fraction(1), Fraction(1), Fraction(1))  # a hit at the end: p = l/3
def test_the_percussion_point_is_at_rest(
    mass: Fraction, half: Fraction, impulse: Fraction, hit: Fraction
) -> None:
    """An impulse Pi at height h gives M V = Pi and I w = Pi h; the point at distance p = V/w
    on the far side is at rest (V - w p = 0), and h p = I/M = l^2/3 (Fig. 11.10)."""
    h = hit * half
    response = rotation.rod_impulse(mass, half, impulse, h)
    assert mass * response.cm_velocity == impulse
    assert rotation.free_rod_inertia(mass, half) * response.angular_velocity == impulse * h
    assert response.cm_velocity - response.angular_velocity * response.percussion_radius == 0
    assert response.hit_percussion_product == half * half / 3
    assert response.product_coefficient == Fraction(1, 3)  # h p / l^2, whatever l and h
    assert rotation.percussion_fraction(half, 1 / hit) == 1 / (3 * hit)  # p/l = l/(3h)


@given(exact_radii())
def test_sweet_spot_is_the_radius_of_gyration(half: Fraction) -> None:
    """Where the hit height equals the percussion radius, both are the radius of gyration
    sqrt(I/M) = l/sqrt(3) (text after Fig. 11.10)."""
    spot = rotation.sweet_spot(half)
    gyration = rotation.radius_of_gyration(2 * half)
    assert abs(spot - gyration) <= 1e-9 * float(half)
    assert abs(gyration * math.sqrt(3) - float(half)) <= REL * float(half)


@given(exact_radii(), hit_fractions(), orbit_fractions())
def test_rod_points_roll_on_the_percussion_tire(
    half: Fraction, hit: Fraction, turns: float
) -> None:
    """Each rod point turns about the centre at w while the centre moves at V = w p: the point
    at s = -p touches the road at rest when it is at the bottom (a normal cycloid's cusp), and
    every point's speed is w times its distance from the road contact (Fig. 11.9)."""
    h = hit * half
    response = rotation.rod_impulse(1, half, 1, h)
    p = float(response.percussion_radius)
    w = float(response.angular_velocity)
    t = turns * 2 * math.pi / w
    dt = 1e-7 / w

    def velocity(s: float, time: float) -> tuple[float, float]:
        x1, y1 = rotation.rod_point_position(1, half, 1, h, s, time + dt)
        x0, y0 = rotation.rod_point_position(1, half, 1, h, s, time - dt)
        return ((x1 - x0) / (2 * dt), (y1 - y0) / (2 * dt))

    cusp = velocity(-p, 0.0)
    assert math.hypot(*cusp) <= 1e-6 * w * p
    s = float(half)
    x, y = rotation.rod_point_position(1, half, 1, h, s, t)
    v = velocity(s, t)
    centre_x = float(response.cm_velocity) * t
    distance = math.hypot(x - centre_x, y + p)  # from the contact point (centre_x, -p)
    assert abs(math.hypot(*v) - w * distance) <= 1e-5 * w * (distance + p)
    assert rotation.cycloid_kind(-p, p) == "normal"
    assert rotation.cycloid_kind(0, p) == "line"
    assert rotation.cycloid_kind(p / 2, p) == "prolate"
    assert rotation.cycloid_kind(2 * p, p) == "curlate"


@given(exact_radii(), exact_radii(), exact_radii())
def test_inertia_energy_is_the_point_mass_energy(m: Fraction, r: Fraction, w: Fraction) -> None:
    """1/2 I w^2 with I = m r^2 is the point mass's 1/2 m r^2 w^2 (11.23), exactly."""
    inertia = rotation.point_inertia(m, r)
    assert rotation.inertia_energy(inertia, w) == rotation.rotation_energy(m, r, w)
    assert rotation.inertia_energy(inertia, 2 * w) == 4 * rotation.inertia_energy(inertia, w)


@given(exact_radii(), exact_radii())
def test_rod_inertia_by_mass(mass: Fraction, length: Fraction) -> None:
    """A rod of mass M = rho l about one end has I = rho l^3/3 = M l^2/3 (11.25), exactly; two
    such rods of mass M/2 welded end to end (a free rod of half-length l) keep I = M l^2/3."""
    inertia = rotation.rod_inertia_of_mass(mass, length)
    assert inertia == rotation.rod_inertia_about_end(mass / length, length)
    assert inertia == mass * length * length / 3
    assert rotation.free_rod_inertia(mass, length) == inertia


@given(exact_radii(), hit_fractions())
@example(Fraction(1), Fraction(1, 3))  # h = l/3 gives p = l
def test_percussion_radius_for_a_hit_at_a_fraction(half: Fraction, hit: Fraction) -> None:
    """A hit at h = l/d puts the percussion point at p = d l/3: h p = l^2/3 (Fig. 11.10), the
    radius growing as the hit height falls."""
    divisor = 1 / hit
    p = rotation.percussion_radius_for_divisor(half, divisor)
    assert p * half / divisor == half * half / 3
    assert p == rotation.percussion_fraction(half, divisor) * half
