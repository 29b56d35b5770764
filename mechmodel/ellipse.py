"""The kinetic energy of bodies and its level sets, the energy ellipses (chapters 3-5, 8, 12).

Bodies of masses m_k moving at v_k carry the kinetic energy KE = sum 1/2 m_k v_k^2 (3.5b). For
two bodies its level set KE = E in the (V1, V2) plane of their velocities is the energy
ellipse (3.7) with radii a = sqrt(2E/m1) along V1 and b = sqrt(2E/m2) along V2: the ellipse of
Fig. 3.1 that an elastic collision keeps its point on, the bang histories of Figs. 4.7-4.9 and
5.1, the shares of Fig. 8.3. The same energy written in momenta p = m v, H(p) = sum p^2/(2m),
has the radii sqrt(2 E m) (Fig. 12.2). Every model that needs an energy ellipse takes it from
here; ``ellipse_outline`` gives the report's figures the points to draw.

Energies in J (or the book's scaled units), masses in kg, velocities in m/s, radii in the
units of the velocities (momenta for ``momentum_radius``). Plain operators: ``int`` and
``Fraction`` inputs keep the energy exact, and a radius is exact where 2E/m is a rational
square; mpmath inputs keep their precision; otherwise floats.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import overload

from mechmodel import inputs
from mechmodel.exact import exact_sqrt
from mechmodel.typing import Num, Real, Symbolic


def _is_mp(x: object) -> bool:
    return type(x).__module__.startswith("mpmath")


@overload
def kinetic_energy(masses: Sequence[Real], velocities: Sequence[Real]) -> Real: ...
@overload
def kinetic_energy(masses: Sequence[Symbolic], velocities: Sequence[Symbolic]) -> Symbolic: ...
def kinetic_energy(masses: Sequence[Num], velocities: Sequence[Num]) -> Num:
    """Total kinetic energy KE = sum 1/2 m v^2 ((3.5b), the Lagrangian of free bodies (12.3));
    finite masses only.

    The 1/2 is written as a division so that integer and Fraction inputs stay exact.
    """
    return sum(m * v * v for m, v in inputs.bodies(masses, velocities)) / 2


def velocity_radius(mass: Real, energy: Real) -> Real:
    """Radius sqrt(2E/m) of the energy ellipse KE = E along the velocity axis of the body of
    mass m: where that body alone carries the energy, 1/2 m v^2 = E ((3.7b), Fig. 12.2)."""
    inputs.mass(mass, "mass")
    inputs.real(energy, "energy")
    if energy < 0:
        raise ValueError(f"a kinetic energy is not negative, got {energy!r}")
    return exact_sqrt(2 * energy / mass)


def momentum_radius(mass: Real, energy: Real) -> Real:
    """Radius sqrt(2 E m) of the ellipse H(p) = sum p^2/(2m) = E along the momentum axis of the
    body of mass m (Fig. 12.2): m times its velocity radius."""
    inputs.mass(mass, "mass")
    inputs.real(energy, "energy")
    if energy < 0:
        raise ValueError(f"a kinetic energy is not negative, got {energy!r}")
    return exact_sqrt(2 * energy * mass)


def ellipse_radii(m1: Real, m2: Real, energy: Real) -> tuple[Real, Real]:
    """Radii (a, b) = (sqrt(2 KE/m1), sqrt(2 KE/m2)) of the KE ellipse (3.7b).

    ``a`` lies along the V1 axis, ``b`` along V2: 1/2 m1 a^2 = 1/2 m2 b^2 = KE.
    """
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    return (velocity_radius(m1, energy), velocity_radius(m2, energy))


@dataclass(frozen=True)
class EnergyEllipse:
    """The KE ellipse 1/2 m1 V1^2 + 1/2 m2 V2^2 = KE through the point (v1, v2) (Fig. 3.1,
    (3.7); Figs. 4.7c and 4.9).

    ``energy`` is KE and ``twice_energy`` the 2 KE = m1 v1^2 + m2 v2^2 of (3.7b); ``radii`` its
    (a, b), also as ``radius_v1`` and ``radius_v2``; ``minor_radius`` lies along the heavier
    body's velocity. ``tangent_slope`` is the slope of the ellipse at the point: at the COM
    point (V, V) it is the momentum line's -m1/m2, and in the COM frame it is 1 where the
    momentum line cuts the ellipse (Fig. 3.1, the duality of line 2419).
    """

    masses: tuple[Real, Real]
    point: tuple[Real, Real]

    @property
    def energy(self) -> Real:
        """Kinetic energy KE of the point (3.5b)."""
        return kinetic_energy(self.masses, self.point)

    @property
    def twice_energy(self) -> Real:
        """2 KE = m1 v1^2 + m2 v2^2, the right side of (3.7b)."""
        return 2 * self.energy

    @property
    def radii(self) -> tuple[Real, Real]:
        """Radii (a, b) along V1 and V2 (3.7b)."""
        return ellipse_radii(self.masses[0], self.masses[1], self.energy)

    @property
    def radius_v1(self) -> Real:
        """The semi-axis a = sqrt(2 KE/m1) along V1."""
        return self.radii[0]

    @property
    def radius_v2(self) -> Real:
        """The semi-axis b = sqrt(2 KE/m2) along V2."""
        return self.radii[1]

    @property
    def minor_radius(self) -> Real:
        """The shorter semi-axis (along the heavier body's velocity)."""
        return min(self.radii)

    @property
    def major_radius(self) -> Real:
        """The longer semi-axis (along the lighter body's velocity)."""
        return max(self.radii)

    @property
    def tangent_slope(self) -> Real:
        """Slope dV2/dV1 = -m1 v1 / (m2 v2) of the ellipse at the point; ValueError where the
        tangent is vertical (v2 = 0)."""
        (m1, m2), (v1, v2) = self.masses, self.point
        if v2 == 0:
            raise ValueError("the tangent is vertical where V2 = 0")
        return -(m1 * v1) / (m2 * v2)


def energy_ellipse(m1: Real, m2: Real, v1: Real, v2: Real) -> EnergyEllipse:
    """The KE ellipse of bodies m1, m2 through the velocity point (v1, v2) (Fig. 3.1, (3.7))."""
    inputs.bodies((m1, m2), (v1, v2))
    return EnergyEllipse((m1, m2), (v1, v2))


def ellipse_point(a: Real, b: Real, angle: Real) -> tuple[float, float]:
    """Point (a cos s, b sin s) of the ellipse of radii a, b >= 0 at the clock-hand angle s
    (Fig. 11.1; Exercise Figs. 3.6-3.7); radii 0 give the point ellipse of a body at rest."""
    for radius, name in ((a, "a"), (b, "b")):
        inputs.real(radius, name)
        if radius < 0:
            raise ValueError(f"{name} must not be negative, got {radius!r}")
    inputs.real(angle, "angle")
    if _is_mp(angle):
        import mpmath

        return (a * mpmath.cos(angle), b * mpmath.sin(angle))
    return (a * math.cos(angle), b * math.sin(angle))


def ellipse_outline(a: Real, b: Real, points: int = 361) -> tuple[list[float], list[float]]:
    """The closed outline of the ellipse of radii a, b: ``points`` points (a cos s, b sin s)
    at equal steps of s from 0 to 2 pi, as x and y lists of floats for drawing."""
    n = inputs.count(points, "points", minimum=2)
    outline = [ellipse_point(float(a), float(b), 2 * math.pi * k / (n - 1)) for k in range(n)]
    return [x for x, _ in outline], [y for _, y in outline]
