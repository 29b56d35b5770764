"""N-body collisions: towers of balls, pile-ups and the pellet rocket (chapter 8).

- Towers dropped onto the floor at speed ``v_drop``, the heaviest ball at the bottom. With
  finite gaps every collision is independent and elastic (Fig. 8.1(b), Fig. 8.2): the result
  does not depend on the force law. With zero gaps the balls and the floor push on each other
  all at once (Fig. 8.1(a), (c), Fig. 7.6-7.7): ``zero_gap_tower`` integrates that soft
  collision (``mechmodel.contact.soft_collision``).
- The INF limit of a tower whose every ball is infinitely heavier than the one above it, the
  column bounce of identical balls (Newton's balls, Fig. 8.2(c-d)), the kinetic-energy boost.
- Inelastic collisions: the quadratic (8.4b) for the final velocity at a given energy loss, the
  Ka-runch pile-ups of Figs. 8.5-8.6, and the "time-reversed pile-up": the rocket of pellets
  (8.7), Fig. 8.8.

Exact with Fraction inputs wherever only + - * / are involved; the soft collision is numerical.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

from mechmodel import inputs
from mechmodel.collisions import Collision, collide
from mechmodel.contact import SoftCollision, soft_collision
from mechmodel.ellipse import kinetic_energy, velocity_radius
from mechmodel.typing import Real, Symbolic, Vector


@dataclass(frozen=True)
class Tower:
    """A tower's ball-ball bangs, bottom first, and its balls' final velocities.

    ``rebound`` is ball 1's velocity just after the floor bounce; ``bangs[k]`` is Bang(k+2)
    between balls k+1 and k+2 (the book's Bang(2)12, Bang(3)23, ...), with its velocities before
    and after; ``velocities[k]`` is ball k+1's final velocity.
    """

    masses: tuple[Real, ...]
    rebound: Real
    bangs: tuple[Collision[Real], ...]
    velocities: tuple[Real, ...]

    @property
    def momentum_slopes(self) -> tuple[Real, ...]:
        """Sizes m_k / m_(k+1) of the slopes of the momentum lines of the bangs (Fig. 8.1(b):
        "a slope 100/30 line"): the line falls with slope -m_k / m_(k+1) in (V_k, V_(k+1))."""
        return tuple(lo / up for lo, up in itertools.pairwise(self.masses))

    @property
    def energy_boost(self) -> Real:
        """The top ball's kinetic-energy gain factor, (V_top / v_drop)^2 (after Fig. 8.2)."""
        ratio = self.velocities[-1] / self.rebound
        return ratio * ratio


def independent_tower(masses: Vector, v_drop: Real = 1) -> Tower:
    """Final velocities of an N-ball tower with independent collisions (Fig. 8.1(b), Fig. 8.2).

    Ball 1 rebounds elastically from the floor at +v_drop and meets ball 2, still falling at
    -v_drop (Bang(2)12); ball 2 leaves with its new velocity and meets ball 3, still falling
    (Bang(3)23); and so on up. Ball k's final velocity is the one it leaves its bang with ball
    k+1 with; the top ball's is the tower's launch speed. Later bangs between balls that may
    catch up again are not part of this construction. Exact with Fraction inputs.
    """
    if len(masses) < 1:
        raise ValueError("a tower needs at least one ball")
    for i, m in enumerate(masses):
        inputs.mass(m, f"masses[{i}]")
    inputs.positive(v_drop, "v_drop")
    rebound = rising = collide(math.inf, masses[0], 0, -v_drop).v2
    bangs = []
    for lower, upper in itertools.pairwise(masses):
        bangs.append(collide(lower, upper, rising, -v_drop))
        rising = bangs[-1].v2
    finals = (*(bang.v1 for bang in bangs), rising)
    return Tower(tuple(masses), rebound, tuple(bangs), finals)


def geometric_tower(n_balls: int, ratio: Real, v_drop: Real = 1) -> Tower:
    """The independent-collision tower of ``n_balls`` balls, each ``ratio`` times the one above
    it (Fig. 8.2: 4 balls with ratio 3 or 7; ratio 1 is Newton's balls). The top ball has mass 1.
    """
    n = inputs.count(n_balls, "n_balls", minimum=1)
    inputs.positive(ratio, "ratio")
    masses = [ratio ** (n - 1 - k) for k in range(n)]
    return independent_tower(masses, v_drop)


def inf_limit_tower(n_balls: int, v_drop: Real = 1) -> tuple[Real, ...]:
    """Velocities of a tower whose every ball is infinitely heavier than the one above (the INF
    limit, Fig. 4.5, exercise 1.8.2): each ball leaves its bang at 2 V + v_drop, where V is the
    velocity of the (immovable) ball below. The top ball reaches (2^N - 1) v_drop."""
    n = inputs.count(n_balls, "n_balls", minimum=1)
    inputs.positive(v_drop, "v_drop")
    rising = collide(math.inf, 1, 0, -v_drop).v2
    out = [rising]
    for _ in range(n - 1):
        rising = collide(math.inf, 1, rising, -v_drop).v2
        out.append(rising)
    return tuple(out)


def energy_boost(velocity: Real, v_drop: Real = 1) -> Real:
    """Kinetic-energy gain factor (V / v_drop)^2 of a ball launched at ``velocity`` by a tower
    dropped at ``v_drop``: the (V4)^2 of Fig. 8.2(b), the 5.8^2 of the 3:1 tower."""
    inputs.real(velocity, "velocity")
    inputs.positive(v_drop, "v_drop")
    return (velocity / v_drop) * (velocity / v_drop)


def column_bounce_bangs(n_balls: int, ratio: Real = 1, v_drop: Real = 1) -> int:
    """Number of independent bangs a dropped column of balls makes before it flies apart.

    The balls (each ``ratio`` times the one above; 1 for the identical balls of Fig. 8.2(c-d))
    fall together at ``v_drop`` with small gaps; the lowest pending bang goes first: ball 1 off
    the floor when it falls, else the lowest pair closing on each other (``collide``). The column
    is done when ball 1 rises and no pair closes. Identical balls need N (N + 1) / 2 bangs:
    N floor bounces and the N (N - 1) / 2 swaps of the velocity exchanges.
    """
    n = inputs.count(n_balls, "n_balls", minimum=1)
    inputs.positive(ratio, "ratio")
    inputs.positive(v_drop, "v_drop")
    masses = [ratio ** (n - 1 - k) for k in range(n)]
    v = [-v_drop] * n
    limit = 100 * n * n
    for count in range(limit):
        if v[0] < 0:
            v[0] = collide(math.inf, masses[0], 0, v[0]).v2
            continue
        closing = [k for k in range(n - 1) if v[k] > v[k + 1]]
        if not closing:
            return count
        k = closing[0]
        v[k], v[k + 1] = collide(masses[k], masses[k + 1], v[k], v[k + 1]).after
    raise ValueError(f"the column did not fly apart within {limit} bangs")


def zero_gap_tower(
    masses: Vector, power: Real, v_drop: Real = 1, strength: Real = 1
) -> SoftCollision:
    """Final velocities of a tower dropped with zero gaps (Fig. 8.1(a), (c); Fig. 7.6-7.7).

    The balls touch each other and, at the start, the floor; all move down at ``v_drop``. Every
    contact (floor-ball 1 and each ball-ball pair) pushes with the same law F = k y^n of its
    overlap y; gravity is left out during the contact (its impulse over the short contact is
    negligible) and there is no friction, so energy is conserved. For a power law the final
    velocities are then proportional to ``v_drop`` and independent of k = ``strength``: scaling
    time and length removes both. Returns the ``contact.SoftCollision`` (velocities with their
    numerical errors).
    """
    inputs.positive(v_drop, "v_drop")
    n = len(masses)
    return soft_collision(masses, [0] * n, [-v_drop] * n, power, strength, floor=True)


# --- inelastic collisions: (8.1)-(8.6), pile-ups, Figs. 8.3-8.6 ------------------------------


@dataclass(frozen=True)
class InelasticQuadratic:
    """The quadratic (8.4b) for u1 at momentum p and kinetic energy K, in the book's form
    A u1^2 + B u1 + C = 0 (twice the energy balance): A = m1 (m1 + m2) / m2,
    B = -2 p m1 / m2, C = p^2 / m2 - 2 K.

    ``momentum_coefficient`` is the 2 of -2 p (m1/m2) u1 (= -B m2 / (p m1)); ``energy_coefficient``
    the 2 of -2 K (= -dC/dK); ``roots`` the two solutions (u1FIN and u1IN of Fig. 8.3b, in
    increasing order, None if the energy is below the minimum); ``v_com`` their mean.
    """

    a: Real
    b: Real
    c: Real
    momentum_coefficient: Real | None
    energy_coefficient: Real
    roots: tuple[float, float] | None
    v_com: Real


def inelastic_quadratic(m1: Real, m2: Real, momentum: Real, energy: Real) -> InelasticQuadratic:
    """Build (8.4b) by putting u2 = (p - m1 u1) / m2 (8.4a) into the energy (8.2), and solve it.

    The coefficients are read off the polynomial at u1 = 0, 1, -1, so nothing is assumed of
    their form. Exact with Fraction inputs (the roots are floats).
    """
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    inputs.real(momentum, "momentum")
    inputs.real(energy, "energy")

    def twice_balance(u1: Real, k: Real) -> Real:
        u2 = (momentum - m1 * u1) / m2
        return m1 * u1 * u1 + m2 * u2 * u2 - 2 * k

    c = twice_balance(0, energy)
    a = (twice_balance(1, energy) + twice_balance(-1, energy)) / 2 - c
    b = (twice_balance(1, energy) - twice_balance(-1, energy)) / 2
    discriminant = b * b - 4 * a * c
    roots = None
    if discriminant >= 0:
        root = math.sqrt(discriminant)
        roots = ((-b - root) / (2 * a), (-b + root) / (2 * a))
    return InelasticQuadratic(
        a=a,
        b=b,
        c=c,
        momentum_coefficient=-b * m2 / (momentum * m1) if momentum else None,
        energy_coefficient=twice_balance(0, energy) - twice_balance(0, energy + 1),
        roots=roots,
        v_com=momentum / (m1 + m2),
    )


@dataclass(frozen=True)
class InelasticBalance:
    """The energy balance of (8.2) along the momentum line (8.1), at ball 1's velocity u1.

    ``u2`` is ball 2's velocity from momentum conservation (8.4a); ``kinetic`` the pair's
    kinetic energy 1/2 m1 u1^2 + 1/2 m2 u2^2 there; ``twice_residual`` twice its excess over the
    given energy K, 2 (KE - K), the left side of (8.4b), which vanishes at the solutions.
    """

    u2: Real
    kinetic: Real
    twice_residual: Real


def inelastic_energy_balance(
    m1: Real, m2: Real, momentum: Real, energy: Real, u1: Real
) -> InelasticBalance:
    """The kinetic energy of two balls of total momentum ``momentum`` when ball 1 moves at
    ``u1``, and twice its excess over ``energy`` ((8.2) with (8.4a) put in: the quadratic
    (8.4b) in u1). Plain operators: exact with Fractions."""
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    inputs.real(momentum, "momentum")
    inputs.real(energy, "energy")
    inputs.real(u1, "u1")
    u2 = (momentum - m1 * u1) / m2  # the momentum left for ball 2
    kinetic = m1 * u1 * u1 / 2 + m2 * u2 * u2 / 2
    return InelasticBalance(u2, kinetic, 2 * (kinetic - energy))


def min_energy_retention(m1: Real, m2: Real) -> Real:
    """Lowest kinetic-energy retention KE_FIN / KE_IN of a collision from the start
    (V1, V2) = (V_IN, -V_IN) of Fig. 8.3-8.4 (the Bang(1) point): the totally inelastic
    (Ka-runch) final state at V_COM, where the energy ellipse shrinks to touch the momentum line
    ((8.6), Fig. 8.3c). Exact with Fractions."""
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    start = (1, -1)
    hit = collide(m1, m2, start[0], start[1], 0)
    before = m1 * start[0] ** 2 + m2 * start[1] ** 2
    after = m1 * hit.v1 * hit.v1 + m2 * hit.v2 * hit.v2
    return after / before


def min_retention_velocity_ratio(m1: Symbolic, m2: Symbolic) -> Symbolic:
    """V_COM / V_IN for the start (V_IN, -V_IN): the common velocity of the totally inelastic
    collision over the initial speed ((8.6a)), from ``collide`` with restitution 0."""
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    return collide(m1, m2, 1, -1, 0).v1


def mass_ratio_for_retention(r_min: Real) -> float:
    """The mass ratio m2 / m1 <= 1 whose lowest energy retention (``min_energy_retention``)
    from the start (V_IN, -V_IN) is ``r_min`` ((8.6b) read backward), by bisection: the
    retention falls from 1 to 0 as m2 / m1 goes from 0 to 1."""
    inputs.real(r_min, "r_min")
    if not 0 < r_min < 1:
        raise ValueError(f"a retention ratio lies between 0 and 1, got {r_min!r}")
    lo, hi = 0.0, 1.0
    while True:  # halving [lo, hi] until no float lies between them
        mid = (lo + hi) / 2
        if mid in (lo, hi):
            break
        if float(min_energy_retention(1.0, mid)) > r_min:
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


def retention_from_radii(mass: Real, radius_in: Real, radius_fin: Real) -> Real:
    """Kinetic-energy retention KE_FIN / KE_IN read off the radii of two energy ellipses along
    the velocity axis of ``mass`` (Fig. 8.3-8.4): an ellipse (3.7) reaches V = radius on that
    axis, where all the energy is that ball's, KE = mass radius^2 / 2."""
    inputs.mass(mass, "mass")
    inputs.positive(radius_in, "radius_in")
    inputs.positive(radius_fin, "radius_fin")

    def energy(radius: Real) -> Real:
        return mass * radius * radius / 2

    return energy(radius_fin) / energy(radius_in)


def equal_velocity_line_angle(v_com: Real) -> float:
    """Angle of the line through (V_COM, V_COM) and the origin (V1 = V2), radians: the 45-degree
    line on which the totally inelastic point of Fig. 8.3c-8.4 lies."""
    inputs.real(v_com, "v_com")
    if v_com == 0:
        raise ValueError("the origin is on every line: give a non-zero V_COM")
    return math.atan2(v_com, v_com) if v_com > 0 else math.atan2(-v_com, -v_com)


@dataclass(frozen=True)
class PileUp:
    """A chain of Ka-runch (totally inelastic) collisions (Figs. 8.5-8.6).

    ``slopes[k]`` is the pile's mass over the added car's before the k-th collision (the
    velocity-velocity slope k:1 of the momentum line) and ``inverse_slopes`` their reciprocals
    (1/1, 1/2, ...); energies are kinetic energies, ``energy_lost`` the total loss.
    """

    momentum_in: Real
    energy_in: Real
    final_mass: Real
    final_velocity: Real
    momentum_out: Real
    energy_out: Real
    energy_lost: Real
    slopes: tuple[Real, ...]
    inverse_slopes: tuple[Real, ...]


def pile_up(car_mass: Real, car_speed: Real, moving_cars: int, stationary_cars: int) -> PileUp:
    """Pile up ``moving_cars`` cars at ``car_speed`` and ``stationary_cars`` cars at rest, all of
    ``car_mass``, by Ka-runch collisions (``collide`` with restitution 0).

    One moving car plows through a line of stationary ones (Fig. 8.5), or a line of moving cars
    rams one stationary car, one after the other (Fig. 8.6). Other mixtures have many possible
    orders (Fig. 8.7) and are refused.
    """
    inputs.mass(car_mass, "car_mass")
    inputs.real(car_speed, "car_speed")
    moving = inputs.count(moving_cars, "moving_cars", minimum=1)
    still = inputs.count(stationary_cars, "stationary_cars", minimum=1)
    if moving > 1 and still > 1:
        raise ValueError("a mixed pile-up has many possible orders (Fig. 8.7): give one side 1")
    momentum_in = moving * car_mass * car_speed
    energy_in = moving * car_mass * car_speed * car_speed / 2
    added_v: Real
    if moving == 1:
        pile_mass, pile_v, added, added_v = car_mass, car_speed, still, 0 * car_speed
    else:
        pile_mass, pile_v, added, added_v = car_mass, 0 * car_speed, moving, car_speed
    slopes = []
    for _ in range(added):
        slopes.append(pile_mass / car_mass)
        hit = collide(pile_mass, car_mass, pile_v, added_v, 0)
        pile_mass, pile_v = pile_mass + car_mass, hit.v1
    energy_out = pile_mass * pile_v * pile_v / 2
    return PileUp(
        momentum_in=momentum_in,
        energy_in=energy_in,
        final_mass=pile_mass,
        final_velocity=pile_v,
        momentum_out=pile_mass * pile_v,
        energy_out=energy_out,
        energy_lost=energy_in - energy_out,
        slopes=tuple(slopes),
        inverse_slopes=tuple(1 / s for s in slopes),
    )


# --- the pellet rocket: (8.7), Fig. 8.8 -------------------------------------------------------


@dataclass(frozen=True)
class PelletRocket:
    """A line of equal balls blown apart one at a time from the rear (8.7), Fig. 8.8.

    Balls are numbered 0 (rear) to N-1 (the payload, ``payload_label``); blast b (0 ... N-2,
    ``last_blast``; ``blasts`` in all) blows ball b back at the exhaust velocity relative to the
    rocket before the blast. ``rocket_masses[b]`` is the mass left after blast b (the 10m, 9m, ...
    of (8.7)); ``boosts[b]`` the rocket's velocity gain dV_M(b) = -m v_e / M_b; ``velocities[b]``
    its velocity V(b) after blast b (partial sums of the harmonic series); ``slopes[b]`` the
    pow(b)-line slope -m / M_b; ``pellet_momentum`` m v_e; ``pellet_velocities[b]`` ball b's
    final velocity in the starting frame; ``total_momenta[b]`` the momentum of all the balls
    after blast b (zero: "zero-sum"); ``first_fast_blast`` the first blast after which the rocket
    outruns the exhaust speed; ``first_forward_pellet`` the first ball to end up moving forward.
    """

    payload_label: int
    last_blast: int
    blasts: int
    rocket_masses: tuple[Real, ...]
    boosts: tuple[Real, ...]
    velocities: tuple[Real, ...]
    slopes: tuple[Real, ...]
    pellet_momentum: Real
    pellet_velocities: tuple[Real, ...]
    total_momenta: tuple[Real, ...]
    first_fast_blast: int | None
    first_forward_pellet: int | None


def pellet_rocket(n_balls: int, pellet_mass: Real, exhaust_velocity: Real) -> PelletRocket:
    """Blow the pellets off a line of ``n_balls`` equal balls at rest, one per blast (8.7).

    Each blast conserves momentum: m dv_b + M_b dV_M(b) = 0 with dv_b = ``exhaust_velocity``
    (negative: backward) relative to the rocket's velocity before the blast. Exact with Fraction
    inputs.
    """
    n = inputs.count(n_balls, "n_balls", minimum=2)
    inputs.mass(pellet_mass, "pellet_mass")
    inputs.real(exhaust_velocity, "exhaust_velocity")
    if exhaust_velocity > 0:
        raise ValueError("the exhaust goes backward: exhaust_velocity <= 0")
    v = 0 * exhaust_velocity
    masses, boosts, velocities, slopes, pellets, totals = [], [], [], [], [], []
    for b in range(n - 1):
        rest = (n - 1 - b) * pellet_mass
        boost = -pellet_mass * exhaust_velocity / rest
        pellets.append(v + exhaust_velocity)
        v = v + boost
        masses.append(rest)
        boosts.append(boost)
        velocities.append(v)
        slopes.append(-pellet_mass / rest)
        totals.append(sum(pellet_mass * p for p in pellets) + rest * v)
    fast = [b for b, vb in enumerate(velocities) if vb > -exhaust_velocity]
    forward = [b for b, pb in enumerate(pellets) if pb > 0]
    return PelletRocket(
        payload_label=n - 1,
        last_blast=n - 2,
        blasts=n - 1,
        rocket_masses=tuple(masses),
        boosts=tuple(boosts),
        velocities=tuple(velocities),
        slopes=tuple(slopes),
        pellet_momentum=pellet_mass * exhaust_velocity,
        pellet_velocities=tuple(pellets),
        total_momenta=tuple(totals),
        first_fast_blast=fast[0] if fast else None,
        first_forward_pellet=forward[0] if forward else None,
    )


def retained_ellipse_radius(mass: Real, radius_in: Real, retention: Real) -> Real:
    """Radius, along the velocity axis of ``mass``, of the energy ellipse that keeps the share
    ``retention`` = KE_FIN / KE_IN of the energy of the ellipse of radius ``radius_in`` (Fig.
    8.3b): the ellipse (3.7) reaches V = radius on that axis, where KE = mass radius^2 / 2."""
    inputs.mass(mass, "mass")
    inputs.positive(radius_in, "radius_in")
    inputs.real(retention, "retention")
    if not 0 <= retention <= 1:
        raise ValueError(f"a retention ratio lies between 0 and 1, got {retention!r}")
    energy_in = kinetic_energy((mass,), (radius_in,))
    return velocity_radius(mass, retention * energy_in)


@dataclass(frozen=True)
class RocketBlast:
    """One blast b of the pellet rocket (8.7): the rocket's mass after it (the (10 - b) m of
    (8.7b)), its velocity boost dV_M(b), its velocity V(b) after it and ``terms``, how many of
    the boosts (terms of the harmonic series for unit pellets) add up to V(b)."""

    rocket_mass: Real
    boost: Real
    velocity: Real
    terms: int


def rocket_blast(
    n_balls: int, pellet_mass: Real, exhaust_velocity: Real, blast: int
) -> RocketBlast:
    """Blast number ``blast`` (0 ... N-2) of the pellet rocket of ``pellet_rocket``."""
    b = inputs.count(blast, "blast")
    rocket = pellet_rocket(n_balls, pellet_mass, exhaust_velocity)
    if b >= rocket.blasts:
        raise ValueError(f"the rocket has blasts 0 to {rocket.last_blast}, not {b}")
    sums = list(itertools.accumulate(rocket.boosts))  # the partial sums, as the rocket adds them
    terms = sums.index(rocket.velocities[b]) + 1
    return RocketBlast(rocket.rocket_masses[b], rocket.boosts[b], rocket.velocities[b], terms)


def blasts_leaving(n_balls: int, remaining: int) -> int:
    """Number of blasts after which ``remaining`` of the ``n_balls`` balls are left in the
    rocket (Fig. 8.8): the blasts of ``pellet_rocket`` counted until its mass is ``remaining``
    pellets."""
    n = inputs.count(n_balls, "n_balls", minimum=2)
    k = inputs.count(remaining, "remaining", minimum=1)
    if k >= n:
        raise ValueError("a blast leaves fewer balls than the rocket started with")
    rocket = pellet_rocket(n, 1, -1)
    return next(b + 1 for b, mass in enumerate(rocket.rocket_masses) if mass == k)


def rocket_remaining(n_balls: int, remaining: int) -> tuple[int, ...]:
    """Labels of the balls still in the rocket when ``remaining`` of the ``n_balls`` are left
    (Fig. 8.8): the pellets go from the rear, ball 0 first, so the last ``remaining`` labels
    stay, the payload N - 1 at the head."""
    n = inputs.count(n_balls, "n_balls", minimum=1)
    k = inputs.count(remaining, "remaining", minimum=1)
    if k > n:
        raise ValueError("more balls remaining than the rocket had")
    return tuple(range(n - k, n))
