"""Geometry and physics of common potential fields (chapter 9).

The chapter's fields, each as pure functions of the book's inputs:

- power laws and their geometric constructions: the parabola U = a x^2 drawn by similar
  triangles (Fig. 9.1), its Hooke force F = -dU/dx, the staircase of slopes s and -1/s (Fig. 9.2),
  and the focus-directrix geometry of the parabola (Figs. 9.3, 9.4);
- the inverse-square laws: Coulomb's force and potential (9.1)-(9.2), the calculus of r^n, the
  ratios of sizes and energies that the book's estimates use, and Newton's gravity (9.3);
- a uniform Earth of radius R and surface gravity g: the linear field inside and the
  inverse-square field outside (9.4), the parabolic potential inside that meets -1/x outside
  (Fig. 9.7), the tunnel through any chord and the grazing orbit (Fig. 9.8), the three equal
  energy steps to escape (9.11) and the black-hole radius (9.12);
- the neutron starlet: the density of nuclear matter and the forces on a fingertip of it;
- the isotropic two-dimensional oscillator that every starlet inside the Earth is (9.8)-(9.15):
  its orbits, energies and angular momentum, and the clock phases of Figs. 9.10-9.11.

Units: SI in, SI out (or any consistent units); the "scaled" functions use the book's units of
Fig. 9.7 (x in Earth radii, forces in mg, potentials in mgR, so that GM = 1). Angles are in
radians. Floats throughout; where a function uses only + - * / (parabola geometry, powers, the
scaled potential, the clock), ``fractions.Fraction`` inputs give exact results.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from scipy import optimize

from mechmodel import inputs
from mechmodel.numeric import clock_angle as clock_angle  # the catalog's fields.*
from mechmodel.numeric import complex_step_derivative, line_angle

# --- power laws and the constructions of Figs. 9.1-9.2 --------------------------------------


def parabola_point(x: Any, unit: Any = 1) -> Any:
    """Height of the point of the parabola y = x^2 / unit above ``x``, by the two-step
    construction of Fig. 9.1a.

    Go up the vertical line at ``x`` to the 45-degree line (height x), across to the vertical line
    at ``unit``; the line from the origin through (unit, x) has slope x / unit and meets the
    vertical at ``x`` at the height x * x / unit: similar triangles multiply.
    """
    inputs.real(x, "x")
    inputs.positive(unit, "unit")
    slope = x / unit
    return slope * x


def power_law_force(a: Any, n: Any, x: Any) -> Any:
    """Force F(x) = -dU/dx of the power-law potential U(x) = a x^n (Force = -Slope, (6.9)).

    For the oscillator U = x^2 this is Hooke's law F = -2x of Fig. 9.1b.
    """
    inputs.real(a, "a")
    inputs.real(n, "n")
    inputs.real(x, "x")
    if x == 0 and n < 1:
        raise ValueError(f"the force of a x^{n} is infinite at x = 0")
    return -n * a * x ** (n - 1)


def power_law_force_slope(a: Any, n: Any, x: Any) -> Any:
    """Slope dF/dx of the force F = -dU/dx of U(x) = a x^n: the power rule applied twice
    (``power_law_calculus``). For the oscillator U = x^2 it is the constant slope of the Hooke
    line of Fig. 9.1b."""
    inputs.real(a, "a")
    inputs.real(n, "n")
    inputs.real(x, "x")
    first = power_law_calculus(n)  # dU/dx = a n x^(n-1)
    second = power_law_calculus(first.derivative_exponent)
    if x == 0 and second.derivative_exponent < 0 and first.derivative_coefficient != 0:
        raise ValueError(f"the force of a x^{n} has no slope at x = 0")
    if first.derivative_coefficient == 0 or second.derivative_coefficient == 0:
        return 0 * a
    return (
        -a
        * first.derivative_coefficient
        * second.derivative_coefficient
        * x ** (second.derivative_exponent)
    )


@dataclass(frozen=True)
class ForceTriangle:
    """The force triangle of Fig. 9.1a at the point (x, a x^2) of the parabola U = a x^2.

    ``force`` is the Hooke force -2 a x; ``scale`` the factor that makes the force vector equal and
    opposite to the coordinate x; ``base`` the scaled force (= -x) and ``altitude`` the triangle's
    height (constant, whatever x): its hypotenuse is normal to the parabola's tangent.
    """

    force: Any
    scale: Any
    base: Any
    altitude: Any


def force_triangle(a: Any, x: Any) -> ForceTriangle:
    """The force triangle at ``x`` on U = a x^2 (Fig. 9.1a): base F/(2a), altitude 1/(2a)."""
    inputs.positive(a, "a")
    force = power_law_force(a, 2, x)
    scale = -x / force if x != 0 else 1 / (2 * a)
    slope = 2 * a * x  # the tangent's slope: the normal drops 1/slope for each unit across
    base = force * scale
    # the normal through (x, a x^2) runs along (-slope, 1); it crosses the axis after -x across
    altitude = 1 / (2 * a) if slope == 0 else -base / slope
    return ForceTriangle(force, scale, base, altitude)


def normal_slope(slope: Any) -> Any:
    """Slope -1/s of the line normal to a line of slope s (Fig. 9.2: y = s x and y = -x/s)."""
    inputs.real(slope, "slope")
    if slope == 0:
        raise ValueError("a horizontal line has a vertical normal: no slope")
    return -1 / slope


def angle_between_lines(slope1: Any, slope2: Any) -> float:
    """Angle between two lines of the given slopes, radians, in [0, pi/2] (Fig. 9.2's 90-degree
    marks between y = s x and y = -x/s, and between y = x and y = -x)."""
    turn = abs(line_angle(slope1) - line_angle(slope2)) % math.pi
    return min(turn, math.pi - turn)


# --- the parabola: focus, directrix, latus rectum (Figs. 9.3, 9.4, 9.7) ----------------------


@dataclass(frozen=True)
class ParabolaGeometry:
    """Focus-directrix geometry of the parabola y = a x^2 (vertex at the origin).

    ``focal_height`` p = 1/(4a) is the focus above the tip and the directrix as far below it;
    ``semi_latus_rectum`` is the book's lambda = 2p, the half-width at the focus;
    ``focus_to_directrix`` is 2p = lambda; ``tip_to_directrix`` the tip's height above the
    directrix, p; ``tip_radius_of_curvature`` the radius of the osculating
    circle at the tip, also lambda; ``latus_end_slope`` the slope at (lambda, p), where the focal
    radius is horizontal (the square kite of Fig. 9.4); ``focal_factor`` is the 4 of
    x^2 = 4 p y, 1/(a p); ``latus_factor`` the 2 of x^2 = 2 lambda y, 1/(a lambda).
    """

    a: Any
    focal_height: Any
    semi_latus_rectum: Any
    focus_to_directrix: Any
    directrix_height: Any
    tip_to_directrix: Any
    tip_radius_of_curvature: Any
    latus_end_slope: Any
    focal_factor: Any
    latus_factor: Any

    def height(self, x: Any) -> Any:
        """The parabola's height a x^2 at ``x``."""
        return self.a * x * x

    def focal_radius(self, x: Any) -> float:
        """Distance from the point of the parabola above ``x`` to the focus."""
        dy = self.height(x) - self.focal_height
        return math.hypot(x, dy)

    def directrix_distance(self, x: Any) -> Any:
        """Distance from the point of the parabola above ``x`` down to the directrix."""
        return self.height(x) - self.directrix_height

    def subnormal(self, x: Any) -> Any:
        """Rise from the point above ``x`` to where its normal crosses the axis (= lambda)."""
        slope = 2 * self.a * x
        return self.semi_latus_rectum if slope == 0 else x / slope


