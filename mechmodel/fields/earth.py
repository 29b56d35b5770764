"""A uniform Earth: field, potential, escape (chapter 9, (9.4)-(9.7), (9.11)-(9.12), Figs. 9.6-9.7).

Radius R and surface gravity g: the field is linear inside (-g r / R) and inverse-square
outside (9.4); the potential is the parabola g (r^2/R - 3R)/2 inside that meets -g R^2/r
outside (Fig. 9.7; in the book's units, GM = 1, (x^2 - 3)/2); the shell elements that cancel
inside (Fig. 9.6); the starlet's energy, the three equal energy steps to escape (9.11), the
orbit and escape speeds v0 = sqrt(g R), Ve = sqrt(2 g R), and the black-hole radius (9.12).
SI units (m, s, kg, J) or the scaled units of Fig. 9.7.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from mechmodel import inputs
from mechmodel.fields.inverse_square_laws import inverse_square
from mechmodel.fields.parabola import ParabolaGeometry, parabola_geometry
from mechmodel.typing import Real


def gravity_field(g: Real, radius: Real, r: Real) -> Real:
    """Radial gravitational field of a uniform Earth at distance ``r`` from its centre, m/s^2
    (negative: toward the centre).

    Inside (r <= R) only the mass within r pulls: -g r / R, linear (9.4a); outside the whole
    mass pulls as from the centre: -g R^2 / r^2. Both give -g at the surface.
    """
    inputs.positive(g, "g")
    inputs.positive(radius, "radius")
    inputs.real(r, "r")
    if r < 0:
        raise ValueError(f"r is a distance from the centre, got {r!r}")
    if r <= radius:
        return -g * r / radius
    return -g * radius * radius / (r * r)


def gravity_potential(g: Real, radius: Real, r: Real) -> Real:
    """Gravitational potential (energy per unit mass) of a uniform Earth, J/kg, zero at infinity.

    Outside: -g R^2 / r (= -GM/r). Inside: the parabola g (r^2/R - 3R) / 2, whose slope is
    minus the linear field and which meets -gR at the surface (Fig. 9.7: (x^2 - 3)/2 in mgR).
    """
    inputs.positive(g, "g")
    inputs.positive(radius, "radius")
    inputs.real(r, "r")
    if r < 0:
        raise ValueError(f"r is a distance from the centre, got {r!r}")
    if r <= radius:
        return g * (r * r / radius - 3 * radius) / 2
    return -g * radius * radius / r


def potential_energy(mass: Real, g: Real, radius: Real, r: Real) -> Real:
    """Gravitational potential energy of ``mass`` at distance ``r`` from the centre, J."""
    inputs.mass(mass, "mass")
    return mass * gravity_potential(g, radius, r)


@dataclass(frozen=True)
class InteriorPotential:
    """The potential inside a uniform planet in the book's units of Fig. 9.7 (GM = 1).

    Inside, U(x) = quadratic * x^2 + offset, so that its slope is minus the linear force and it
    meets the outside potential -1/x at the surface. ``quadratic_divisor`` is the 2 of x^2/2,
    ``offset_over_quadratic`` the -3 of (x^2 - 3)/2; ``surface_potential``, ``surface_force`` and
    ``surface_slope`` are U, F = -dU/dx and dU/dx at the surface, equal on both sides;
    ``centre_potential`` is the bottom of the parabola.
    """

    surface: Real
    quadratic: Real
    offset: Real
    quadratic_divisor: Real
    offset_over_quadratic: Real
    surface_potential: Real
    surface_force: Real
    surface_slope: Real
    centre_potential: Real


def interior_potential(surface: Real) -> InteriorPotential:
    """The parabolic potential inside a uniform planet whose surface is at x = ``surface``, in
    units where GM = 1 (the book's Fig. 9.7 has surface = 1).

    Outside, U = -1/x and F = -1/x^2. Inside, the force is linear, F = -x / surface^3 (continuous
    at the surface), so U = x^2 / (2 surface^3) + offset; the offset makes U continuous:
    offset = -1/surface - 1/(2 surface) = -3/(2 surface).
    """
    inputs.positive(surface, "surface")
    stiffness = 1 / surface**3  # F = -stiffness x inside
    quadratic = stiffness / 2
    outside_at_surface = -1 / surface
    offset = outside_at_surface - quadratic * surface * surface
    return InteriorPotential(
        surface=surface,
        quadratic=quadratic,
        offset=offset,
        quadratic_divisor=1 / quadratic,
        offset_over_quadratic=offset / quadratic,
        surface_potential=quadratic * surface * surface + offset,
        surface_force=-stiffness * surface,
        surface_slope=2 * quadratic * surface,
        centre_potential=offset,
    )


@dataclass(frozen=True)
class InteriorCurve:
    """The interior potential of ``interior_potential`` at a point x (Fig. 9.7 units):
    ``value`` is U(x), ``spring`` its quadratic part alone, the potential of the linear force
    -x / surface^3 with zero at the centre, before the constant that matches -1/x is added."""

    value: Real
    spring: Real


def interior_potential_at(surface: Real, x: Real) -> InteriorCurve:
    """The parabolic potential inside a uniform planet (``interior_potential``) at ``x``, with
    |x| <= ``surface`` (GM = 1 units: the book's y = x^2/2 - 3/2 for surface = 1)."""
    pot = interior_potential(surface)
    inputs.real(x, "x")
    if not -surface <= x <= surface:
        raise ValueError("the point is outside the planet: |x| <= surface")
    spring = pot.quadratic * x * x
    return InteriorCurve(spring + pot.offset, spring)


def starlet_energy(mass: Real, g: Real, radius: Real, r: Real, speed: Real) -> Real:
    """Total energy KE + PE of a starlet of ``mass`` moving at ``speed`` at distance ``r`` from
    the centre of a uniform planet (``potential_energy``, zero at infinity), J ((9.5)-(9.7))."""
    inputs.real(speed, "speed")
    return mass * speed * speed / 2 + potential_energy(mass, g, radius, r)


def centre_speed_squared(g: Real, radius: Real) -> Real:
    """Square of the speed at the centre of a starlet dropped from rest at the surface: twice
    the potential drop per unit mass from R to 0 (``gravity_potential``), m^2/s^2 ((9.7))."""
    drop = gravity_potential(g, radius, radius) - gravity_potential(g, radius, 0)
    return 2 * drop


def interior_parabola(surface: Real) -> ParabolaGeometry:
    """The focus-directrix geometry of the interior potential's parabola (Fig. 9.7): its x^2
    coefficient from ``interior_potential`` (GM = 1 units) in ``parabola_geometry``."""
    return parabola_geometry(interior_potential(surface).quadratic)


@dataclass(frozen=True)
class EscapeLadder:
    """The starlet's energy (per unit mass, GM = 1 units) on its way out of the planet: at rest
    at the centre, at rest on the surface, in the grazing circular orbit, and just escaping
    (zero at infinity); ``steps`` are the three energy jumps between them, and
    ``equal_steps`` the climb from the centre to escape counted in jumps of the first step."""

    centre: Real
    surface_rest: Real
    orbit: Real
    escape: Real
    steps: tuple[Real, Real, Real]
    equal_steps: Real


def escape_ladder(surface: Real) -> EscapeLadder:
    """The three energy steps of "Starlet escapes! (In 3 equal steps)" for a planet of radius
    ``surface`` (GM = 1): each is half of GM m / R, 1/2 mgR in mks units."""
    pot = interior_potential(surface)
    centre = pot.centre_potential
    surface_rest = pot.surface_potential
    orbit_speed_squared = 1 / surface  # v^2 / R = GM / R^2 for the grazing circular orbit
    orbit = surface_rest + orbit_speed_squared / 2
    escape = 0  # zero kinetic plus zero potential energy at infinity
    steps = (surface_rest - centre, orbit - surface_rest, escape - orbit)
    return EscapeLadder(centre, surface_rest, orbit, escape, steps, (escape - centre) / steps[0])


@dataclass(frozen=True)
class SurfaceSpeeds:
    """Speeds at the surface of a planet of surface gravity g and radius R: the grazing circular
    orbit v0 = sqrt(gR) (9.7b) and escape Ve = sqrt(2gR) (9.11), and their ratios.
    ``escape_factor`` is the 2 of Ve^2 = 2 g R = 2 G M / R."""

    orbit: float
    escape: float
    escape_over_orbit: float
    orbit_over_escape: float
    escape_factor: float


def circular_orbit_speed(g: Real, radius: Real) -> float:
    """Speed of a circular orbit at the surface, v0 = sqrt(g R) (eq. (9.7b)).

    Also the speed a starlet dropped from the surface has at the centre: (9.5)-(9.7a) give
    v^2 = g R from U(0) - U(R) = -g R / 2 per unit mass.
    """
    inputs.positive(g, "g")
    inputs.positive(radius, "radius")
    return math.sqrt(g * radius)


def escape_speed(g: Real, radius: Real) -> float:
    """Escape speed from the surface, sqrt(2 g R): the kinetic energy that lifts the potential
    -g R to zero ((9.11a))."""
    inputs.positive(g, "g")
    inputs.positive(radius, "radius")
    kinetic_needed = -gravity_potential(g, radius, radius)  # per unit mass
    return math.sqrt(2 * kinetic_needed)


def escape_speed_from_orbit_speed(orbit_speed: Real) -> float:
    """Escape speed Ve = v0 sqrt(2) from the grazing orbit speed v0 ((9.11a), the book's step)."""
    inputs.positive(orbit_speed, "orbit_speed")
    return orbit_speed * math.sqrt(2)


def escape_speed_of_orbit(orbit_speed: Real) -> float:
    """Escape speed from a planet's surface given its grazing orbit speed v0, by energies: the
    circular orbit has v0^2 = GM/R (gravity supplies the centripetal pull) and escape needs the
    kinetic energy GM m/R that lifts the potential -GM m/R to zero ((9.11a))."""
    inputs.positive(orbit_speed, "orbit_speed")
    gm_over_r = orbit_speed * orbit_speed
    kinetic_per_mass = gm_over_r
    return math.sqrt(2 * kinetic_per_mass)  # 1/2 v^2 = the kinetic energy per unit mass


def escape_speed_gm(big_g: Real, mass: Real, radius: Real) -> float:
    """Escape speed from the surface of a body of ``mass`` and ``radius``: ``escape_speed``
    with the surface gravity g = G M / R^2 ((9.11b); with the speed of light, (9.12a))."""
    inputs.positive(big_g, "G")
    inputs.mass(mass, "mass")
    inputs.positive(radius, "radius")
    return escape_speed(big_g * mass / (radius * radius), radius)


def black_hole_radius(big_g: Real, mass: Real, c: Real) -> float:
    """Radius at which the escape speed from a body of ``mass`` is ``c`` ((9.12b)): the escape
    speed squared falls as 1/R (``escape_speed_gm``), so R = 1 (v_e(1)/c)^2 in the units of R."""
    inputs.positive(c, "c")
    at_unit_radius = escape_speed_gm(big_g, mass, 1)
    return (at_unit_radius / c) ** 2


def surface_speeds(g: Real, radius: Real) -> SurfaceSpeeds:
    """The orbit and escape speeds at the surface and their ratios ((9.7b), (9.11))."""
    v0 = circular_orbit_speed(g, radius)
    ve = escape_speed(g, radius)
    return SurfaceSpeeds(v0, ve, ve / v0, v0 / ve, ve * ve / (g * radius))


def schwarzschild_radius(big_g: Real, mass: Real, c: Real) -> Real:
    """Radius 2 G M / c^2 at which the escape speed sqrt(2GM/R) is the speed of light, m
    ((9.12))."""
    inputs.positive(big_g, "G")
    inputs.mass(mass, "mass")
    inputs.positive(c, "c")
    return 2 * big_g * mass / (c * c)


def shell_pair_pull(solid_angle: Real, near: Real, far: Real) -> Real:
    """Net pull on you of the two shell elements cut by a narrow cone of sight (Fig. 9.6): the
    near element m = A d^2 at distance d, the far one M = A D^2 at D, pulling opposite ways,
    G m / d^2 - G M / D^2 (G = 1). Zero for any d and D: no gravity inside a shell."""
    inputs.positive(solid_angle, "solid_angle")
    inputs.positive(near, "near")
    inputs.positive(far, "far")
    m_near = solid_angle * near * near
    m_far = solid_angle * far * far
    return m_near * inverse_square(near) - m_far * inverse_square(far)
