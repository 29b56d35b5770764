"""Single bangs of chapter 4: bounces off the floor and ceiling, the X2 launcher, the Earth's share.

A bounce off the floor or the ceiling (an infinite mass at rest) reverses a ball's velocity
(Fig. 4.2a, Bang-1(01) and Bang-3(20) of Fig. 4.4a, 4.7b); the momentum it gives the floor is
the Earth's share of Fig. 4.2a. The X2 launcher (Fig. 4.1, 4.4, 4.5) is a floor bounce of ball 1
followed by one elastic bang between the balls; its mass ratio m1/m2 sets the launch speed,
height and energy transfer. Velocities are positive up, in the units of the inputs (the book's
scaled units: drop speed v0 = 1); masses in (0, inf], an infinite m1 being the INF point I of
Fig. 4.5b. Exact with ``Fraction`` inputs. Collisions come from ``mechmodel.collisions.collide``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from decimal import Decimal
from typing import cast

from mechmodel import inputs
from mechmodel.collisions import collide
from mechmodel.exact import magnitude
from mechmodel.typing import Real, Vector


# -- single bounces ----------------------------------------------------------------------------
def floor_bounce(v: Real, restitution: Real = 1) -> Real:
    """Velocity of a ball after it bounces off the floor (an infinite mass at rest below it).

    ``v`` is the ball's velocity before (negative: falling); it leaves at ``-e v`` (Fig. 4.2a,
    Bang-1(01) of Fig. 4.4a): the floor's matrix F of (5.4) in one component.
    """
    inputs.real(v, "v")
    return collide(math.inf, 1, 0, v, restitution).v2


def ceiling_bounce(v: Real, restitution: Real = 1) -> Real:
    """Velocity of a ball after it bounces off the ceiling (an infinite mass at rest above it).

    ``v`` is the ball's velocity before (positive: rising); it leaves at ``-e v`` (Bang-3(20) of
    Fig. 4.7b): the ceiling matrix C of (5.3) in one component.
    """
    inputs.real(v, "v")
    return collide(1, math.inf, v, 0, restitution).v1


def floor_impulse(m: Real, v: Real, restitution: Real = 1) -> Real:
    """Size of the momentum a ball of mass ``m`` arriving at velocity ``v`` gives the floor.

    The ball's momentum changes from m v to m v', so the floor (Earth) absorbs m (v - v'),
    downward: of size 2 m |v| for an elastic bounce and m |v| for a Ka-runch (e = 0), as in
    the discussion of Fig. 4.2a. Units of m v.
    """
    inputs.mass(m, "m")
    return cast(Real, abs(m * (v - floor_bounce(v, restitution))))  # abs of a Real union


def bounce_impulse(m: Real, speed: Real, restitution: Real = 1) -> Real:
    """Size of the momentum the floor (the Earth) absorbs from a ball of mass ``m`` that hits it
    at ``speed`` >= 0, arriving with velocity -speed (point I0 of Fig. 4.2a): ``floor_impulse``
    of that arrival, 2 m V0 for an elastic bounce and m V0 for a Ka-runch."""
    inputs.real(speed, "speed")
    if speed < 0:
        raise ValueError(f"speed must not be negative, got {speed!r}")
    return floor_impulse(m, -speed, restitution)


@dataclass(frozen=True)
class BangChanges:
    """What one elastic bang between the balls changes: momentum and kinetic energy (ICM)."""

    momentum_change: Real
    energy_change: Real


def bang_changes(m1: Real, m2: Real, v1: Real, v2: Real) -> BangChanges:
    """Changes of total momentum and kinetic energy in one elastic ball bang: both zero.

    The independent collision model (Fig. 4.4) finds each bang's two final velocities from the
    two equations Delta P = 0 and Delta KE = 0; computed here from the bang itself.
    """
    hit = collide(m1, m2, v1, v2)
    return BangChanges(hit.momentum - (m1 * v1 + m2 * v2), hit.ke_after - hit.ke_before)


def mass_ratio(m1: Real, m2: Real) -> Real:
    """The mass ratio m1/m2 (the 7/1 of the X2 superball and pen, the 49 of Fig. 5.1)."""
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    return m1 / m2


# -- the X2 launcher (Fig. 4.1, 4.4, 4.5) ----------------------------------------------------
@dataclass(frozen=True)
class X2Launch:
    """The X2 launcher: ball 1 (m1) falls on the floor with ball 2 (m2) just above it.

    Both are dropped at speed ``v0``. Bang-1(01) bounces ball 1 up to +v0 (the INIT point
    ``start = (v0, -v0)`` of Fig. 4.4b); Bang-2(12) is the elastic bang between the balls, after
    which they move at ``v1`` and ``v2``. ``m1`` may be infinite (the INF point I of Fig. 4.5b).
    """

    masses: tuple[Real, Real]
    drop_speed: Real
    start: tuple[Real, Real]
    v1: Real
    v2: Real

    @property
    def speed_ratio(self) -> Real:
        """Launch speed of ball 2 over the drop speed, v2/v0 (3 at infinite m1/m2)."""
        return self.v2 / self.drop_speed

    @property
    def height_ratio(self) -> Real:
        """Height ball 2 rises to over the drop height: (v2/v0)^2, since h = v^2 / 2g."""
        return self.speed_ratio**2

    @property
    def energy_transfer(self) -> Real:
        """Share of the total kinetic energy that ball 2 carries away (1 at the M point)."""
        m1, m2 = self.masses
        inputs.mass(m1, "m1")
        total = (m1 + m2) * self.drop_speed**2
        return m2 * self.v2**2 / total


def x2_launch(m1: Real, m2: Real, v0: Real = 1) -> X2Launch:
    """The two bangs of the X2 launcher (Fig. 4.4, 4.5) for drop speed ``v0`` > 0.

    ``m1`` may be ``math.inf``: ball 2 then leaves at 3 v0 (the INF point I of Fig. 4.5b).
    """
    inputs.mass(m1, "m1", infinite_ok=True)
    inputs.mass(m2, "m2")
    inputs.positive(v0, "v0")
    up = floor_bounce(-v0)
    hit = collide(m1, m2, up, -v0)
    return X2Launch((m1, m2), v0, (up, -v0), hit.v1, hit.v2)


def x2_infinite_ratio_launch(v0: Real = 1) -> X2Launch:
    """The X2 launch in the limit m1/m2 -> infinity (the INF point I of Fig. 4.5b).

    Ball 1 is then an unmovable wall moving up at v0, off which ball 2 rebounds at 3 v0.
    """
    return x2_launch(math.inf, 1, v0)


def x2_full_transfer_ratio(v0: Real = 1) -> Real:
    """The mass ratio m1/m2 at which the X2 bang stops ball 1 (the M point of Fig. 4.5b).

    After the floor bounce (v0, -v0), (m1 + m2) v1' = (m1 - m2) v0 - 2 m2 v0 is linear in the
    ratio r = m1/m2 (first row of (5.1b)); its root is where ball 1 stops and ball 2 takes all
    the energy. Found from the collision law at two ratios, not from the closed form.
    """
    inputs.positive(v0, "v0")

    def scaled_v1(r: Real) -> Real:
        return (r + 1) * x2_launch(r, 1, v0).v1

    slope = scaled_v1(2) - scaled_v1(1)
    return -(scaled_v1(1) - slope) / slope


def x2_final_locus_angle(v0: Real, ratios: Vector) -> float:
    """Inclination (radians) of the line through the X2 final points of two mass ratios.

    Every elastic final point (v1, v2) has v2 - v1 = 2 v0 (the relative velocity reverses), so
    they all lie on one line of slope 1: the 45-degree line CPL of Fig. 4.5a.
    """
    if len(ratios) != 2 or ratios[0] == ratios[1]:
        raise ValueError("ratios must be two different mass ratios")
    a, b = (x2_launch(r, 1, v0) for r in ratios)
    return math.atan2(b.v2 - a.v2, b.v1 - a.v1)


@dataclass(frozen=True)
class ShiftedCollision:
    """A collision seen after a Galileo boost and a change of speed scale (Fig. 4.5b, U line)."""

    before: tuple[Real, Real]
    after: tuple[Real, Real]
    energy_transfer: Real


def galileo_shifted_collision(
    m1: Real, m2: Real, v1: Real, v2: Real, boost: Real = 0, scale: Real = 1
) -> ShiftedCollision:
    """Collide after boosting both velocities by ``boost`` and scaling them by ``scale``.

    Fig. 4.5b: the unit-ratio line U, (+1, -1) -> (-1, +1), boosted by -1 becomes the pool shot
    (0, -2) -> (-2, 0); at half that speed it is (0, -1) -> (-1, 0). ``energy_transfer`` is the
    share of the kinetic energy that changes hands: 1 when a moving ball stops and the resting
    one takes all its energy.
    """
    inputs.real(boost, "boost")
    inputs.positive(scale, "scale")
    before = (scale * (v1 + boost), scale * (v2 + boost))
    hit = collide(m1, m2, *before)
    ke1_before, ke1_after = m1 * before[0] ** 2, m1 * hit.v1**2
    total = m1 * before[0] ** 2 + m2 * before[1] ** 2
    if total == 0:
        raise ValueError("both balls at rest: no energy to transfer")
    transfer = magnitude(ke1_before - ke1_after) / total
    return ShiftedCollision(before, hit.after, transfer)


# -- the Earth's share (the energy ellipse of Figs. 4.7c and 4.9 is mechmodel.ellipse) ---------
@dataclass(frozen=True)
class EarthRecoil:
    """What the Earth (mass M) takes from a ball (mass m) bouncing off it (Fig. 4.2a)."""

    ball_mass: Real
    earth_mass: Real

    @property
    def mass_fraction(self) -> Real:
        """The fraction m/M, ratio of the Earth's COM velocity to the ball's speed."""
        return self.ball_mass / self.earth_mass

    @property
    def energy_fraction(self) -> Real:
        """Kinetic energy of the Earth in the COM frame over the ball's, m M / (m + M)^2.

        In the COM frame the Earth moves at V_COM = m V0 / (m + M); (1/2) M V_COM^2 over
        (1/2) m V0^2 is the book's 'fraction M2/M_Earth of ball KE' (~ m/M).
        """
        m, big = self.ball_mass, self.earth_mass
        return m * big / (m + big) ** 2


def earth_recoil(m: Real, earth_mass: Real) -> EarthRecoil:
    """The Earth's share of a bounce of a ball of mass ``m`` (kg) off the Earth (kg)."""
    inputs.mass(m, "m")
    inputs.mass(earth_mass, "earth_mass")
    return EarthRecoil(m, earth_mass)


def sagitta_small_spot_depth(spot_radius: Real, ball_radius: Real) -> Real:
    """Depth d of a flat spot of radius r on a ball of radius R to leading order in r/R: the
    saggital approximation of Fig. 4.1.

    Exactly d = R - sqrt(R^2 - r^2) = r^2 / (R + sqrt(R^2 - r^2)) (multiplying by the
    conjugate); for r << R the root is R itself, which leaves r^2 over R + R. Plain operators:
    exact for Fraction inputs.
    """
    r = inputs.positive(spot_radius, "spot_radius")
    big = inputs.positive(ball_radius, "ball_radius")
    return r * r / (big + big)


def figures_of_agreement(approximations: Vector, precise: Vector) -> int:
    """How many significant figures every approximation agrees with its precise value.

    The largest n such that each precise value rounded to n significant figures equals the
    approximation (the Earth's 6e24 kg and the Sun's 2e30 kg are 'good to 2 figures').
    """
    if len(approximations) != len(precise) or not precise:
        raise ValueError("give one precise value per approximation")

    def agreeing(approx: Real, exact: Real) -> int:
        a, p = Decimal(repr(float(approx))), Decimal(repr(float(exact)))
        if a <= 0 or p <= 0:
            raise ValueError("values must be positive")
        n = 0
        while n < 15:
            quantum = Decimal(1).scaleb(p.adjusted() - n)
            if p.quantize(quantum) != a:
                break
            n += 1
        return n

    return min(agreeing(a, p) for a, p in zip(approximations, precise, strict=True))