def parabola_geometry(a: Any) -> ParabolaGeometry:
    """Focus, directrix and latus rectum of y = a x^2 (Figs. 9.3, 9.4; 4 p y = x^2 = 2 lambda y).

    Exact with a ``Fraction`` ``a``; the tip's radius of curvature is (1 + y'^2)^(3/2) / y'' at
    the tip, where y' = 0 and y'' = 2a.
    """
    inputs.positive(a, "a")
    p = 1 / (4 * a)
    lam = 1 / (2 * a)
    directrix = -p
    curvature = 2 * a  # y'' at the tip, where y' = 0
    return ParabolaGeometry(
        a=a,
        focal_height=p,
        semi_latus_rectum=lam,
        focus_to_directrix=p + p,
        directrix_height=directrix,
        tip_to_directrix=0 - directrix,  # the tip is at height 0
        tip_radius_of_curvature=1 / curvature,
        latus_end_slope=2 * a * lam,
        focal_factor=1 / (a * p),
        latus_factor=1 / (a * lam),
    )


def parabola_height_for_focus(p: Any, x: Any) -> Any:
    """Height y above its tip of the point at ``x`` of the parabola whose focus is ``p`` above
    the tip (Fig. 9.3b): the point as far from the focus (0, p) as from the directrix y = -p,
    x^2 + (y - p)^2 = (y + p)^2, so y = x^2 / (4 p). Plain operators (exact, symbolic)."""
    return x * x / (4 * p)


def parabola_height_for_latus(lam: Any, x: Any) -> Any:
    """Height y above its tip of the point at ``x`` of the parabola of semi-latus rectum
    ``lam`` (the half-width at the focus, Fig. 9.4): the focus is at p = lam / 2, so
    y = x^2 / (4 p) = x^2 / (2 lam)."""
    return parabola_height_for_focus(lam / 2, x)


def equidistant_height(p: float, x: float) -> float:
    """Height y of the point at ``x`` that is as far from the focus (0, p) as from the
    directrix y = -p (the parabola's definition, Fig. 9.3b), found as the root of
    |(x, y) - (0, p)| - (y + p), which is positive at y = 0 and negative far above (it tends
    to -2p): a check of 4 p y = x^2 that does not use it. Floats; p > 0."""
    inputs.positive(p, "p")

    def excess(y: float) -> float:
        return math.hypot(x, y - p) - (y + p)

    if excess(0.0) <= 0:
        return 0.0  # x = 0: the tip
    top = p
    while excess(top) > 0:
        top *= 2
    return float(optimize.brentq(excess, 0.0, top, xtol=1e-15, rtol=4 * sys.float_info.epsilon))


