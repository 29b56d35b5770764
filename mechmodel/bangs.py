"""Sequences of bangs between two balls, the floor and the ceiling (chapters 4-5).

Collisions are independent (the book's independent collision model, ICM, Fig. 4.3b): each
bang is a two-body collision completed before the next begins, so that between bangs the balls
move at constant velocity along straight space-time lines (Fig. 4.6-4.7). Ball 1 (mass m1) is
below ball 2 (mass m2); the floor (at height ``floor``, below ball 1) and the ceiling (at height
``ceiling``, above ball 2) are infinite masses at rest. Velocities and heights are positive up.

Bang kinds follow the book's labels: ``"01"`` ball 1 off the floor (Bang-1(01)), ``"12"`` ball 1
hits ball 2 (Bang-2(12)), ``"02"`` ball 2 off the ceiling (Bang-3(20), Bang-11(02)); 0 is the
Earth, floor or ceiling. Collisions come from ``mechmodel.collisions.collide``.

Functions take floats, ints, ``Fraction`` or mpmath numbers: exact with ``Fraction`` inputs
(every bang, time and height is then a rational number), floats otherwise.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction
from typing import Any, Literal

from mechmodel import inputs
from mechmodel.collisions import collide
from mechmodel.ellipse import energy_ellipse as energy_ellipse  # the catalog names bangs.*
from mechmodel.typing import not_monotonic

BangKind = Literal["01", "12", "02"]
FLOOR, BALLS, CEILING = "01", "12", "02"


# -- single bounces ----------------------------------------------------------------------------
def floor_bounce(v: Any, restitution: Any = 1) -> Any:
    """Velocity of a ball after it bounces off the floor (an infinite mass at rest below it).

    ``v`` is the ball's velocity before (negative: falling); it leaves at ``-e v`` (Fig. 4.2a,
    Bang-1(01) of Fig. 4.4a): the floor's matrix F of (5.4) in one component.
    """
    inputs.real(v, "v")
    return collide(math.inf, 1, 0, v, restitution).v2


def ceiling_bounce(v: Any, restitution: Any = 1) -> Any:
    """Velocity of a ball after it bounces off the ceiling (an infinite mass at rest above it).

    ``v`` is the ball's velocity before (positive: rising); it leaves at ``-e v`` (Bang-3(20) of
    Fig. 4.7b): the ceiling matrix C of (5.3) in one component.
    """
    inputs.real(v, "v")
    return collide(1, math.inf, v, 0, restitution).v1


def floor_impulse(m: Any, v: Any, restitution: Any = 1) -> Any:
    """Size of the momentum a ball of mass ``m`` arriving at velocity ``v`` gives the floor.

    The ball's momentum changes from m v to m v', so the floor (Earth) absorbs m (v - v'),
    downward: of size 2 m |v| for an elastic bounce and m |v| for a Ka-runch (e = 0), as in
    the discussion of Fig. 4.2a. Units of m v.
    """
    inputs.mass(m, "m")
    return abs(m * (v - floor_bounce(v, restitution)))


def bounce_impulse(m: Any, speed: Any, restitution: Any = 1) -> Any:
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

    momentum_change: Any
    energy_change: Any


def bang_changes(m1: Any, m2: Any, v1: Any, v2: Any) -> BangChanges:
    """Changes of total momentum and kinetic energy in one elastic ball bang: both zero.

    The independent collision model (Fig. 4.4) finds each bang's two final velocities from the
    two equations Delta P = 0 and Delta KE = 0; computed here from the bang itself.
    """
    hit = collide(m1, m2, v1, v2)
    return BangChanges(hit.momentum - (m1 * v1 + m2 * v2), hit.ke_after - hit.ke_before)


def mass_ratio(m1: Any, m2: Any) -> Any:
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

    masses: tuple[Any, Any]
    drop_speed: Any
    start: tuple[Any, Any]
    v1: Any
    v2: Any

    @property
    def speed_ratio(self) -> Any:
        """Launch speed of ball 2 over the drop speed, v2/v0 (3 at infinite m1/m2)."""
        return self.v2 / self.drop_speed

    @property
    def height_ratio(self) -> Any:
        """Height ball 2 rises to over the drop height: (v2/v0)^2, since h = v^2 / 2g."""
        return self.speed_ratio**2

    @property
    def energy_transfer(self) -> Any:
        """Share of the total kinetic energy that ball 2 carries away (1 at the M point)."""
        m1, m2 = self.masses
        inputs.mass(m1, "m1")
        total = (m1 + m2) * self.drop_speed**2
        return m2 * self.v2**2 / total


def x2_launch(m1: Any, m2: Any, v0: Any = 1) -> X2Launch:
    """The two bangs of the X2 launcher (Fig. 4.4, 4.5) for drop speed ``v0`` > 0.

    ``m1`` may be ``math.inf``: ball 2 then leaves at 3 v0 (the INF point I of Fig. 4.5b).
    """
    inputs.mass(m1, "m1", infinite_ok=True)
    inputs.mass(m2, "m2")
    inputs.positive(v0, "v0")
    up = floor_bounce(-v0)
    hit = collide(m1, m2, up, -v0)
    return X2Launch((m1, m2), v0, (up, -v0), hit.v1, hit.v2)


def x2_infinite_ratio_launch(v0: Any = 1) -> X2Launch:
    """The X2 launch in the limit m1/m2 -> infinity (the INF point I of Fig. 4.5b).

    Ball 1 is then an unmovable wall moving up at v0, off which ball 2 rebounds at 3 v0.
    """
    return x2_launch(math.inf, 1, v0)


def x2_full_transfer_ratio(v0: Any = 1) -> Any:
    """The mass ratio m1/m2 at which the X2 bang stops ball 1 (the M point of Fig. 4.5b).

    After the floor bounce (v0, -v0), (m1 + m2) v1' = (m1 - m2) v0 - 2 m2 v0 is linear in the
    ratio r = m1/m2 (first row of (5.1b)); its root is where ball 1 stops and ball 2 takes all
    the energy. Found from the collision law at two ratios, not from the closed form.
    """
    inputs.positive(v0, "v0")

    def scaled_v1(r: Any) -> Any:
        return (r + 1) * x2_launch(r, 1, v0).v1

    slope = scaled_v1(2) - scaled_v1(1)
    return -(scaled_v1(1) - slope) / slope


def x2_final_locus_angle(v0: Any, ratios: Sequence[Any]) -> float:
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

    before: tuple[Any, Any]
    after: tuple[Any, Any]
    energy_transfer: Any


def galileo_shifted_collision(
    m1: Any, m2: Any, v1: Any, v2: Any, boost: Any = 0, scale: Any = 1
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
    transfer = abs(ke1_before - ke1_after) / total
    return ShiftedCollision(before, hit.after, transfer)


# -- the Earth's share (the energy ellipse of Figs. 4.7c and 4.9 is mechmodel.ellipse) ---------
@dataclass(frozen=True)
class EarthRecoil:
    """What the Earth (mass M) takes from a ball (mass m) bouncing off it (Fig. 4.2a)."""

    ball_mass: Any
    earth_mass: Any

    @property
    def mass_fraction(self) -> Any:
        """The fraction m/M, ratio of the Earth's COM velocity to the ball's speed."""
        return self.ball_mass / self.earth_mass

    @property
    def energy_fraction(self) -> Any:
        """Kinetic energy of the Earth in the COM frame over the ball's, m M / (m + M)^2.

        In the COM frame the Earth moves at V_COM = m V0 / (m + M); (1/2) M V_COM^2 over
        (1/2) m V0^2 is the book's 'fraction M2/M_Earth of ball KE' (~ m/M).
        """
        m, big = self.ball_mass, self.earth_mass
        return m * big / (m + big) ** 2


def earth_recoil(m: Any, earth_mass: Any) -> EarthRecoil:
    """The Earth's share of a bounce of a ball of mass ``m`` (kg) off the Earth (kg)."""
    inputs.mass(m, "m")
    inputs.mass(earth_mass, "earth_mass")
    return EarthRecoil(m, earth_mass)


def sagitta_small_spot_depth(spot_radius: Any, ball_radius: Any) -> Any:
    """Depth d of a flat spot of radius r on a ball of radius R to leading order in r/R: the
    saggital approximation of Fig. 4.1.

    Exactly d = R - sqrt(R^2 - r^2) = r^2 / (R + sqrt(R^2 - r^2)) (multiplying by the
    conjugate); for r << R the root is R itself, which leaves r^2 over R + R. Plain operators:
    exact for Fraction inputs.
    """
    r = inputs.positive(spot_radius, "spot_radius")
    big = inputs.positive(ball_radius, "ball_radius")
    return r * r / (big + big)


def figures_of_agreement(approximations: Sequence[Any], precise: Sequence[Any]) -> int:
    """How many significant figures every approximation agrees with its precise value.

    The largest n such that each precise value rounded to n significant figures equals the
    approximation (the Earth's 6e24 kg and the Sun's 2e30 kg are 'good to 2 figures').
    """
    if len(approximations) != len(precise) or not precise:
        raise ValueError("give one precise value per approximation")

    def agreeing(approx: Any, exact: Any) -> int:
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


# -- velocity-only sequences under a ceiling (Fig. 5.1) ---------------------------------------
@dataclass(frozen=True)
class Bang:
    """One bang: ``"12"`` (ball 1 hits ball 2) or ``"02"`` (ball 2 off the ceiling), and the
    velocities (v1, v2) just after it."""

    kind: BangKind
    v1: Any
    v2: Any


@dataclass(frozen=True)
class BangSequence:
    """A sequence of bangs from a starting state to the last possible bang."""

    start: tuple[Any, Any]
    bangs: tuple[Bang, ...]

    @property
    def count(self) -> int:
        """How many bangs the sequence has, to its end."""
        return len(self.bangs)

    @property
    def velocities(self) -> tuple[tuple[Any, Any], ...]:
        """``velocities[k]`` is (v1, v2) after k bangs; ``velocities[0]`` is the start."""
        return (self.start, *((b.v1, b.v2) for b in self.bangs))


def bang_possible(v1: Any, v2: Any, *, floor: bool = False, ceiling: bool = True) -> bool:
    """Whether another bang can still happen to balls moving at (v1, v2).

    Ball 1 catches ball 2 if v1 > v2; ball 2 reaches a ceiling if it rises (v2 > 0); ball 1
    reaches a floor if it falls (v1 < 0). When none holds the sequence is over: the 'game-over'
    point of (5.13) and Exercise 1.5.1, after which the balls drift apart for good.
    """
    inputs.real(v1, "v1")
    inputs.real(v2, "v2")
    return v1 > v2 or (ceiling and v2 > 0) or (floor and v1 < 0)


def ceiling_sequence(m1: Any, m2: Any, v1: Any, v2: Any) -> BangSequence:
    """Bangs of ball 1 against ball 2 and of ball 2 against the ceiling, until neither can occur.

    Fig. 5.1 and (5.4): from (v1, v2) the balls collide when ball 1 gains on ball 2 (v1 > v2), and
    ball 2 bounces off the ceiling when it rises (v2 > 0). The two alternate, since an elastic
    bang leaves the balls separating and a ceiling bang leaves ball 2 falling: the matrix product
    (C M)^p of (5.3). Where both could come first (v1 > v2 > 0) the ball-ball bang is taken
    first. No floor intervenes, so the sequence ends when ball 2 is not rising and ball 1 does
    not gain on it. Exact with Fraction inputs.
    """
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    a, b = inputs.real(v1, "v1"), inputs.real(v2, "v2")
    bangs: list[Bang] = []
    while True:
        if a > b:
            hit = collide(m1, m2, a, b)
            bang = Bang(BALLS, hit.v1, hit.v2)
        elif b > 0:
            bang = Bang(CEILING, a, ceiling_bounce(b))
        else:
            break
        bangs.append(bang)
        a, b = bang.v1, bang.v2
    return BangSequence((v1, v2), tuple(bangs))


# -- the rotation picture: counts and states in O(1) (chapter 5) -------------------------------
# In mass-scaled velocities V = (v1 sqrt(m1), v2 sqrt(m2)) (5.6) both bangs are reflections that
# keep |V|: a ball bang across the collision line v1 = v2, at angle phi = atan(sqrt(m2/m1)), a
# ceiling bang across the V1 axis; a double bang turns V by -2 phi (5.12). With alpha the polar
# angle of V in (-pi, pi], a ball bang is possible iff alpha lies in (phi - pi, phi) (v1 > v2) and
# a ceiling bang iff alpha lies in (0, pi) (v2 > 0). From a ball bang at angle a the k-th ball
# bang happens iff a - 2 k phi > phi - pi and the k-th ceiling bang iff a - 2 k phi > 2 phi - pi:
# the counts are ceilings of A = (a - phi + pi)/(2 phi) and A - 1/2, computed in floats where
# they are far from a whole number and with mpmath near one.
_TIE_MARGIN = 1e-9  # relative distance from a whole number below which floats are not trusted


@dataclass(frozen=True)
class BangCount:
    """How many bangs a ball pair under a ceiling makes, from the rotation picture.

    ``first`` is the kind of the first bang (None when no bang can happen).
    """

    ball_bangs: int
    ceiling_bangs: int
    first: BangKind | None

    @property
    def total(self) -> int:
        """All bangs of the sequence."""
        return self.ball_bangs + self.ceiling_bangs


def _angles(m1: Any, m2: Any, v1: Any, v2: Any, *, precise: bool) -> tuple[Any, Any]:
    """(phi, alpha): the collision line's angle and the state's polar angle in V space."""
    if precise:
        import mpmath

        def to_mp(x: Any) -> Any:
            return (
                mpmath.mpf(x.numerator) / x.denominator
                if hasattr(x, "denominator")
                else (mpmath.mpf(x))
            )

        m1, m2, v1, v2 = (to_mp(x) for x in (m1, m2, v1, v2))
        return mpmath.atan(mpmath.sqrt(m2 / m1)), mpmath.atan2(
            v2 * mpmath.sqrt(m2), v1 * mpmath.sqrt(m1)
        )
    m1, m2, v1, v2 = (float(x) for x in (m1, m2, v1, v2))
    return math.atan(math.sqrt(m2 / m1)), math.atan2(v2 * math.sqrt(m2), v1 * math.sqrt(m1))


@not_monotonic
def bang_count(m1: Any, m2: Any, v1: Any, v2: Any) -> BangCount:
    """How many bangs ``ceiling_sequence`` makes, in O(1): no bang is simulated.

    The rotation picture (5.12)-(5.13) of the comment above. Where a count's boundary falls
    within a relative 1e-9 of a whole number the angles are recomputed with mpmath at enough
    digits (more for a wide mass ratio or a wide spread of the speeds); a true tie (a later
    state exactly on a boundary: v1 = v2 or v2 = 0 after some bangs) is settled by simulating
    the inputs' exact rational values. The first bang's kind is decided exactly on the given
    velocities. The counts are those of the inputs' exact values: they agree with
    ``ceiling_sequence`` (the reference) run exactly, and with a float run wherever its
    rounding decides no bang (near a boundary, 2 v_com - v1 can lose a tiny velocity).
    """
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    inputs.real(v1, "v1")
    inputs.real(v2, "v2")
    if v1 == 0 and v2 == 0:
        return BangCount(0, 0, None)
    # enough digits for the mass ratio and for the velocities' spread (a v2 of 1e-300 beside a
    # v1 of 1 moves a boundary by 1e-300)
    speeds = [abs(float(v)) for v in (v1, v2) if v]
    spread = math.log10(max(speeds)) - math.log10(min(speeds)) if all(speeds) else 0.0
    digits = 30 + int(abs(math.log10(float(m1) / float(m2))) + spread)
    for precise in (False, True):
        counts = _count_at(m1, m2, v1, v2, precise=precise, digits=digits)
        if counts is not None:
            return counts
    # a true tie: the exact values of the inputs are simulated without rounding
    sequence = ceiling_sequence(*(_exact(x) for x in (m1, m2, v1, v2)))
    balls = sum(b.kind == BALLS for b in sequence.bangs)
    first = sequence.bangs[0].kind if sequence.bangs else None
    return BangCount(balls, sequence.count - balls, first)


def _exact(x: Any) -> Any:
    """The exact rational value of an int, float, Fraction or Decimal; other numbers as given."""
    try:
        return Fraction(x)
    except TypeError:
        return x


def _count_at(
    m1: Any, m2: Any, v1: Any, v2: Any, *, precise: bool, digits: int
) -> BangCount | None:
    """The counts at float or mpmath precision, or None if a boundary is too close to call."""
    import mpmath

    with mpmath.workdps(digits):
        phi, alpha = _angles(m1, m2, v1, v2, precise=precise)
        pi = mpmath.pi if precise else math.pi
        half = mpmath.mpf(1) / 2 if precise else 0.5
        margin = mpmath.mpf(10) ** (10 - digits) if precise else _TIE_MARGIN
        # which bang comes first is decided on the velocities themselves, exactly: the angles
        # of a state on a boundary (v1 = v2, v2 = 0) can round to either side
        ceiling_first = 0
        if v1 > v2:
            first, start = BALLS, alpha
        elif v2 > 0:
            first, start, ceiling_first = CEILING, -alpha, 1
            if not v1 > -v2:  # after the ceiling bang the balls do not close
                return BangCount(0, 1, first)
        else:
            return BangCount(0, 0, None)
        big_a = (start - phi + pi) / (2 * phi)
        big_b = big_a - half
        for x in (big_a, big_b):
            if abs(x - round(x)) <= margin * max(1, abs(x)):
                return None
        ceil = mpmath.ceil if precise else math.ceil
        balls, ceilings = int(ceil(big_a)), int(ceil(big_b))
        return BangCount(balls, max(0, ceilings) + ceiling_first, first)


def state_after_bangs(m1: Any, m2: Any, v1: Any, v2: Any, n: Any) -> tuple[float, float]:
    """(v1, v2) after the first ``n`` bangs of ``ceiling_sequence``, in O(1) (floats).

    Each ball bang reflects the V-space angle across phi (alpha -> 2 phi - alpha), each ceiling
    bang across 0 (alpha -> -alpha); |V| is kept. ``ValueError`` past the sequence's end.
    """
    n = inputs.count(n, "n")
    count = bang_count(m1, m2, v1, v2)
    if n > count.total:
        raise ValueError(f"the sequence has {count.total} bangs, fewer than {n}")
    phi, alpha = _angles(m1, m2, v1, v2, precise=False)
    radius = math.hypot(float(v1) * math.sqrt(float(m1)), float(v2) * math.sqrt(float(m2)))
    if count.first == CEILING and n >= 1:
        alpha, n = -alpha, n - 1
    alpha -= 2 * phi * (n // 2)  # each double bang (ball, then ceiling) turns by -2 phi
    if n % 2:
        alpha = 2 * phi - alpha
    return (
        radius * math.cos(alpha) / math.sqrt(float(m1)),
        radius * math.sin(alpha) / math.sqrt(float(m2)),
    )


def velocities_after_bang(m1: Any, m2: Any, v1: Any, v2: Any, bang: int) -> tuple[Any, Any]:
    """(v1, v2) just after Bang-``bang`` of the book's numbering for Fig. 5.1.

    Bang-1 is the floor bounce F that left the balls at (v1, v2) = (1, -1) in (5.13); the ball
    and ceiling bangs of ``ceiling_sequence`` are Bang-2, Bang-3, ... (even bangs (12), odd
    bangs (02), as on p. 5). ``ValueError`` past the last bang of the sequence.
    """
    n = inputs.count(bang, "bang", minimum=1)
    states = ceiling_sequence(m1, m2, v1, v2).velocities
    if n > len(states):
        raise ValueError(f"the sequence ends at Bang-{len(states)}, before Bang-{n}")
    return states[n - 1]


@not_monotonic
def game_over_bang(m1: Any, m2: Any, v1: Any, v2: Any) -> int:
    """The number of the last bang of Fig. 5.1's sequence, counting the floor bounce as Bang-1.

    Without a second floor bounce the sequence (C M)^p ends when no bang can occur (5.13):
    the 'game-over' point of Exercise 1.5.1.
    """
    return 1 + ceiling_sequence(m1, m2, v1, v2).count


def bangs_in_chain(double_bangs: int, floor_bounces: int = 1) -> int:
    """Bangs in a chain of floor bounces followed by ``double_bangs`` (C M) pairs: (5.3)-(5.4).

    The p double-bangs (C M)^p after the floor bounce F make 2 p + 1 bangs in all.
    """
    p = inputs.count(double_bangs, "double_bangs")
    return inputs.count(floor_bounces, "floor_bounces") + 2 * p


# -- space-time histories (Fig. 4.6, 4.7, 4.11, 4.12) ----------------------------------------
@dataclass(frozen=True)
class Event:
    """A bang of a space-time history: Bang-``number`` of ``kind`` at ``time``.

    ``y1``, ``y2`` are the heights of the balls at the bang (the space-space point y(n) of
    Fig. 4.11) and ``v1``, ``v2`` their velocities just after it (the point v(n)).
    """

    number: int
    kind: BangKind
    time: Any
    y1: Any
    y2: Any
    v1: Any
    v2: Any


@dataclass(frozen=True)
class History:
    """Every bang of two balls between a floor and a ceiling, in order, from time 0.

    ``ended`` is True when no further bang can occur (the game-over point); False when the
    history stopped at ``max_bangs``.
    """

    masses: tuple[Any, Any]
    start: tuple[Any, Any, Any, Any]
    bangs: tuple[Event, ...]
    ended: bool

    @property
    def count(self) -> int:
        """How many bangs were recorded."""
        return len(self.bangs)

    def numbers(self, kind: BangKind) -> tuple[int, ...]:
        """The numbers n of the bangs Bang-n of one kind, in order."""
        return tuple(e.number for e in self.bangs if e.kind == kind)

    @property
    def floor_bangs(self) -> tuple[int, ...]:
        """Numbers of the floor bangs (01) of ball 1: Bang-1, Bang-7 in Fig. 4.7."""
        return self.numbers(FLOOR)

    @property
    def ball_bangs(self) -> tuple[int, ...]:
        """Numbers of the bangs (12) between the balls: Bang-2, 4, 6, 9 in Fig. 4.7."""
        return self.numbers(BALLS)

    @property
    def ceiling_bangs(self) -> tuple[int, ...]:
        """Numbers of the ceiling bangs (02) of ball 2: Bang-3, 5, 8 in Fig. 4.7."""
        return self.numbers(CEILING)

    def positions_at(self, t: Any) -> tuple[Any, Any]:
        """Heights (y1, y2) at time ``t`` >= 0 (the space-time paths between bangs)."""
        inputs.real(t, "t")
        if t < 0:
            raise ValueError("t must be >= 0")
        y1, y2, v1, v2 = self.start
        t0: Any = 0
        for e in self.bangs:
            if e.time > t:
                break
            t0, y1, y2, v1, v2 = e.time, e.y1, e.y2, e.v1, e.v2
        return y1 + v1 * (t - t0), y2 + v2 * (t - t0)


@not_monotonic
def bang_history(
    m1: Any,
    m2: Any,
    y1: Any,
    y2: Any,
    v1: Any,
    v2: Any,
    ceiling: Any = None,
    floor: Any = 0,
    floor_bounces: int | None = None,
    max_bangs: int = 1000,
) -> History:
    """Event-driven history of two point balls between a floor and a ceiling (Fig. 4.6-4.7).

    Ball 1 (mass m1, height y1, velocity v1) is below ball 2 (m2, y2, v2). ``ceiling`` is its
    height (None: no ceiling); ``floor`` the floor's height (None: no floor), open after
    ``floor_bounces`` bounces (None: never; 1 for Exercise 1.4.2's 'floor is open after
    Bang-1'). From time 0 each ball moves in a straight line until the next bang: ball 1 off the
    floor when it falls onto it, the balls when ball 1 catches ball 2, ball 2 off the ceiling
    when it rises to it. Bangs at the same instant are done in the order floor, balls, ceiling.
    Records up to ``max_bangs`` bangs; exact with Fraction inputs.
    """
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    for value, name in ((y1, "y1"), (y2, "y2"), (v1, "v1"), (v2, "v2")):
        inputs.real(value, name)
    limit = inputs.count(max_bangs, "max_bangs")
    if ceiling is not None:
        inputs.real(ceiling, "ceiling")
    if floor is not None:
        inputs.real(floor, "floor")
    if floor_bounces is not None:
        floor_bounces = inputs.count(floor_bounces, "floor_bounces")
    if y1 > y2:
        raise ValueError("ball 1 must start below ball 2 (y1 <= y2)")
    if floor is not None and y1 < floor:
        raise ValueError("ball 1 must start on or above the floor")
    if ceiling is not None and y2 > ceiling:
        raise ValueError("ball 2 must start on or below the ceiling")

    t: Any = 0
    a, b, u, w = y1, y2, v1, v2
    bangs: list[Event] = []
    bounces = 0
    while len(bangs) < limit:
        floor_open = floor is None or (floor_bounces is not None and bounces >= floor_bounces)
        waits: list[tuple[Any, BangKind]] = []
        if not floor_open and u < 0:
            waits.append(((a - floor) / -u, FLOOR))
        if u > w:
            waits.append(((b - a) / (u - w), BALLS))
        if ceiling is not None and w > 0:
            waits.append(((ceiling - b) / w, CEILING))
        if not waits:
            return History((m1, m2), (y1, y2, v1, v2), tuple(bangs), True)
        dt, kind = min(waits, key=lambda item: item[0])  # ties: first listed wins
        t = t + dt
        a, b = a + u * dt, b + w * dt
        if kind == FLOOR:
            a, u = floor, floor_bounce(u)
            bounces += 1
        elif kind == BALLS:
            b = a  # they meet: the same height
            hit = collide(m1, m2, u, w)
            u, w = hit.v1, hit.v2
        else:
            b, w = ceiling, ceiling_bounce(w)
        bangs.append(Event(len(bangs) + 1, kind, t, a, b, u, w))
    return History((m1, m2), (y1, y2, v1, v2), tuple(bangs), False)
