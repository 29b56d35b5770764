"""One-dimensional two-body collisions (chapters 2-3).

Velocities are along one line, positive "up" (or "east"); masses in (0, inf]. The restitution
coefficient ``e`` runs from 0 (Ka-runch: the bodies stick, Fig. 2.1) to 1 (Ka-bong: elastic,
eq. (4.1)); in between a collision loses part of the energy available in the centre-of-momentum
frame (Fig. 3.1). Works on floats, ``Fraction`` (exact) and mpmath numbers; units are whatever
the inputs carry (the book's scaled units or SI).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from mechmodel import inputs


@dataclass(frozen=True)
class Collision:
    """A two-body collision: masses, velocities before and after.

    ``momentum``, ``ke_before``, ``ke_after`` and ``ke_lost`` need finite masses.
    """

    masses: tuple[Any, Any]
    before: tuple[Any, Any]
    after: tuple[Any, Any]

    @property
    def v1(self) -> Any:
        """Velocity of body 1 after the collision."""
        return self.after[0]

    @property
    def v2(self) -> Any:
        """Velocity of body 2 after the collision."""
        return self.after[1]

    @property
    def momentum(self) -> Any:
        """Total momentum m1 v1 + m2 v2 (the same before and after, eq. (2.5a))."""
        return momentum(self.masses, self.after)

    @property
    def ke_before(self) -> Any:
        """Total kinetic energy before, sum of 1/2 m v^2 (eq. (3.5b))."""
        return kinetic_energy(self.masses, self.before)

    @property
    def ke_after(self) -> Any:
        """Total kinetic energy after the collision."""
        return kinetic_energy(self.masses, self.after)

    @property
    def ke_lost(self) -> Any:
        """Kinetic energy lost to crumpling (zero when elastic)."""
        return self.ke_before - self.ke_after


def collide(m1: Any, m2: Any, v1: Any, v2: Any, restitution: Any = 1) -> Collision:
    """Collide body 1 (mass ``m1``, velocity ``v1``) with body 2 in one dimension.

    Momentum is conserved and the relative velocity reverses, scaled by the restitution ``e``:
    ``v2' - v1' = e (v1 - v2)``. With ``e = 1`` this is the elastic bang (4.1),
    ``v' = 2 V_COM - v``; with ``e = 0`` both leave at V_COM (Fig. 2.1). An infinite mass (a
    wall, the floor, a ceiling) keeps its velocity and the other body rebounds off it:
    ``v' = u + e (u - v)``. Raises ``ValueError`` for a non-positive or NaN mass, a non-finite
    velocity, ``e`` outside [0, 1], or two infinite masses.
    """
    inputs.mass(m1, "m1", infinite_ok=True)
    inputs.mass(m2, "m2", infinite_ok=True)
    inputs.real(v1, "v1")
    inputs.real(v2, "v2")
    inputs.real(restitution, "restitution")
    if not 0 <= restitution <= 1:
        raise ValueError(f"restitution must be in [0, 1], got {restitution!r}")
    infinite1, infinite2 = inputs.is_infinite(m1), inputs.is_infinite(m2)
    if infinite1 and infinite2:
        raise ValueError("two infinite masses cannot collide")
    if infinite1:
        after = (v1, v1 + restitution * (v1 - v2))
    elif infinite2:
        after = (v2 + restitution * (v2 - v1), v2)
    else:
        total = m1 * v1 + m2 * v2
        closing = v1 - v2
        mass_sum = m1 + m2
        after = (
            (total - m2 * restitution * closing) / mass_sum,
            (total + m1 * restitution * closing) / mass_sum,
        )
    return Collision((m1, m2), (v1, v2), after)


def _pairs(masses: Sequence[Any], velocities: Sequence[Any]) -> list[tuple[Any, Any]]:
    if len(masses) != len(velocities) or not masses:
        raise ValueError("give one velocity per mass (and at least one mass)")
    for i, (m, v) in enumerate(zip(masses, velocities, strict=True), start=1):
        inputs.mass(m, f"masses[{i - 1}]")
        inputs.real(v, f"velocities[{i - 1}]")
    return list(zip(masses, velocities, strict=True))


def momentum(masses: Sequence[Any], velocities: Sequence[Any]) -> Any:
    """Total momentum P = sum m v (eq. (2.5a)); finite masses only."""
    return sum(m * v for m, v in _pairs(masses, velocities))


def kinetic_energy(masses: Sequence[Any], velocities: Sequence[Any]) -> Any:
    """Total kinetic energy KE = sum 1/2 m v^2 (eq. (3.5b)); finite masses only.

    The 1/2 is written as a division so that integer and Fraction inputs stay exact.
    """
    return sum(m * v * v for m, v in _pairs(masses, velocities)) / 2


def center_of_mass_velocity(masses: Sequence[Any], velocities: Sequence[Any]) -> Any:
    """Velocity of the centre of momentum, V_COM = sum m v / sum m (eq. (2.5b))."""
    pairs = _pairs(masses, velocities)
    return sum(m * v for m, v in pairs) / sum(m for m, _ in pairs)