def equidistant_height_for_latus(lam: float, x: float) -> float:
    """``equidistant_height`` for the parabola of semi-latus rectum ``lam``: at the focus's
    height the distance to the directrix is 2p, so the points there are 2p across: p = lam/2."""
    return equidistant_height(lam / 2, x)


def parabola_for_focus(p: Any) -> ParabolaGeometry:
    """The focus-directrix geometry of the parabola whose focus is ``p`` above its tip
    (Figs. 9.3-9.4): y = a x^2 with a its height at x = 1 (``parabola_height_for_focus``).
    Exact with a ``Fraction``."""
    inputs.positive(p, "p")
    return parabola_geometry(parabola_height_for_focus(p, 1))


def parabola_for_latus(lam: Any) -> ParabolaGeometry:
    """The geometry of the parabola y = a x^2 whose half-width at the focus is ``lam`` (the
    book's lambda): the points lam across are at the focus's height, a lam^2 = 1/(4a)
    (``parabola_geometry``'s focal height), so a = 1/(2 lam). Exact with a ``Fraction``."""
    inputs.positive(lam, "lam")
    return parabola_geometry(1 / (lam + lam))


def parabola_slope_for_focus(p: Any, x: Any) -> float:
    """Slope dy/dx at ``x`` of the parabola whose focus is ``p`` above its tip, by the complex
    step on its height (``parabola_height_for_focus``): the x/lambda = x/(2p) of Fig. 9.4."""
    inputs.positive(p, "p")
    inputs.real(x, "x")
    return complex_step_derivative(lambda u: parabola_height_for_focus(p, u), x)


@dataclass(frozen=True)
class UnitSlopePoint:
    """The point of slope 1 of a parabola (Figs. 9.4, 9.7): its distance ``x`` across from the
    axis and its distance ``focal_distance`` from the focus."""

    x: float
    focal_distance: float


def parabola_unit_slope_point(p: Any) -> UnitSlopePoint:
    """Where the parabola whose focus is ``p`` above its tip has slope 1: the slope is
    proportional to x (``parabola_slope_for_focus``), so x = 1 / (slope at x = 1); its distance
    from the focus follows from the point's height (``ParabolaGeometry.focal_radius``)."""
    x = 1 / parabola_slope_for_focus(p, 1)
    return UnitSlopePoint(x, parabola_for_focus(p).focal_radius(x))


def focal_drop_angle(slope: Any) -> float:
    """Angle between the focal radius and the vertical drop line to the directrix at the point of
    the parabola whose tangent has slope ``slope``, radians (Figs. 9.4, 9.7).

    The tangent bisects that angle (the reflection law of the parabola): the drop line makes
    pi/2 - atan(slope) with the tangent, so the angle is twice that. Slope 1 gives the right
    angle of the square kite ("twice 45 degrees gives 90").
    """
    return 2 * (math.pi / 2 - line_angle(slope))


# --- Coulomb's law, power-law calculus, sizes (9.1)-(9.3) ------------------------------------


@dataclass(frozen=True)
class PowerLawCalculus:
    """Derivative and antiderivative of r^n: d/dr r^n = n r^(n-1), integral r^(n+1)/(n+1).

    For n = -1 the antiderivative is the logarithm, not a power: its fields are None.
    """

    exponent: Any
    derivative_coefficient: Any
    derivative_exponent: Any
    antiderivative_exponent: Any
    antiderivative_coefficient: Any


def power_law_calculus(n: Any) -> PowerLawCalculus:
    """Calculus of the power r^n used in (9.2b)-(9.2c): U ~ r^-1 gives F ~ r^-2 and back."""
    inputs.real(n, "n")
    if n == -1:  # the antiderivative of 1/r is ln r
        return PowerLawCalculus(n, n, n - 1, None, None)
    return PowerLawCalculus(n, n, n - 1, n + 1, 1 / (n + 1))


def coulomb_force(k: Any, q1: Any, q2: Any, r: Any) -> Any:
    """Coulomb force k q1 q2 / r^2 between two charges ``r`` apart, N ((9.1); repulsive > 0)."""
    inputs.positive(k, "k")
    inputs.positive(r, "r")
    return k * q1 * q2 / (r * r)


def coulomb_energy(k: Any, q1: Any, q2: Any, r: Any) -> Any:
    """Coulomb potential energy k q1 q2 / r of two charges ``r`` apart, J ((9.2a))."""
    inputs.positive(k, "k")
    inputs.positive(r, "r")
    return k * q1 * q2 / r


