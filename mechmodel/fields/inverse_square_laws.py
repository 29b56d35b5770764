"""Coulomb's and Newton's inverse-square laws, sizes and nuclear matter (chapter 9, (9.1)-(9.4)).

Coulomb's force k q1 q2 / r^2 and potential k q1 q2 / r (9.1)-(9.2), each obtained from the
other by the calculus of r^n; the ratios of sizes and energies of the book's estimates; Newton's
gravity G m1 m2 / r^2 (9.3) and the pull inside a uniform ball (9.4a); the units of G and k
(``Symbolic``: a formula claim calls them with sympy symbols); the density of nuclear matter
and the mass and weight of a fingertip of it (the neutron starlet). SI units.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from mechmodel import inputs
from mechmodel.typing import Real, Symbolic


@dataclass(frozen=True)
class PowerLawCalculus:
    """Derivative and antiderivative of r^n: d/dr r^n = n r^(n-1), integral r^(n+1)/(n+1).

    For n = -1 the antiderivative is the logarithm, not a power: its fields are None.
    """

    exponent: Real
    derivative_coefficient: Real
    derivative_exponent: Real
    antiderivative_exponent: Real | None
    antiderivative_coefficient: Real | None


def power_law_calculus(n: Real) -> PowerLawCalculus:
    """Calculus of the power r^n used in (9.2b)-(9.2c): U ~ r^-1 gives F ~ r^-2 and back."""
    inputs.real(n, "n")
    if n == -1:  # the antiderivative of 1/r is ln r
        return PowerLawCalculus(n, n, n - 1, None, None)
    return PowerLawCalculus(n, n, n - 1, n + 1, 1 / (n + 1))


def coulomb_force(k: Real, q1: Real, q2: Real, r: Real) -> Real:
    """Coulomb force k q1 q2 / r^2 between two charges ``r`` apart, N ((9.1); repulsive > 0)."""
    inputs.positive(k, "k")
    inputs.positive(r, "r")
    return k * q1 * q2 / (r * r)


def coulomb_energy(k: Real, q1: Real, q2: Real, r: Real) -> Real:
    """Coulomb potential energy k q1 q2 / r of two charges ``r`` apart, J ((9.2a))."""
    inputs.positive(k, "k")
    inputs.positive(r, "r")
    return k * q1 * q2 / r


def coulomb_force_from_potential(q1: Real, q2: Real, epsilon0: Real, r: Real) -> Real:
    """Coulomb force F = -dU/dr at ``r`` from the potential U = q1 q2 r^-1 / (4 pi eps0) of
    (9.2a), by the power rule (``power_law_calculus``): (9.2b). N for SI inputs."""
    inputs.positive(epsilon0, "epsilon0")
    inputs.positive(r, "r")
    constant = q1 * q2 / (4 * math.pi * epsilon0)
    calculus = power_law_calculus(-1)  # U ~ r^-1
    return -constant * calculus.derivative_coefficient * r**calculus.derivative_exponent


def coulomb_potential_from_force(q1: Real, q2: Real, epsilon0: Real, r: Real) -> Real:
    """Coulomb potential U(R) = -integral from infinity to R of the force F = q1 q2 r^-2 /
    (4 pi eps0) of (9.1), by the power rule (``power_law_calculus``; the antiderivative
    vanishes at infinity): (9.2c). J for SI inputs."""
    inputs.positive(epsilon0, "epsilon0")
    inputs.positive(r, "r")
    constant = q1 * q2 / (4 * math.pi * epsilon0)
    calculus = power_law_calculus(-2)  # F ~ r^-2
    assert calculus.antiderivative_coefficient is not None  # only r^-1 integrates to a log
    assert calculus.antiderivative_exponent is not None
    antiderivative = (
        constant * calculus.antiderivative_coefficient * r**calculus.antiderivative_exponent
    )
    at_infinity = 0  # r^(n+1) with n + 1 < 0
    return -(antiderivative - at_infinity)


def coulomb_energy_ratio(r_near: Real, r_far: Real) -> Real:
    """How many times the Coulomb energy (~ 1/r) of charges ``r_near`` apart exceeds that of the
    same charges ``r_far`` apart: r_far / r_near (the book's atom-to-nucleus estimates)."""
    inputs.positive(r_near, "r_near")
    inputs.positive(r_far, "r_far")
    return coulomb_energy(1, 1, 1, r_near) / coulomb_energy(1, 1, 1, r_far)


def force_constant_ratio(k: Real, big_g: Real) -> Real:
    """How many times Coulomb's constant k exceeds Newton's G in mks units (after (9.3))."""
    inputs.positive(k, "k")
    inputs.positive(big_g, "G")
    return k / big_g


def sphere_area(radius: Real) -> float:
    """Area 4 pi r^2 of a sphere of radius ``radius`` (the bang-ball count falls off as 1/area)."""
    inputs.positive(radius, "radius")
    return 4 * math.pi * radius**2


def sphere_volume(radius: Real) -> float:
    """Volume 4 pi r^3 / 3 of a ball of radius ``radius`` (a nucleus, a uniform Earth)."""
    inputs.positive(radius, "radius")
    return 4 * math.pi * radius**3 / 3


def inverse_square(r: Real) -> Real:
    """1 / r^2, the inverse-square factor at distance ``r`` (m^-2 for r in m)."""
    inputs.positive(r, "r")
    return 1 / (r * r)


def gravitational_force(big_g: Real, m1: Real, m2: Real, r: Real) -> Real:
    """Newton's attraction G m1 m2 / r^2 between masses ``r`` apart, N (magnitude of (9.3))."""
    inputs.positive(big_g, "G")
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    return big_g * m1 * m2 * inverse_square(r)


def inside_mass(density: Real, r: Real) -> Real:
    """Mass M< inside the radius ``r`` of a uniform ball of ``density``: the density times the
    ball's volume (``sphere_volume``), kg ((9.4a))."""
    return mass_of(density, sphere_volume(r))


def inside_gravity_force(big_g: Real, density: Real, mass: Real, r: Real) -> Real:
    """Pull on ``mass`` at radius ``r`` inside a uniform ball of ``density``: Newton's law
    (``gravitational_force``) with only the mass M< inside r (the shells outside cancel, Fig.
    9.6), N ((9.4a))."""
    return gravitational_force(big_g, mass, inside_mass(density, r), r)


def uniform_surface_gravity(big_g: Real, density: Real, radius: Real) -> Real:
    """Surface gravity g of a uniform ball of ``density`` and ``radius``: the pull on a unit
    mass at r = R (``inside_gravity_force``), m/s^2 ((9.4b))."""
    return inside_gravity_force(big_g, density, 1, radius)


def gravitational_constant_unit(newton: Symbolic, metre: Symbolic, kilogram: Symbolic) -> Symbolic:
    """The unit of Newton's constant G: Newton's law F = G M m / r^2 (9.3) solved for G,
    G = F r^2 / (M m), with each quantity replaced by its unit (N m^2/kg^2). Plain operators:
    give sympy symbols for a symbolic unit, or numbers for a change of units."""
    force, distance, mass = newton, metre, kilogram
    return force * distance * distance / (mass * mass)


def coulomb_constant_unit(joule: Symbolic, metre: Symbolic, coulomb: Symbolic) -> Symbolic:
    """The unit of Coulomb's constant 1/(4 pi eps0): the potential energy U = k q Q / r (9.2a)
    solved for k, k = U r / (q Q), with each quantity replaced by its unit (J m/C^2). Plain
    operators (symbolic with sympy symbols)."""
    energy, distance, charge = joule, metre, coulomb
    return energy * distance / (charge * charge)


# --- nuclear matter and the neutron starlet -------------------------------------------------


def nucleus_mass(nucleons: Real, nucleon_mass: Real) -> Real:
    """Mass of a nucleus of ``nucleons`` nucleons of ``nucleon_mass`` each, kg."""
    inputs.positive(nucleons, "nucleons")
    inputs.mass(nucleon_mass, "nucleon_mass")
    return nucleons * nucleon_mass


def density(mass: Real, volume: Real) -> Real:
    """Density mass / volume, kg/m^3 (nuclear matter: a nucleus's mass over its volume)."""
    inputs.mass(mass, "mass")
    inputs.positive(volume, "volume")
    return mass / volume


def ball_density(mass: Real, radius: Real) -> Real:
    """Mean density of a ball of ``mass`` (kg) and ``radius`` (m), mass / (4 pi r^3 / 3),
    kg/m^3: a nucleus's mass over the volume its radius gives (Ch. 9, nuclear matter)."""
    inputs.mass(mass, "mass")
    return density(mass, sphere_volume(radius))


def mass_as_dense_as(mass: Real, radius: Real, volume: Real) -> Real:
    """Mass (kg) of ``volume`` (m^3) of matter as dense as a ball of ``mass`` (kg) and
    ``radius`` (m): a fingertip of nuclear matter (Ch. 9, the neutron starlet)."""
    return mass_of(ball_density(mass, radius), volume)


def mass_of(density: Real, volume: Real) -> Real:
    """Mass of ``volume`` of matter of ``density``, kg (a fingertip of nuclear matter)."""
    inputs.positive(density, "density")
    inputs.positive(volume, "volume")
    return density * volume


def weight(mass: Real, g: Real) -> Real:
    """Weight m g of a mass at the Earth's surface, N."""
    inputs.mass(mass, "mass")
    inputs.positive(g, "g")
    return mass * g
