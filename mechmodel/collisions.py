"""One-dimensional two-body collisions (chapters 2-3).

Velocities are along one line, positive "up" (or "east"); masses in (0, inf]. The restitution
coefficient ``e`` runs from 0 (Ka-runch: the bodies stick, Fig. 2.1) to 1 (Ka-bong: elastic,
eq. (4.1)); in between a collision loses part of the energy available in the centre-of-momentum
frame (Fig. 3.1). Works on floats, ``Fraction`` (exact) and mpmath numbers; units are whatever
the inputs carry (the book's scaled units or SI).

The geometry of chapters 2-3 lives in the velocity-velocity plane (V1, V2) = (V_SUV, V_VW):
a collision moves the point IN to FIN along the momentum line of slope -m1/m2 (2.4), (3.6);
the kinetic energy fixes an ellipse of radii sqrt(2 KE/m1), sqrt(2 KE/m2) (3.7). The kinetic
energy and its ellipse are ``mechmodel.ellipse`` (re-exported here where the catalog names
them). A Galilean frame moving at ``u`` subtracts ``u`` from every velocity (Fig. 2.3-2.5); the
centre-of-momentum (COM) frame is the one moving at V_COM. Square roots stay exact for Fraction
inputs that are perfect squares and are floats otherwise.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Generic, cast, overload

from mechmodel import inputs
from mechmodel.ellipse import EnergyEllipse, kinetic_energy
from mechmodel.ellipse import ellipse_radii as ellipse_radii  # the catalog's collisions.*
from mechmodel.ellipse import energy_ellipse as energy_ellipse
from mechmodel.exact import exact_sqrt
from mechmodel.numeric import line_angle as line_angle
from mechmodel.numeric import line_slope as line_slope
from mechmodel.tensor_forms import TensorForms as TensorForms  # the catalog's collisions.*
from mechmodel.tensor_forms import ellipse_tensor_form as ellipse_tensor_form
from mechmodel.tensor_forms import inertia_coefficient_count as inertia_coefficient_count
from mechmodel.tensor_forms import inertia_tensor as inertia_tensor
from mechmodel.tensor_forms import tensor_energy_forms as tensor_energy_forms
from mechmodel.tensor_forms import tensor_form as tensor_form
from mechmodel.typing import Num, Real, Symbolic, Vector


@dataclass(frozen=True)
class Collision(Generic[Num]):
    """A two-body collision: masses, velocities before and after.

    ``momentum``, ``ke_before``, ``ke_after``, ``ke_lost`` need finite masses. The masses, and
    so the velocities after, may be sympy symbols (the collision matrix (5.1b) as a formula).
    """

    masses: tuple[Num, Num]
    before: tuple[Num, Num]
    after: tuple[Num, Num]

    @property
    def v1(self) -> Num:
        """Velocity of body 1 after the collision."""
        return self.after[0]

    @property
    def v2(self) -> Num:
        """Velocity of body 2 after the collision."""
        return self.after[1]

    @property
    def momentum(self) -> Num:
        """Total momentum m1 v1 + m2 v2 (the same before and after, eq. (2.5a))."""
        return momentum(self.masses, self.after)

    @property
    def ke_before(self) -> Num:
        """Total kinetic energy before, sum of 1/2 m v^2 (eq. (3.5b))."""
        return kinetic_energy(self.masses, self.before)

    @property
    def ke_after(self) -> Num:
        """Total kinetic energy after the collision."""
        return kinetic_energy(self.masses, self.after)

    @property
    def ke_lost(self) -> Num:
        """Kinetic energy lost to crumpling (zero when elastic)."""
        return self.ke_before - self.ke_after

    @property
    def com_velocity(self) -> Num:
        """Velocity V_COM of the centre of momentum (2.5b), the same before and after.

        With an infinite mass (a wall) it is the wall's velocity.
        """
        m1, m2 = self.masses
        if inputs.is_infinite(m1):
            return self.before[0]
        if inputs.is_infinite(m2):
            return self.before[1]
        return center_of_mass_velocity(self.masses, self.before)


@overload
def collide(m1: Real, m2: Real, v1: Real, v2: Real, restitution: Real = 1) -> Collision[Real]: ...
@overload
def collide(
    m1: Symbolic, m2: Symbolic, v1: Real, v2: Real, restitution: Real = 1
) -> Collision[Symbolic]: ...
def collide(m1: Num, m2: Num, v1: Real, v2: Real, restitution: Real = 1) -> Collision[Num]:
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
    after: tuple[Num, Num]
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


@overload
def momentum(masses: Sequence[Real], velocities: Sequence[Real]) -> Real: ...
@overload
def momentum(masses: Sequence[Symbolic], velocities: Sequence[Symbolic]) -> Symbolic: ...
def momentum(masses: Sequence[Num], velocities: Sequence[Num]) -> Num:
    """Total momentum P = sum m v (eq. (2.5a)); finite masses only."""
    return sum(m * v for m, v in inputs.bodies(masses, velocities))


def kinetic_energy_change(m: Real, v_in: Real, v_fin: Real) -> Real:
    """Change KE(v_fin) - KE(v_in) of the kinetic energy of one body of mass ``m`` whose velocity
    goes from ``v_in`` to ``v_fin`` (finite mass): the work done on it, which is what the product
    (3.3)·(3.4) of its momentum change and its IN-FIN average velocity multiplies out to."""
    return kinetic_energy((m,), (v_fin,)) - kinetic_energy((m,), (v_in,))


@overload
def center_of_mass_velocity(masses: Sequence[Real], velocities: Sequence[Real]) -> Real: ...
@overload
def center_of_mass_velocity(
    masses: Sequence[Symbolic], velocities: Sequence[Symbolic]
) -> Symbolic: ...
def center_of_mass_velocity(masses: Sequence[Num], velocities: Sequence[Num]) -> Num:
    """Velocity of the centre of momentum, V_COM = sum m v / sum m (eq. (2.5b))."""
    pairs = inputs.bodies(masses, velocities)
    return sum(m * v for m, v in pairs) / sum(m for m, _ in pairs)


# -- momentum: totals, the zero-sum exchange and the momentum line (chapter 2) ----------------


def total_mass(masses: Vector) -> Real:
    """Total mass M_TOTAL = sum m of the bodies that may crunch into one hunk (Fig. 2.1, (2.5a))."""
    if not masses:
        raise ValueError("give at least one mass")
    for i, m in enumerate(masses):
        inputs.mass(m, f"masses[{i}]")
    return sum(masses)


def momentum_change(masses: Vector, before: Vector, after: Vector) -> Real:
    """Change of total momentum, Delta P_Total = P(after) - P(before) (2.3), (3.2).

    Zero for any collision (the zero-sum game); applied to printed IN and FIN points it checks
    that they lie on one momentum line.
    """
    return momentum(masses, after) - momentum(masses, before)


def momentum_line_slope(m1: Real, m2: Real) -> Real:
    """Slope dV2/dV1 = -m1/m2 of the momentum line in the (V1, V2) plane ((2.4), (3.6b))."""
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    return -m1 / m2


def momentum_exchange_step(m1: Real, m2: Real) -> tuple[Real, Real]:
    """A velocity change (Delta V1, Delta V2) = (-m2, m1) that keeps P = m1 V1 + m2 V2.

    Body 1 loses m2 units of velocity for every m1 units body 2 gains (the zero-sum rule (2.3));
    its direction is that of the momentum line (the book's slope-(-1:4) line of Fig. 2.6a).
    """
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    return (-m2, m1)


def momentum_line_partner(m1: Real, m2: Real, v1: Real, v2: Real, u1: Real) -> Real:
    """V2 of the point with V1 = ``u1`` on the momentum line through (v1, v2) (Fig. 2.6a).

    The line keeps m1 V1 + m2 V2 = m1 v1 + m2 v2, so V2 = v2 - (m1/m2)(u1 - v1); every point on
    it has the same m1:m2 weighted average V_COM (2.5b).
    """
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    for value, name in ((v1, "v1"), (v2, "v2"), (u1, "u1")):
        inputs.real(value, name)
    return v2 - m1 * (u1 - v1) / m2


# -- Galilean frames and reversal (Fig. 2.3-2.5) ------------------------------------------


def shift_frame(velocities: Vector, frame_velocity: Real) -> tuple[Real, ...]:
    """Velocities seen from a frame moving at ``frame_velocity``: v - u (Galilean, Fig. 2.5).

    The cop going at u = V_COM sees the COM frame of Fig. 2.3-2.4.
    """
    inputs.real(frame_velocity, "frame_velocity")
    for i, v in enumerate(velocities):
        inputs.real(v, f"velocities[{i}]")
    return tuple(v - frame_velocity for v in velocities)


def collide_in_frame(
    m1: Real, m2: Real, v1: Real, v2: Real, frame_velocity: Real, restitution: Real = 1
) -> Collision[Real]:
    """The collision of ``collide`` seen from a frame moving at ``frame_velocity``.

    ``v1``, ``v2`` are Earth-frame velocities; the result's ``before`` and ``after`` are frame
    velocities (each Earth value minus u), as in the cop frame of Fig. 2.3-2.4 and the car
    frames VW(I), SUV(F) of Fig. 2.5b. Galilean covariance: colliding the shifted velocities
    gives the shifted result, so the collision is computed in the frame itself.
    """
    w1, w2 = shift_frame((v1, v2), frame_velocity)
    return collide(m1, m2, w1, w2, restitution)


def velocity_reversed(hit: Collision[Num]) -> Collision[Num]:
    """The collision with every velocity negated, V -> -V (reflection through the origin of
    the (V1, V2) plane, the book's reflection through the COM point in Fig. 2.4).

    The collision law is odd in the velocities, so this is again a collision with the same
    restitution.
    """
    return Collision(hit.masses, (-hit.before[0], -hit.before[1]), (-hit.after[0], -hit.after[1]))


def time_reversed(hit: Collision[Num]) -> Collision[Num]:
    """The time-reversed collision (Delta t -> -Delta t): it starts from the reversed outgoing
    velocities and ends at the reversed incoming ones (Fig. 2.4, the reversed video of Fig. 2.2).

    For an elastic collision this is what ``collide`` gives from -FIN; an inelastic one does
    not reverse (the "un-crash" of Fig. 2.1).
    """
    return Collision(hit.masses, (-hit.after[0], -hit.after[1]), (-hit.before[0], -hit.before[1]))


def collide_reversed(
    m1: Real, m2: Real, v1: Real, v2: Real, frame_velocity: Real = 0, restitution: Real = 1
) -> Collision[Real]:
    """The collision that starts from the reversed incoming velocities, in a frame at u.

    Seen from the frame moving at ``frame_velocity``, the incoming velocities (v - u) are
    negated and collided: the book's reversed Ka-bong of Fig. 2.4, initial (-10, 40) to final
    (10, -40) for the cop frame. Equals ``velocity_reversed`` of the forward collision.
    """
    w1, w2 = shift_frame((v1, v2), frame_velocity)
    return collide(m1, m2, -w1, -w2, restitution)


def elastic_final_velocity(v_in: Real, v_com: Real) -> Real:
    """Velocity after an elastic bang of a body that arrives at ``v_in`` while the centre of
    momentum moves at ``v_com`` (the (4.1), (4.3) form of the IN-FIN balance (3.4)).

    In the COM frame the partner's momentum is always the opposite of the body's, so the body
    rebounds as off a wall moving with the COM: an elastic bounce off an infinite mass moving
    at ``v_com`` (``collide``'s wall branch), whatever the partner's mass.
    """
    return collide(1, math.inf, v_in, v_com).v1


def elastic_com_velocity(v_in: Real, v_fin: Real) -> Real:
    """Velocity V_COM of the centre of momentum of an elastic bang that takes a body from
    ``v_in`` to ``v_fin`` (the T-symmetry balance (3.4)).

    It is the frame velocity u at which ``elastic_final_velocity(v_in, u)`` is ``v_fin``; that
    final velocity is linear in u, so u is found from two evaluations of the collision law, not
    from a closed form.
    """
    at_rest = elastic_final_velocity(v_in, 0)
    per_unit = elastic_final_velocity(v_in, 1) - at_rest
    return (v_fin - at_rest) / per_unit


# -- lines, angles and the energy ellipse's form (Fig. 3.1, (3.6)-(3.7)) ----------------------


def energy_ellipse_form(m1: Real, m2: Real, energy: Real, v1: Real, v2: Real) -> Real:
    """The left side V1^2/(2 KE/m1) + V2^2/(2 KE/m2) of the KE ellipse (3.7a) at the point
    (v1, v2): the kinetic energy of that point over ``energy`` = KE > 0, so 1 on the ellipse,
    less inside it and more outside."""
    inputs.positive(energy, "energy")
    return kinetic_energy((m1, m2), (v1, v2)) / energy


@dataclass(frozen=True)
class ComFrame:
    """Two bodies seen from their centre-of-momentum frame (Fig. 2.4, Fig. 3.1's small ellipse).

    ``com_velocity`` is V_COM in the original frame; ``velocities`` are v - V_COM (their
    momentum is zero); ``energy`` is the KE left in the COM frame, 1/2 mu (v1 - v2)^2, the most
    any collision can lose (the ECOM of (3.8)).
    """

    masses: tuple[Real, Real]
    com_velocity: Real
    velocities: tuple[Real, Real]

    @property
    def speeds(self) -> tuple[Real, Real]:
        """Speeds |v - V_COM| of the two bodies in the COM frame."""
        return (cast(Real, abs(self.velocities[0])), cast(Real, abs(self.velocities[1])))

    @property
    def energy(self) -> Real:
        """Kinetic energy in the COM frame (3.8), the ECOM that a Ka-runch loses."""
        return kinetic_energy(self.masses, self.velocities)

    @property
    def ellipse(self) -> EnergyEllipse:
        """The COM-frame KE ellipse through the COM-frame velocities (Fig. 3.1)."""
        return EnergyEllipse(self.masses, self.velocities)


def com_frame(m1: Real, m2: Real, v1: Real, v2: Real) -> ComFrame:
    """Bodies m1, m2 at velocities v1, v2 seen from their COM frame (Fig. 2.4, (3.8))."""
    u = center_of_mass_velocity((m1, m2), (v1, v2))
    w = shift_frame((v1, v2), u)
    return ComFrame((m1, m2), u, (w[0], w[1]))


# -- partially inelastic collisions: the Ka-whump on a reduced ellipse (Fig. 3.2) -------------


@dataclass(frozen=True)
class PartialCollision:
    """A Ka-whump that leaves the kinetic energy ``energy_after`` (Fig. 3.2b).

    The momentum line cuts the reduced ellipse of energy ``energy_after`` in two points:
    ``rebound`` (the collision with restitution ``restitution``, the top F_whump point) and
    ``pass_through`` (its mirror through the COM point, the cars passing through each other).
    """

    masses: tuple[Real, Real]
    before: tuple[Real, Real]
    energy_after: Real
    restitution: Real
    rebound: Collision[Real]
    pass_through: Collision[Real]

    @property
    def ke_before(self) -> Real:
        """Kinetic energy before the collision (3.5b)."""
        return kinetic_energy(self.masses, self.before)

    @property
    def ke_lost(self) -> Real:
        """Energy lost, KE before minus ``energy_after`` (the E_loss of Fig. 3.2)."""
        return self.ke_before - self.energy_after


def collide_to_energy(
    m1: Real, m2: Real, v1: Real, v2: Real, energy_after: Real
) -> PartialCollision:
    """The partially inelastic collision that ends with kinetic energy ``energy_after``.

    The energy left is IE + e^2 E_COM, where IE = 1/2 (m1 + m2) V_COM^2 is what a Ka-runch
    keeps and E_COM = 1/2 mu (v1 - v2)^2 the energy in the COM frame (3.8); so the restitution
    is e = sqrt((energy_after - IE) / E_COM). ``energy_after`` must lie in [IE, KE]
    (``ValueError`` otherwise, and when the bodies have no relative velocity).
    """
    frame = com_frame(m1, m2, v1, v2)
    inputs.real(energy_after, "energy_after")
    available = frame.energy
    if available == 0:
        raise ValueError("the bodies have no relative velocity: nothing collides")
    kept = kinetic_energy((m1, m2), (frame.com_velocity, frame.com_velocity))
    total = kept + available
    if not kept <= energy_after <= total:
        raise ValueError(
            f"energy_after must lie between the Ka-runch energy {kept!r} and KE {total!r}, "
            f"got {energy_after!r}"
        )
    ratio = (energy_after - kept) / available
    if ratio > 1:  # energy_after <= kept + available was checked: this is float rounding
        ratio = 1.0
    e = exact_sqrt(ratio)
    rebound = collide(m1, m2, v1, v2, e)
    u = frame.com_velocity
    through = (u + e * frame.velocities[0], u + e * frame.velocities[1])
    return PartialCollision(
        (m1, m2),
        (v1, v2),
        energy_after,
        e,
        rebound,
        Collision((m1, m2), (v1, v2), through),
    )


# -- tensor forms of a two-body collision ((3.9)-(3.14); n bodies: tensor_forms) ----------


def collision_tensor_forms(
    m1: Real, m2: Real, v1: Real, v2: Real, restitution: Real = 1
) -> TensorForms:
    """The tensor forms (3.11)-(3.14) of a two-body collision: M = diag(m1, m2) (3.9a),
    V_IN = (v1, v2), V_FIN from ``collide`` and V_COM = (V, V) at the COM velocity (2.5b).

    For the SUV/VW crash of Fig. 3.1 these are the book's (60, 10), (40, 90) and (50, 50).
    """
    hit = collide(m1, m2, v1, v2, restitution)
    v = hit.com_velocity
    return tensor_energy_forms(inertia_tensor((m1, m2)), hit.before, hit.after, (v, v))


# -- units ------------------------------------------------------------------------------------


def velocity_in_si(velocity: Real, length: Real, duration: Real) -> Real:
    """A velocity of ``velocity`` lengths per duration, in m/s.

    ``length`` is the length unit in metres and ``duration`` the time unit in seconds (a foot
    per minute for the rescaled Fig. 2.2); the claim's unit converts the result to ft/s or mph.
    """
    inputs.real(velocity, "velocity")
    inputs.positive(length, "length")
    inputs.positive(duration, "duration")
    return velocity * length / duration