def coulomb_force_from_potential(q1: Any, q2: Any, epsilon0: Any, r: Any) -> Any:
    """Coulomb force F = -dU/dr at ``r`` from the potential U = q1 q2 r^-1 / (4 pi eps0) of
    (9.2a), by the power rule (``power_law_calculus``): (9.2b). N for SI inputs."""
    inputs.positive(epsilon0, "epsilon0")
    inputs.positive(r, "r")
    constant = q1 * q2 / (4 * math.pi * epsilon0)
    calculus = power_law_calculus(-1)  # U ~ r^-1
    return -constant * calculus.derivative_coefficient * r**calculus.derivative_exponent


def coulomb_potential_from_force(q1: Any, q2: Any, epsilon0: Any, r: Any) -> Any:
    """Coulomb potential U(R) = -integral from infinity to R of the force F = q1 q2 r^-2 /
    (4 pi eps0) of (9.1), by the power rule (``power_law_calculus``; the antiderivative
    vanishes at infinity): (9.2c). J for SI inputs."""
    inputs.positive(epsilon0, "epsilon0")
    inputs.positive(r, "r")
    constant = q1 * q2 / (4 * math.pi * epsilon0)
    calculus = power_law_calculus(-2)  # F ~ r^-2
    antiderivative = (
        constant * calculus.antiderivative_coefficient * r**calculus.antiderivative_exponent
    )
    at_infinity = 0  # r^(n+1) with n + 1 < 0
    return -(antiderivative - at_infinity)


def coulomb_energy_ratio(r_near: Any, r_far: Any) -> Any:
    """How many times the Coulomb energy (~ 1/r) of charges ``r_near`` apart exceeds that of the
    same charges ``r_far`` apart: r_far / r_near (the book's atom-to-nucleus estimates)."""
    inputs.positive(r_near, "r_near")
    inputs.positive(r_far, "r_far")
    return coulomb_energy(1, 1, 1, r_near) / coulomb_energy(1, 1, 1, r_far)


def force_constant_ratio(k: Any, big_g: Any) -> Any:
    """How many times Coulomb's constant k exceeds Newton's G in mks units (after (9.3))."""
    inputs.positive(k, "k")
    inputs.positive(big_g, "G")
    return k / big_g


def sphere_area(radius: Any) -> float:
    """Area 4 pi r^2 of a sphere of radius ``radius`` (the bang-ball count falls off as 1/area)."""
    inputs.positive(radius, "radius")
    return 4 * math.pi * radius**2


def sphere_volume(radius: Any) -> float:
    """Volume 4 pi r^3 / 3 of a ball of radius ``radius`` (a nucleus, a uniform Earth)."""
    inputs.positive(radius, "radius")
    return 4 * math.pi * radius**3 / 3


def inverse_square(r: Any) -> Any:
    """1 / r^2, the inverse-square factor at distance ``r`` (m^-2 for r in m)."""
    inputs.positive(r, "r")
    return 1 / (r * r)


def gravitational_force(big_g: Any, m1: Any, m2: Any, r: Any) -> Any:
    """Newton's attraction G m1 m2 / r^2 between masses ``r`` apart, N (magnitude of (9.3))."""
    inputs.positive(big_g, "G")
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    return big_g * m1 * m2 * inverse_square(r)


def inside_mass(density: Any, r: Any) -> Any:
    """Mass M< inside the radius ``r`` of a uniform ball of ``density``: the density times the
    ball's volume (``sphere_volume``), kg ((9.4a))."""
    return mass_of(density, sphere_volume(r))


def inside_gravity_force(big_g: Any, density: Any, mass: Any, r: Any) -> Any:
    """Pull on ``mass`` at radius ``r`` inside a uniform ball of ``density``: Newton's law
    (``gravitational_force``) with only the mass M< inside r (the shells outside cancel, Fig.
    9.6), N ((9.4a))."""
    return gravitational_force(big_g, mass, inside_mass(density, r), r)


def uniform_surface_gravity(big_g: Any, density: Any, radius: Any) -> Any:
    """Surface gravity g of a uniform ball of ``density`` and ``radius``: the pull on a unit
    mass at r = R (``inside_gravity_force``), m/s^2 ((9.4b))."""
    return inside_gravity_force(big_g, density, 1, radius)


def gravitational_constant_unit(newton: Any, metre: Any, kilogram: Any) -> Any:
    """The unit of Newton's constant G: Newton's law F = G M m / r^2 (9.3) solved for G,
    G = F r^2 / (M m), with each quantity replaced by its unit (N m^2/kg^2). Plain operators:
    give sympy symbols for a symbolic unit, or numbers for a change of units."""
    force, distance, mass = newton, metre, kilogram
    return force * distance * distance / (mass * mass)


def coulomb_constant_unit(joule: Any, metre: Any, coulomb: Any) -> Any:
    """The unit of Coulomb's constant 1/(4 pi eps0): the potential energy U = k q Q / r (9.2a)
    solved for k, k = U r / (q Q), with each quantity replaced by its unit (J m/C^2). Plain
    operators (symbolic with sympy symbols)."""
    energy, distance, charge = joule, metre, coulomb
    return energy * distance / (charge * charge)


