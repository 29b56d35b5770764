"""Kinetic energy in velocities, quasi-velocities and momenta: (12.1)-(12.9), Figs. 12.1-12.2.

The Lagrangian L(v) = sum m_k v_k^2/2 (12.3, ``mechmodel.ellipse.kinetic_energy``), the
"Estrangian" E(V) = sum V_k^2/2 of the quasi-velocities V_k = sqrt(m_k) v_k (12.1), (12.5), and
the Hamiltonian H(p) = sum p_k^2/(2 m_k) of the momenta p_k = m_k v_k (12.2), (12.4); the
root-mass matrix R = M^(1/2) with M = R^2, M^-1 = R^-2 (12.9); the slopes of the collision
line, tangent and COM bisector in the three planes (Fig. 12.1) and the radii of the energy
ellipses (Fig. 12.2). SI units (kg, m/s, kg m/s, J) or the book's scaled units. Exact for
``int`` and ``Fraction`` where no root is needed.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from mechmodel import inputs
from mechmodel.algebra import Laurent
from mechmodel.ellipse import kinetic_energy, momentum_radius, velocity_radius
from mechmodel.exact import exact_sqrt, magnitude
from mechmodel.lagrange._common import _power, _same_length, _sqrt
from mechmodel.typing import Real, Vector


def quasi_velocities(masses: Vector, velocities: Vector) -> list[Real]:
    """Mass-scaled velocities V_k = sqrt(m_k) v_k (12.1), the coordinates in which the energy
    ellipse is a circle (Fig. 12.1b); kg^(1/2) m/s."""
    _same_length(masses, velocities)
    return [
        _sqrt(inputs.mass(m)) * inputs.real(v, "velocity")
        for m, v in zip(masses, velocities, strict=True)
    ]


def momenta(masses: Vector, velocities: Vector) -> list[Real]:
    """Momenta p_k = m_k v_k (12.2), kg m/s. Exact for ``int`` and ``Fraction``."""
    _same_length(masses, velocities)
    return [
        inputs.mass(m) * inputs.real(v, "velocity") for m, v in zip(masses, velocities, strict=True)
    ]


def estrangian(quasi: Vector) -> Real:
    """E(V) = sum_k V_k^2 / 2 (12.5): the kinetic energy as a function of V."""
    return sum(inputs.real(x, "V") ** 2 for x in quasi) / 2


def hamiltonian_free(masses: Vector, momenta_: Vector) -> Real:
    """H(p) = sum_k p_k^2 / (2 m_k) (12.4): the kinetic energy as a function of momenta."""
    _same_length(masses, momenta_)
    return (
        sum(
            inputs.real(p, "momentum") ** 2 / inputs.mass(m)
            for m, p in zip(masses, momenta_, strict=True)
        )
        / 2
    )


@dataclass(frozen=True)
class RootMassPowers:
    """Powers of the root-mass matrix R = M^(1/2) that map velocities to momenta and back."""

    momentum: int  # p = R^momentum . v, so M = R^momentum
    velocity: int  # v = R^velocity . p, so M^-1 = R^velocity


def root_mass_powers() -> RootMassPowers:
    """(12.9): V = R.v and p = R.V (a second factor sqrt(m): p = m v = sqrt(m) V), so
    M = R^2 and M^-1 = R^-2. Counted by composing the two scalings symbolically."""
    w, v = Laurent.var("w"), Laurent.var("v")
    quasi = w * v  # V = sqrt(m) v
    momentum = w * quasi  # p = sqrt(m) V
    to_momentum = (momentum / v).power("w")
    # v in terms of p: invert p = w^k v
    to_velocity = (v / momentum).power("w")
    return RootMassPowers(momentum=to_momentum, velocity=to_velocity)


def scaled_coordinate_energy(masses: Vector, coordinates: Vector, scale_power: Real) -> Real:
    """The kinetic energy of bodies given by their mass-scaled coordinates u_k = m_k^s v_k:
    each velocity is recovered as v_k = u_k m_k^-s and put into L(v) = sum m_k v_k^2/2 (12.3).
    s = 1/2 gives the energy in the quasi-velocities V (12.1), s = 1 in the momenta p (12.2).
    Exact for ``int`` and ``Fraction`` masses when m^s is rational (s = 1); ``scale_power`` is
    a number or a Fraction.
    """
    _same_length(masses, coordinates)
    s = Fraction(scale_power)
    velocities = [
        inputs.real(u, "coordinate") * _power(inputs.mass(m), -s)
        for m, u in zip(masses, coordinates, strict=True)
    ]
    return kinetic_energy(masses, velocities)


@dataclass(frozen=True)
class RootMassMaps:
    """The maps of (12.9) for one body of root mass R = sqrt(m): the momentum p that a unit
    velocity maps to (the mass M) and the velocity v that a unit momentum maps back to
    (the inverse mass M^-1)."""

    mass: Real
    inverse_mass: Real


def root_mass_maps(root_mass: Real) -> RootMassMaps:
    """Compose the root-mass scalings of (12.9) map by map: forward V = R v and p = R V, so a
    unit velocity becomes the momentum R (R 1); back V = p / R and v = V / R, so a unit
    momentum becomes the velocity (1 / R) / R. Exact for ``int`` and ``Fraction``."""
    r = inputs.positive(root_mass, "root_mass")
    if isinstance(r, int):
        r = Fraction(r)
    unit = r**0
    quasi = r * unit  # V = R v at v = 1
    momentum = r * quasi  # p = R V
    back_quasi = unit / r  # V = p / R at p = 1
    velocity = back_quasi / r  # v = V / R
    return RootMassMaps(mass=momentum, inverse_mass=velocity)


@dataclass(frozen=True)
class EllipseSlopes:
    """Slopes (rise over run) of the lines of Fig. 12.1 in the three planes: the collision
    (momentum-conserving) line, the tangent of the energy ellipse at its COM point, and the COM
    bisector (both bodies at the COM velocity), in v (Lagrangian), V (Estrangian) and p
    (Hamiltonian) coordinates. ``*_steepness`` is the magnitude of the collision-line slope
    (the slope triangle drawn on that line)."""

    mass_ratio: Real
    velocity_collision: Real
    velocity_tangent: Real
    velocity_bisector: Real
    quasi_collision: Real
    quasi_tangent: Real
    quasi_bisector: Real
    quasi_steepness: Real
    momentum_collision: Real
    momentum_tangent: Real
    momentum_bisector: Real
    momentum_steepness: Real


def ke_ellipse_slopes(collision_slope: Real) -> EllipseSlopes:
    """The slopes of Fig. 12.1 from the slope -m1/m2 of the collision line in the v1-v2 plane.

    A collision keeps m1 v1 + m2 v2, so it moves (v1, v2) along (m2, -m1); the COM bisector is
    (1, 1). The map to V multiplies the components by sqrt(m_k), the map to p by m_k. The
    tangent of each ellipse at the COM point is normal to the gradient of the energy there
    ((12.10): grad_v L = p, grad_V E = V, grad_p H = v). Exact for a perfect-square ratio.
    """
    inputs.real(collision_slope, "collision_slope")
    ratio = -collision_slope
    inputs.positive(ratio, "mass ratio m1/m2 (minus the collision slope)")
    exact = isinstance(ratio, int | Fraction)
    m1, m2 = (Fraction(ratio), Fraction(1)) if exact else (ratio, 1.0)
    r1, r2 = exact_sqrt(m1), exact_sqrt(m2)

    def slope(dx: Real, dy: Real) -> Real:
        return dy / dx

    def tangent(grad: tuple[Real, Real]) -> Real:
        return slope(grad[1], -grad[0])  # the direction (g2, -g1) is normal to (g1, g2)

    collision_v = (m2, -m1)
    bisector_v = (m2 / m2, m2 / m2)
    com_v = bisector_v  # a COM point: both at the same velocity (any scale)
    grad_l = (m1 * com_v[0], m2 * com_v[1])  # p at the COM point
    com_quasi = (r1 * com_v[0], r2 * com_v[1])  # V at the COM point, grad E = V
    com_p = grad_l
    grad_h = (com_p[0] / m1, com_p[1] / m2)  # v at the COM point, grad H = v
    quasi_collision = slope(r1 * collision_v[0], r2 * collision_v[1])
    momentum_collision = slope(m1 * collision_v[0], m2 * collision_v[1])
    return EllipseSlopes(
        mass_ratio=m1 / m2,
        velocity_collision=slope(*collision_v),
        velocity_tangent=tangent(grad_l),
        velocity_bisector=slope(*bisector_v),
        quasi_collision=quasi_collision,
        quasi_tangent=tangent(com_quasi),
        quasi_bisector=slope(r1 * bisector_v[0], r2 * bisector_v[1]),
        quasi_steepness=magnitude(quasi_collision),
        momentum_collision=momentum_collision,
        momentum_tangent=tangent(grad_h),
        momentum_bisector=slope(m1 * bisector_v[0], m2 * bisector_v[1]),
        momentum_steepness=magnitude(momentum_collision),
    )


@dataclass(frozen=True)
class EllipseRadii:
    """Semi-axes of the energy ellipses L(v) = E (velocity radii sqrt(2E/m_k)) and H(p) = E
    (momentum radii sqrt(2 E m_k)), Fig. 12.2."""

    velocity: list[Real]
    momentum: list[Real]


def energy_ellipse_radii(masses: Vector, energy: Real) -> EllipseRadii:
    """Radii of the L and H ellipses of energy E (Fig. 12.2): L(v) = sum m v^2/2 = E meets the
    v_k axis at sqrt(2E/m_k), H(p) = sum p^2/(2m) = E the p_k axis at sqrt(2E m_k); for each
    axis the H radius is m_k times the L radius."""
    inputs.positive(energy, "energy")
    ms = [inputs.mass(m) for m in masses]
    return EllipseRadii(
        velocity=[velocity_radius(m, energy) for m in ms],
        momentum=[momentum_radius(m, energy) for m in ms],
    )


def ellipse_radius_ratio(mass: Real, energy: Real = 1) -> Real:
    """Ratio of the L(v)-ellipse radius to the H(p)-ellipse radius on one axis for a body of
    mass ``mass`` (Fig. 12.2(d)-(e), where the mass is s times the unit mass): the two radii of
    ``energy_ellipse_radii`` divided, sqrt(2E/m)/sqrt(2Em). Independent of the energy."""
    radii = energy_ellipse_radii([mass], energy)
    return radii.velocity[0] / radii.momentum[0]
