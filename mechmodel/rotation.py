"""Rotating point masses and rods: inertia, impulse, percussion and cycloids (chapter 11).

A mass m on a circle of radius r at angular velocity w moves at V = w r, so its kinetic energy
1/2 m V^2 is 1/2 m r^2 w^2 = 1/2 I w^2 and its angular momentum m V r is m r^2 w = I w, with the
rotational inertia I = m r^2 in place of m and w in place of V ((11.23)-(11.24)). A uniform rod
turning about one end sums I = integral of r^2 dm = rho l^3/3 = M l^2/3 (11.25); two such rods
welded end to end (a free rod of half-length l, "radius" l) have the same I = M l^2/3 about
their centre. An impulse Pi struck at height h above the centre gives the centre the velocity
V = Pi/M and the rod the spin w = Pi h/I; the point at distance p = V/w on the other side is
momentarily at rest: the centre of percussion, h p = I/M = l^2/3 (Fig. 11.10). The rod
"rolls" on a tire of radius p: points of the rod trace cycloids, normal at distance p, prolate
inside and curlate (looped) outside (Fig. 11.9). Where h = p both equal the radius of gyration
sqrt(I/M) = l/sqrt(3).

Types: masses, lengths and impulses are floats or ``fractions.Fraction``; inertia, impulse
response and percussion radii stay exact for rational inputs. Exponents and coefficients of the
formulas are found from the physics with exact arithmetic, not written in: the power of r in
the energy is read off from how the energy grows when r doubles.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from typing import cast

from mechmodel import inputs
from mechmodel.exact import exact_div
from mechmodel.typing import Real

# a sample angular velocity, exact: I = L/w does not depend on it
_SAMPLE_OMEGA = Fraction(7)


# -- a point mass on a circle (11.23)-(11.24) ---------------------------------------------------
def tangential_speed(radius: Real, omega: Real) -> Real:
    """Linear speed V = w r of a point at radius r turning at w (before (11.23))."""
    inputs.real(radius, "radius")
    inputs.real(omega, "omega")
    return omega * radius


def rotation_energy(mass: Real, radius: Real, omega: Real) -> Real:
    """Kinetic energy 1/2 m V^2 of a point mass turning at w on a circle of radius r, with
    V = w r (11.23)."""
    inputs.mass(mass)
    v = tangential_speed(radius, omega)
    return mass * v * v / 2


def point_angular_momentum(mass: Real, radius: Real, omega: Real) -> Real:
    """Angular momentum Pi r = m V r of a point mass on a circle, V = w r (11.24)."""
    inputs.mass(mass)
    return mass * tangential_speed(radius, omega) * radius


def point_inertia(mass: Real, radius: Real) -> Real:
    """Rotational inertia I = L/w, the factor that takes the place of m (after (11.24)): m r^2."""
    return exact_div(point_angular_momentum(mass, radius, _SAMPLE_OMEGA), _SAMPLE_OMEGA)


def inertia_energy(inertia: Real, omega: Real) -> Real:
    """Kinetic energy of rotation at w of a point mass of rotational inertia I (11.23): the
    mass I/point_inertia(1, 1) on the unit circle has that inertia, and its energy is
    1/2 m V^2 with V = w r."""
    inputs.positive(inertia, "inertia")
    unit = point_inertia(1, 1)
    return rotation_energy(exact_div(inertia, unit), 1, omega)


# -- rods (11.25) -------------------------------------------------------------------------------
def rod_inertia_about_end(density: Real, length: Real) -> Real:
    """I = integral from 0 to l of rho r^2 dr (11.25): the antiderivative of rho r^2 is
    rho r^3/3 (power rule for integrals: r^n -> r^(n+1)/(n+1)). Exact for rational input."""
    inputs.positive(density, "density")
    inputs.positive(length, "length")
    n = 2  # dI = r^2 dm
    return exact_div(density * length ** (n + 1), n + 1)


def rod_inertia_of_mass(mass: Real, length: Real) -> Real:
    """Inertia about one end of a uniform rod of mass M and length l: the integral (11.25) with
    the density rho = M/l."""
    inputs.mass(mass)
    inputs.positive(length, "length")
    return rod_inertia_about_end(exact_div(mass, length), length)


def free_rod_inertia(mass: Real, half_length: Real) -> Real:
    """Inertia about the centre of a free rod of mass M and half-length l: two rods of mass M/2
    and length l welded end to end, each turning about its end (after (11.25)): M l^2/3."""
    inputs.mass(mass)
    half = exact_div(mass, 2)
    return 2 * rod_inertia_about_end(exact_div(half, half_length), half_length)


@dataclass(frozen=True)
class ImpulseResponse:
    """A free rod struck across its length: centre-of-mass velocity V = Pi/M, angular momentum
    Lambda = Pi h, angular velocity w = Lambda/I, percussion radius p = V/w (the point on the
    other side of the centre at rest), and h p with h p / l^2 (Fig. 11.10)."""

    cm_velocity: Real
    angular_momentum: Real
    angular_velocity: Real
    percussion_radius: Real
    hit_percussion_product: Real
    product_coefficient: Real


def rod_impulse(mass: Real, half_length: Real, impulse: Real, hit_height: Real) -> ImpulseResponse:
    """Response of a free rod (mass M, half-length l) to an impulse Pi at height h > 0 above its
    centre (Fig. 11.10): translation V = Pi/M and rotation w = Pi h/I cancel at distance
    p = V/w = I/(M h) on the far side."""
    inputs.positive(half_length, "half_length")
    inputs.positive(impulse, "impulse")
    inputs.positive(hit_height, "hit_height")
    inertia = free_rod_inertia(mass, half_length)
    v = exact_div(impulse, mass)
    spin_momentum = impulse * hit_height
    w = exact_div(spin_momentum, inertia)
    p = exact_div(v, w)
    hp = hit_height * p
    return ImpulseResponse(v, spin_momentum, w, p, hp, exact_div(hp, half_length**2))


def percussion_radius(half_length: Real, hit_height: Real) -> Real:
    """Percussion radius p of a free rod of half-length l struck at height h (any M, Pi)."""
    return rod_impulse(1, half_length, 1, hit_height).percussion_radius


def percussion_fraction(half_length: Real, hit_divisor: Real) -> Real:
    """p/l for a hit at h = l/``hit_divisor`` (text after Fig. 11.10: h = l/2 gives p = 2l/3)."""
    inputs.positive(hit_divisor, "hit_divisor")
    return exact_div(
        percussion_radius(half_length, exact_div(half_length, hit_divisor)), half_length
    )


def percussion_radius_for_divisor(half_length: Real, hit_divisor: Real) -> Real:
    """Percussion radius p for a hit at h = l/``hit_divisor`` (text after Fig. 11.10: h = l/3
    gives p = l)."""
    inputs.positive(hit_divisor, "hit_divisor")
    return percussion_radius(half_length, exact_div(half_length, hit_divisor))


def radius_of_gyration(rod_length: Real) -> float:
    """Radius of gyration sqrt(I/M) about the centre of a free rod of total length L = 2l:
    l/sqrt(3) (text after Fig. 11.10)."""
    inputs.positive(rod_length, "rod_length")
    half = exact_div(rod_length, 2)
    return math.sqrt(free_rod_inertia(1, half))


def sweet_spot(half_length: Real) -> float:
    """The hit height h at which the percussion radius p equals h (text after Fig. 11.10):
    h p = l^2/3 with p = h, found by bisection on p(h) - h (p falls and h rises)."""
    inputs.positive(half_length, "half_length")
    length = float(half_length)
    lo, hi = length / 1e6, length
    while hi - lo > 1e-13 * length:
        mid = (lo + hi) / 2
        if percussion_radius(length, mid) > mid:
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


# -- cycloids of a free rod (Fig. 11.9) ---------------------------------------------------------
def rod_point_position(
    mass: Real, half_length: Real, impulse: Real, hit_height: Real, offset: Real, t: Real
) -> tuple[float, float]:
    """Position at time t of the point at signed distance ``offset`` from the centre along a
    rod struck at t = 0 while it stood upright (Fig. 11.9): the centre moves at V along x, the
    rod turns clockwise at w, so the point is at (V t + s sin wt, s cos wt); the point at
    s = -p touches the "road" y = -p at rest."""
    inputs.real(offset, "offset")
    inputs.real(t, "t")
    response = rod_impulse(mass, half_length, impulse, hit_height)
    v, w = float(response.cm_velocity), float(response.angular_velocity)
    return (v * t + offset * math.sin(w * t), offset * math.cos(w * t))


def cycloid_kind(offset: Real, percussion_radius: Real) -> str:
    """The cycloid a rod point traces on the tire of radius p (Fig. 11.9): the centre a line,
    |s| < p prolate, |s| = p normal (with cusps), |s| > p curlate (looped)."""
    inputs.real(offset, "offset")
    inputs.positive(percussion_radius, "percussion_radius")
    s = cast(Real, abs(offset))  # mypy joins abs over a union to object
    if s == 0:
        return "line"
    if s < percussion_radius:
        return "prolate"
    if s == percussion_radius:
        return "normal"
    return "curlate"