# --- nuclear matter and the neutron starlet -------------------------------------------------


def nucleus_mass(nucleons: Any, nucleon_mass: Any) -> Any:
    """Mass of a nucleus of ``nucleons`` nucleons of ``nucleon_mass`` each, kg."""
    inputs.positive(nucleons, "nucleons")
    inputs.mass(nucleon_mass, "nucleon_mass")
    return nucleons * nucleon_mass


def density(mass: Any, volume: Any) -> Any:
    """Density mass / volume, kg/m^3 (nuclear matter: a nucleus's mass over its volume)."""
    inputs.mass(mass, "mass")
    inputs.positive(volume, "volume")
    return mass / volume


def ball_density(mass: Any, radius: Any) -> Any:
    """Mean density of a ball of ``mass`` (kg) and ``radius`` (m), mass / (4 pi r^3 / 3),
    kg/m^3: a nucleus's mass over the volume its radius gives (Ch. 9, nuclear matter)."""
    inputs.mass(mass, "mass")
    return density(mass, sphere_volume(radius))


def mass_as_dense_as(mass: Any, radius: Any, volume: Any) -> Any:
    """Mass (kg) of ``volume`` (m^3) of matter as dense as a ball of ``mass`` (kg) and
    ``radius`` (m): a fingertip of nuclear matter (Ch. 9, the neutron starlet)."""
    return mass_of(ball_density(mass, radius), volume)


def mass_of(density: Any, volume: Any) -> Any:
    """Mass of ``volume`` of matter of ``density``, kg (a fingertip of nuclear matter)."""
    inputs.positive(density, "density")
    inputs.positive(volume, "volume")
    return density * volume


def weight(mass: Any, g: Any) -> Any:
    """Weight m g of a mass at the Earth's surface, N."""
    inputs.mass(mass, "mass")
    inputs.positive(g, "g")
    return mass * g


# --- a uniform Earth: field, potential, energy (9.4), Fig. 9.7 -------------------------------


def gravity_field(g: Any, radius: Any, r: Any) -> Any:
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


def gravity_potential(g: Any, radius: Any, r: Any) -> Any:
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


def potential_energy(mass: Any, g: Any, radius: Any, r: Any) -> Any:
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

    surface: Any
    quadratic: Any
    offset: Any
    quadratic_divisor: Any
    offset_over_quadratic: Any
    surface_potential: Any
    surface_force: Any
    surface_slope: Any
    centre_potential: Any


def interior_potential(surface: Any) -> InteriorPotential:
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

    value: Any
    spring: Any


def interior_potential_at(surface: Any, x: Any) -> InteriorCurve:
    """The parabolic potential inside a uniform planet (``interior_potential``) at ``x``, with
    |x| <= ``surface`` (GM = 1 units: the book's y = x^2/2 - 3/2 for surface = 1)."""
    pot = interior_potential(surface)
    inputs.real(x, "x")
    if abs(x) > surface:
        raise ValueError("the point is outside the planet: |x| <= surface")
    spring = pot.quadratic * x * x
    return InteriorCurve(spring + pot.offset, spring)


def starlet_energy(mass: Any, g: Any, radius: Any, r: Any, speed: Any) -> Any:
    """Total energy KE + PE of a starlet of ``mass`` moving at ``speed`` at distance ``r`` from
    the centre of a uniform planet (``potential_energy``, zero at infinity), J ((9.5)-(9.7))."""
    inputs.real(speed, "speed")
    return mass * speed * speed / 2 + potential_energy(mass, g, radius, r)


def centre_speed_squared(g: Any, radius: Any) -> Any:
    """Square of the speed at the centre of a starlet dropped from rest at the surface: twice
    the potential drop per unit mass from R to 0 (``gravity_potential``), m^2/s^2 ((9.7))."""
    drop = gravity_potential(g, radius, radius) - gravity_potential(g, radius, 0)
    return 2 * drop


def interior_parabola(surface: Any) -> ParabolaGeometry:
    """The focus-directrix geometry of the interior potential's parabola (Fig. 9.7): its x^2
    coefficient from ``interior_potential`` (GM = 1 units) in ``parabola_geometry``."""
    return parabola_geometry(interior_potential(surface).quadratic)


@dataclass(frozen=True)
class EscapeLadder:
    """The starlet's energy (per unit mass, GM = 1 units) on its way out of the planet: at rest
    at the centre, at rest on the surface, in the grazing circular orbit, and just escaping
    (zero at infinity); ``steps`` are the three energy jumps between them, and
    ``equal_steps`` the climb from the centre to escape counted in jumps of the first step."""

    centre: Any
    surface_rest: Any
    orbit: Any
    escape: Any
    steps: tuple[Any, Any, Any]
    equal_steps: Any


def escape_ladder(surface: Any) -> EscapeLadder:
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
    escape_factor: Any


def circular_orbit_speed(g: Any, radius: Any) -> float:
    """Speed of a circular orbit at the surface, v0 = sqrt(g R) (eq. (9.7b)).

    Also the speed a starlet dropped from the surface has at the centre: (9.5)-(9.7a) give
    v^2 = g R from U(0) - U(R) = -g R / 2 per unit mass.
    """
    inputs.positive(g, "g")
    inputs.positive(radius, "radius")
    return math.sqrt(g * radius)


def escape_speed(g: Any, radius: Any) -> float:
    """Escape speed from the surface, sqrt(2 g R): the kinetic energy that lifts the potential
    -g R to zero ((9.11a))."""
    inputs.positive(g, "g")
    inputs.positive(radius, "radius")
    kinetic_needed = -gravity_potential(g, radius, radius)  # per unit mass
    return math.sqrt(2 * kinetic_needed)


def escape_speed_from_orbit_speed(orbit_speed: Any) -> float:
    """Escape speed Ve = v0 sqrt(2) from the grazing orbit speed v0 ((9.11a), the book's step)."""
    inputs.positive(orbit_speed, "orbit_speed")
    return orbit_speed * math.sqrt(2)


def escape_speed_of_orbit(orbit_speed: Any) -> float:
    """Escape speed from a planet's surface given its grazing orbit speed v0, by energies: the
    circular orbit has v0^2 = GM/R (gravity supplies the centripetal pull) and escape needs the
    kinetic energy GM m/R that lifts the potential -GM m/R to zero ((9.11a))."""
    inputs.positive(orbit_speed, "orbit_speed")
    gm_over_r = orbit_speed * orbit_speed
    kinetic_per_mass = gm_over_r
    return math.sqrt(2 * kinetic_per_mass)  # 1/2 v^2 = the kinetic energy per unit mass


def escape_speed_gm(big_g: Any, mass: Any, radius: Any) -> float:
    """Escape speed from the surface of a body of ``mass`` and ``radius``: ``escape_speed``
    with the surface gravity g = G M / R^2 ((9.11b); with the speed of light, (9.12a))."""
    inputs.positive(big_g, "G")
    inputs.mass(mass, "mass")
    inputs.positive(radius, "radius")
    return escape_speed(big_g * mass / (radius * radius), radius)


def black_hole_radius(big_g: Any, mass: Any, c: Any) -> float:
    """Radius at which the escape speed from a body of ``mass`` is ``c`` ((9.12b)): the escape
    speed squared falls as 1/R (``escape_speed_gm``), so R = 1 (v_e(1)/c)^2 in the units of R."""
    inputs.positive(c, "c")
    at_unit_radius = escape_speed_gm(big_g, mass, 1)
    return (at_unit_radius / c) ** 2


def surface_speeds(g: Any, radius: Any) -> SurfaceSpeeds:
    """The orbit and escape speeds at the surface and their ratios ((9.7b), (9.11))."""
    v0 = circular_orbit_speed(g, radius)
    ve = escape_speed(g, radius)
    return SurfaceSpeeds(v0, ve, ve / v0, v0 / ve, ve * ve / (g * radius))


def schwarzschild_radius(big_g: Any, mass: Any, c: Any) -> Any:
    """Radius 2 G M / c^2 at which the escape speed sqrt(2GM/R) is the speed of light, m
    ((9.12))."""
    inputs.positive(big_g, "G")
    inputs.mass(mass, "mass")
    inputs.positive(c, "c")
    return 2 * big_g * mass / (c * c)


# --- tunnels and orbits: the 84-minute Earth (Fig. 9.8, (9.8)-(9.10)) -------------------------


def tunnel_period(g: Any, radius: Any) -> float:
    """Period of a full oscillation through any straight tunnel, 2 pi sqrt(R / g) (eq. (9.8)).

    It does not depend on the chord: every tunnel is a harmonic oscillator with the same
    frequency sqrt(g / R).
    """
    inputs.positive(g, "g")
    inputs.positive(radius, "radius")
    return 2 * math.pi * math.sqrt(radius / g)


def tunnel_transit_time(g: Any, radius: Any) -> float:
    """Time to fall through a tunnel to the far end, half a period: pi sqrt(R / g) (Fig. 9.8)."""
    return tunnel_period(g, radius) / 2


def round_trip_time(transit: Any) -> Any:
    """A full tunnel period from a one-way transit time: there and back, twice the transit
    (the 84-minute period from the 42 minutes of Fig. 9.8), in the transit's unit."""
    inputs.positive(transit, "transit")
    return 2 * transit


def circular_orbit_period(g: Any, radius: Any) -> float:
    """Period 2 pi R / v0 of the grazing circular orbit (Fig. 9.8)."""
    return 2 * math.pi * radius / circular_orbit_speed(g, radius)


def orbit_meeting_fraction(g: Any, radius: Any) -> float:
    """Fraction of its orbit the grazing satellite covers while a body falls through the tunnel
    to the far side: the two meet "1/2-way around" (Fig. 9.8)."""
    return tunnel_transit_time(g, radius) / circular_orbit_period(g, radius)


def chord_acceleration(g: Any, radius: Any, offset: Any, s: Any) -> Any:
    """Acceleration along a straight tunnel (a chord passing ``offset`` from the centre) of a
    body at ``s`` from the chord's midpoint, m/s^2.

    The field inside points to the centre with strength g r / R; its component along the chord
    is -g s / R whatever the offset: every chord is the same harmonic oscillator.
    """
    inputs.positive(radius, "radius")
    inputs.real(offset, "offset")
    inputs.real(s, "s")
    r = math.hypot(offset, s)
    if r > radius * (1 + 8 * sys.float_info.epsilon):  # a chord's ends may round just outside
        raise ValueError("the point is outside the Earth: a tunnel runs inside it")
    if r == 0:
        return 0.0
    return gravity_field(g, radius, r) * s / r


def chord_tunnel_period(g: Any, radius: Any, offset: Any) -> float:
    """Period of a body sliding without friction through a chord passing ``offset`` from the
    centre: 2 pi / sqrt(-a(s)/s), the same for every chord (the synchrony of Fig. 9.8)."""
    inputs.positive(radius, "radius")
    inputs.real(offset, "offset")
    if not abs(offset) < radius:
        raise ValueError("a chord passes inside the Earth: |offset| < radius")
    half_chord = math.sqrt(radius * radius - offset * offset)
    stiffness = -chord_acceleration(g, radius, offset, half_chord) / half_chord
    return 2 * math.pi / math.sqrt(stiffness)


def chord_tunnel_position(g: Any, radius: Any, offset: Any, t: Any) -> tuple[float, float]:
    """Position s and velocity ds/dt, at time ``t``, of a body released at rest at the end of a
    chord passing ``offset`` from the centre (m, m/s): s = s0 cos(w t), w = 2 pi / period."""
    omega = 2 * math.pi / chord_tunnel_period(g, radius, offset)
    half_chord = math.sqrt(radius * radius - offset * offset)
    return half_chord * math.cos(omega * t), -half_chord * omega * math.sin(omega * t)


def chord_length(radius: Any, angle: Any) -> float:
    """Length 2 R sin(angle/2) of the straight tunnel between two surface points ``angle``
    (radians) apart as seen from the centre (exercise 1.9.4: R sqrt(2) for 90 degrees)."""
    inputs.positive(radius, "radius")
    inputs.real(angle, "angle")
    return 2 * radius * math.sin(angle / 2)


def time_zones(longitude: Any, hours_per_day: Any) -> float:
    """Number of hourly time zones spanned by ``longitude`` (radians): one per 2 pi / 24."""
    inputs.real(longitude, "longitude")
    inputs.positive(hours_per_day, "hours_per_day")
    return longitude / (2 * math.pi / hours_per_day)


# --- the isotropic 2-D oscillator: the starlet's orbits (9.8)-(9.15) -------------------------


@dataclass(frozen=True)
class OscillatorState:
    """Position, velocity, per-unit-mass energies of each dimension (ex, ey of (9.10)) and the
    angular momentum per unit mass x vy - y vx of an isotropic 2-D oscillator."""

    x: float
    y: float
    vx: float
    vy: float
    energy_x: float
    energy_y: float
    angular_momentum: float


def oscillator_orbit(
    omega: Any, amp_x: Any, amp_y: Any, phase_x: Any, phase_y: Any, t: Any
) -> OscillatorState:
    """State at time ``t`` of the isotropic oscillator x = X cos(w t + ax), y = Y cos(w t + ay)
    (force -m w^2 r: F = -kr implies Fx = -kx, Fy = -ky (9.15)).

    Equal amplitudes and a quarter-period lag give a circle ((9.13), the starlet of Fig. 9.8);
    zero lag a straight line (9.14); any other lag an inclined ellipse (Fig. 9.10b).
    """
    inputs.positive(omega, "omega")
    for value, name in ((amp_x, "amp_x"), (amp_y, "amp_y"), (phase_x, "phase_x")):
        inputs.real(value, name)
    inputs.real(phase_y, "phase_y")
    inputs.real(t, "t")
    x = amp_x * math.cos(omega * t + phase_x)
    y = amp_y * math.cos(omega * t + phase_y)
    vx = -amp_x * omega * math.sin(omega * t + phase_x)
    vy = -amp_y * omega * math.sin(omega * t + phase_y)
    ex = (vx * vx + omega * omega * x * x) / 2
    ey = (vy * vy + omega * omega * y * y) / 2
    return OscillatorState(x, y, vx, vy, ex, ey, x * vy - y * vx)


def oscillator_amplitude(energy: Any, stiffness: Any) -> float:
    """Amplitude X of an oscillator of energy E whose potential is 1/2 k x^2: at the turning
    point all the energy is potential, 1/2 k X^2 = E ((9.8b))."""
    inputs.positive(energy, "energy")
    inputs.positive(stiffness, "stiffness")
    return math.sqrt(energy / (stiffness / 2))


def phase_velocity(energy: Any, stiffness: Any, omega: Any, theta: Any) -> float:
    """Velocity v = dx/dt = (dtheta/dt) (dx/dtheta) of the oscillator x = X sin(theta) of
    energy E (``oscillator_amplitude``), whose phase turns at the rate ``omega`` ((9.9a))."""
    inputs.real(omega, "omega")
    inputs.real(theta, "theta")
    amplitude = oscillator_amplitude(energy, stiffness)
    dx_dtheta = amplitude * math.cos(theta)  # d/dtheta of X sin(theta)
    return omega * dx_dtheta


@dataclass(frozen=True)
class PhaseState:
    """Position and velocity of an oscillator of energy E, stiffness k and mass m at phase
    theta ((9.8b)-(9.9)): x = X sin(theta), v = dx/dt, and the phase rate omega."""

    x: float
    v: float
    omega: float


def oscillator_phase_state(energy: Any, stiffness: Any, mass: Any, theta: Any) -> PhaseState:
    """The oscillator of ``energy``, ``stiffness`` and ``mass`` at phase ``theta``: x = X
    sin(theta) with 1/2 k X^2 = E, and v = omega dx/dtheta with omega^2 = k / m, the rate
    at which m x'' = -k x turns the phase of x = X sin(omega t + alpha) ((9.8)-(9.9))."""
    inputs.mass(mass, "mass")
    inputs.real(theta, "theta")
    amplitude = oscillator_amplitude(energy, stiffness)
    omega = math.sqrt(stiffness / mass)
    return PhaseState(
        amplitude * math.sin(theta), phase_velocity(energy, stiffness, omega, theta), omega
    )


def oscillator_total_energy(mass: Any, stiffness: Any, x: Any, y: Any, vx: Any, vy: Any) -> Any:
    """Total energy of the isotropic 2-D oscillator at (x, y) with velocity (vx, vy): kinetic
    1/2 m |v|^2 plus the potential 1/2 k |r|^2 of the linear force F = -k r ((9.10), (9.15)).
    Plain operators (exact, symbolic)."""
    kinetic = mass * (vx * vx + vy * vy) / 2
    potential = stiffness * (x * x + y * y) / 2
    return kinetic + potential


def oscillator_initial_phase(x0: Any, amplitude: Any) -> float:
    """Initial phase alpha with x = X sin(alpha) = x0 at t = 0 ((9.8b), theta = w t + alpha):
    starting at the top of the swing, x0 = X, needs alpha = pi/2 (the clock of Fig. 9.10a)."""
    inputs.positive(amplitude, "amplitude")
    inputs.real(x0, "x0")
    if abs(x0) > amplitude:
        raise ValueError("the start lies outside the swing: |x0| <= amplitude")
    return math.asin(x0 / amplitude)


def clock_hour(hour: Any, lead: Any, clock_hours: Any) -> Any:
    """The hour ``lead`` hours after ``hour`` on a clock of ``clock_hours`` hours, written from
    -clock/2 (exclusive) to clock/2 as Fig. 9.10b labels its dials (8 then -7 on 16 hours)."""
    clock = inputs.count(clock_hours, "clock_hours", minimum=1)
    inputs.real(hour, "hour")
    inputs.real(lead, "lead")
    later = (hour + lead) % clock
    return later - clock if later > Fraction(clock, 2) else later


@dataclass(frozen=True)
class PhaseLag:
    """A relative phase lag of two oscillator dimensions: radians, hours on the clock, fraction
    of a period, and the lag with the leads switched (Figs. 9.10b, 9.11)."""

    radians: Any
    hours: Any
    period_fraction: Any
    reversed: Any


def phase_lag(angle: Any, clock_hours: Any) -> PhaseLag:
    """The lag ``angle`` (radians) as hours of a ``clock_hours`` clock and as a fraction of the
    period; switching the leads reverses its sign (right- vs left-handed orbits)."""
    inputs.real(angle, "angle")
    inputs.positive(clock_hours, "clock_hours")
    fraction = angle / (2 * math.pi)
    return PhaseLag(angle, fraction * clock_hours, fraction, -angle)


def points_per_orbit(period: Any, step: Any) -> Any:
    """Number of points of an orbit drawn one per ``step`` over one ``period`` (exercise 1.9.5)."""
    period = inputs.count(period, "period", minimum=1)
    step = inputs.count(step, "step", minimum=1)
    if period % step:
        raise ValueError("the period is not a whole number of steps")
    return period // step


def shell_pair_pull(solid_angle: Any, near: Any, far: Any) -> Any:
    """Net pull on you of the two shell elements cut by a narrow cone of sight (Fig. 9.6): the
    near element m = A d^2 at distance d, the far one M = A D^2 at D, pulling opposite ways,
    G m / d^2 - G M / D^2 (G = 1). Zero for any d and D: no gravity inside a shell."""
    inputs.positive(solid_angle, "solid_angle")
    inputs.positive(near, "near")
    inputs.positive(far, "far")
    m_near = solid_angle * near * near
    m_far = solid_angle * far * far
    return m_near * inverse_square(near) - m_far * inverse_square(far)
