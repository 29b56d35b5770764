"""Laws of towers, pile-ups and the pellet rocket (mechmodel.towers): chapter 8.

Fraction inputs must give exact equality; the zero-gap tower is held to its declared error.
"""

from __future__ import annotations

import itertools
import math
from fractions import Fraction

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from checks.properties.strategies import (
    SOFT_ENERGY_DRIFT,
    ball_counts,
    contact_powers,
    fraction_quantities,
    fraction_tower_masses,
    moderate_fraction_masses,
    rationals,
    soft_masses,
)
from mechmodel import towers
from mechmodel.collisions import center_of_mass_velocity, kinetic_energy, momentum

pytestmark = pytest.mark.properties


@given(fraction_tower_masses(), fraction_quantities())
@example([Fraction(100), Fraction(30), Fraction(10)], Fraction(1))  # Fig. 8.1(b)
def test_independent_tower_launch_law(masses: list[Fraction], v_drop: Fraction) -> None:
    """Dropped at speed v, an independent-collision tower launches its top ball at V_top with
    V_top + v = 2 v prod_k 2 m_k / (m_k + m_(k+1)) (Figs. 8.1(b), 8.2), exactly. Every velocity
    is proportional to v: the book's towers, dropped at unit speed, give them in units of v."""
    tower = towers.independent_tower(masses, v_drop)
    product = Fraction(1)
    for lower, upper in itertools.pairwise(masses):
        product *= 2 * lower / (lower + upper)
    assert tower.velocities[-1] + v_drop == 2 * v_drop * product
    unit = towers.independent_tower(masses)
    assert unit.rebound == 1
    assert tower.rebound == v_drop
    assert tower.velocities == tuple(v_drop * u for u in unit.velocities)
    # each bang moves along its momentum line, of slope -m_k/m_(k+1) (Fig. 8.1(b))
    for bang, slope in zip(tower.bangs, tower.momentum_slopes, strict=True):
        (u1, u2), (w1, w2) = bang.before, bang.after
        assert w2 - u2 == -slope * (w1 - u1)
    # the top ball's kinetic energy grows by (V_top/v)^2 (after Fig. 8.2)
    top = masses[-1]
    boost = kinetic_energy((top,), (tower.velocities[-1],)) / kinetic_energy((top,), (v_drop,))
    assert tower.energy_boost == boost == towers.energy_boost(tower.velocities[-1], v_drop)
    assert towers.energy_boost(unit.velocities[-1]) == boost


@given(fraction_tower_masses())
def test_independent_tower_stays_under_the_inf_limit(masses: list[Fraction]) -> None:
    """Finite masses launch the top ball of N balls below the INF limit 2^N - 1 (Fig. 4.5,
    exercise 1.8.2), which ``inf_limit_tower`` reaches exactly: ball k leaves at (2^k - 1) v."""
    n = len(masses)
    limit = towers.inf_limit_tower(n, 1)[-1]
    assert limit == 2**n - 1
    # ball k leaves its immovable partner at 2 V + v: V_k = (2^k - 1) v
    v = masses[0]
    assert towers.inf_limit_tower(n, v) == tuple((2**k - 1) * v for k in range(1, n + 1))
    assert towers.inf_limit_tower(n) == towers.inf_limit_tower(n, 1)
    assert towers.independent_tower(masses, 1).velocities[-1] < limit or n == 1


@given(ball_counts(), moderate_fraction_masses())
def test_geometric_tower_launch(n: int, ratio: Fraction) -> None:
    """A tower of N balls, each r times the next, launches at 2 (2r / (r + 1))^(N-1) - 1
    (Fig. 8.2: 5.75 for r = 3, 9.72 for r = 7, N = 4)."""
    top = towers.geometric_tower(n, ratio).velocities[-1]  # dropped at the default unit speed
    assert top == 2 * (2 * ratio / (ratio + 1)) ** (n - 1) - 1


@given(ball_counts())
def test_identical_column_needs_triangular_number_of_bangs(n: int) -> None:
    """A column of N identical balls needs N (N + 1) / 2 independent bangs (Fig. 8.2(c-d)),
    whatever the drop speed (the count is scale-free)."""
    assert towers.column_bounce_bangs(n) == n * (n + 1) // 2
    assert towers.column_bounce_bangs(n, 1, Fraction(7, 3)) == n * (n + 1) // 2


@given(ball_counts(), rationals(3, 20, 10))
@example(2, Fraction(3))  # 3:1 stops ball 1 dead (point M of Fig. 4.5b)
@example(4, Fraction(3))  # the 3:1 tower of Fig. 8.2
def test_a_column_three_times_heavier_at_each_step_bangs_once_per_ball(
    n: int, ratio: Fraction
) -> None:
    """With each ball at least 3 times the one above it, a dropped column makes only the N
    bangs of the independent tower, the floor bounce and Bang(2)12, Bang(3)23, ... (Fig. 8.2):
    a ball rising at V >= v off a bang with a ball r >= 3 times lighter keeps
    ((r - 1) V - 2 v)/(r + 1) >= 0 (at r = 3 ball 1 stops dead, Fig. 4.5b's point M), so
    nothing falls back onto the floor or catches up again."""
    assert towers.column_bounce_bangs(n, ratio) == n
    assert towers.column_bounce_bangs(n, ratio, Fraction(1, 3)) == n
    tower = towers.geometric_tower(n, ratio)
    assert all(v >= 0 for v in tower.velocities)
    assert list(tower.velocities) == sorted(tower.velocities)


@given(moderate_fraction_masses(), fraction_quantities(), st.integers(1, 6), st.integers(1, 6))
@example(Fraction(1), Fraction(0), 1, 3)  # cars at rest: nothing moves, nothing is lost
@example(Fraction(1), Fraction(0), 3, 1)
def test_pile_up_keeps_momentum_and_loses_energy(
    mass: Fraction, speed: Fraction, moving: int, still: int
) -> None:
    """Ka-runch pile-ups keep the momentum and lose energy (Figs. 8.5-8.6), exactly: the final
    energy P^2/2M is the incoming one times moving/(moving + still) cars; the slopes run 1:1,
    2:1, 3:1, ..., their inverses the harmonic progression 1/1, 1/2, 1/3, .... Several moving
    cars meeting several at rest have many orders (Fig. 8.7) and are refused."""
    if moving > 1 and still > 1:
        with pytest.raises(ValueError, match="many possible orders"):
            towers.pile_up(mass, speed, moving, still)
        still = 1
    pile = towers.pile_up(mass, speed, moving, still)
    assert pile.momentum_out == pile.momentum_in == momentum([mass] * moving, [speed] * moving)
    assert pile.final_mass == (moving + still) * mass
    assert pile.final_velocity * pile.final_mass == pile.momentum_in
    assert pile.energy_in == kinetic_energy([mass] * moving, [speed] * moving)
    assert pile.energy_out == kinetic_energy((pile.final_mass,), (pile.final_velocity,))
    assert pile.energy_lost == pile.energy_in - pile.energy_out >= 0
    # the same momentum P in more mass: the energy P^2/2M falls as the mass grows
    assert pile.energy_out * (moving + still) == pile.energy_in * moving
    assert pile.slopes == tuple(range(1, len(pile.slopes) + 1))
    assert pile.inverse_slopes == tuple(1 / Fraction(k) for k in pile.slopes)


@given(st.integers(2, 15), moderate_fraction_masses(), fraction_quantities())
@example(4, Fraction(1), Fraction(0))  # a dud exhaust: every blast is allowed, nothing moves
def test_pellet_rocket_momentum_is_zero_sum(n: int, m: Fraction, speed: Fraction) -> None:
    """Every blast keeps the total momentum zero (8.7), and the rocket's velocity is the partial
    sum of the boosts m |ve| / M_b: the harmonic series for unit pellets, exactly. Pellet b
    leaves at the exhaust velocity relative to the rocket before blast b (Fig. 8.8), so the
    first pellet to fly forward follows the first blast after which the rocket outruns the
    exhaust speed. The exhaust goes backward: a forward one is refused."""
    rocket = towers.pellet_rocket(n, m, -speed)
    assert all(p == 0 for p in rocket.total_momenta)
    if speed:
        with pytest.raises(ValueError, match="backward"):
            towers.pellet_rocket(n, m, speed)
    for b, v in enumerate(rocket.velocities):
        assert v == speed * sum(Fraction(1, n - 1 - j) for j in range(b + 1))
    assert (rocket.payload_label, rocket.last_blast, rocket.blasts) == (n - 1, n - 2, n - 1)
    assert rocket.pellet_momentum == -m * speed
    before = (0, *rocket.velocities)
    for b in range(n - 1):
        assert rocket.rocket_masses[b] == (n - 1 - b) * m  # the 10m, 9m, ... of (8.7)
        # pellet b leaves at -|ve| relative to the rocket before its blast, whose boost
        # cancels its momentum (zero-sum, (8.7a)); the pow(b) line has slope -m/M_b
        assert rocket.pellet_velocities[b] == before[b] - speed
        assert rocket.rocket_masses[b] * rocket.boosts[b] == -rocket.pellet_momentum
        assert rocket.velocities[b] - before[b] == rocket.boosts[b]
        assert rocket.slopes[b] == -m / rocket.rocket_masses[b]
    fast = rocket.first_fast_blast
    assert fast is None or rocket.velocities[fast] > speed >= before[fast]
    # the first pellet to fly forward is the one after the rocket outruns its exhaust
    following = None if fast is None or fast + 1 > n - 2 else fast + 1
    assert rocket.first_forward_pellet == following
    if fast is None:
        assert rocket.velocities[-1] <= speed


@given(st.integers(min_value=1, max_value=12), st.integers(min_value=1, max_value=12))
@example(3, 3)  # the payload alone
def test_the_rocket_keeps_its_front_balls(n: int, remaining: int) -> None:
    """The pellets go from the rear, ball 0 first (Fig. 8.8): the k balls still in the rocket
    are the last k labels, the payload N - 1 at the head; no more than N can remain."""
    if remaining > n:
        with pytest.raises(ValueError, match="more balls"):
            towers.rocket_remaining(n, remaining)
        return
    left = towers.rocket_remaining(n, remaining)
    assert len(left) == remaining
    assert left[-1] == n - 1
    assert list(left) == list(range(left[0], left[0] + remaining))


@given(st.floats(min_value=-1e3, max_value=1e3).map(lambda v: v or 1.0))  # not 0
def test_the_totally_inelastic_point_is_on_the_45_degree_line(v_com: float) -> None:
    """The Ka-runch point (V_COM, V_COM) lies on the line V1 = V2 through the origin, at 45
    degrees, whichever the sign of V_COM (Fig. 8.3c-8.4); the origin alone fixes no line."""
    assert math.isclose(towers.equal_velocity_line_angle(v_com), math.pi / 4, rel_tol=1e-15)
    with pytest.raises(ValueError, match="origin"):
        towers.equal_velocity_line_angle(0)


@given(moderate_fraction_masses(), moderate_fraction_masses(), st.data())
def test_inelastic_quadratic_roots_keep_momentum_and_energy(
    m1: Fraction, m2: Fraction, data: st.DataObject
) -> None:
    """The roots of (8.4b) are the two velocities u1 with the given momentum and energy; their
    mean is V_COM, and the book's coefficients -2 pu and -2 ku are read off."""
    u1 = data.draw(rationals(-5, 5, 10))
    u2 = data.draw(rationals(-5, 5, 10))
    p = m1 * u1 + m2 * u2
    k = kinetic_energy((m1, m2), (u1, u2))
    quad = towers.inelastic_quadratic(m1, m2, p, k)
    assert quad.energy_coefficient == 2
    if p:
        assert quad.momentum_coefficient == 2
    assert quad.roots is not None
    assert any(math.isclose(r, float(u1), rel_tol=1e-9, abs_tol=1e-9) for r in quad.roots)
    assert math.isclose(sum(quad.roots) / 2, float(p / (m1 + m2)), rel_tol=1e-9, abs_tol=1e-9)
    assert quad.v_com == center_of_mass_velocity((m1, m2), (u1, u2))


@given(moderate_fraction_masses(), moderate_fraction_masses(), st.data())
def test_energy_balance_follows_the_momentum_line(
    m1: Fraction, m2: Fraction, data: st.DataObject
) -> None:
    """Along the momentum line (8.1) ball 2 carries what momentum ball 1 leaves (8.4a); the
    kinetic energy there is the pair's, and twice its excess over a given K, the left side of
    (8.4b), vanishes at K = the pair's energy, exactly with Fractions."""
    u1 = data.draw(rationals(-5, 5, 10))
    u2 = data.draw(rationals(-5, 5, 10))
    p = m1 * u1 + m2 * u2
    k = kinetic_energy((m1, m2), (u1, u2))
    balance = towers.inelastic_energy_balance(m1, m2, p, k, u1)
    assert balance.u2 == u2
    assert balance.kinetic == k
    assert balance.twice_residual == 0
    other = data.draw(rationals(-5, 5, 10))
    shifted = towers.inelastic_energy_balance(m1, m2, p, k, other)
    assert shifted.twice_residual == 2 * (kinetic_energy((m1, m2), (other, shifted.u2)) - k)
    assert m1 * other + m2 * shifted.u2 == p


@given(moderate_fraction_masses(), moderate_fraction_masses())
@example(Fraction(2), Fraction(1))
def test_lowest_retention_is_the_square_of_the_common_velocity(m1: Fraction, m2: Fraction) -> None:
    """From the start (V_IN, -V_IN) a Ka-runch leaves both balls at V_COM: the retained share
    of the kinetic energy is (V_COM / V_IN)^2 (the pair's energy is then all its COM energy),
    exactly with Fractions, between 0 and 1; it is the square of the radius ratio of the two
    energy ellipses along either axis ((8.6), Figs. 8.3-8.4)."""
    ratio = towers.min_retention_velocity_ratio(m1, m2)
    assert isinstance(ratio, Fraction)  # exact: Fraction masses
    retention = towers.min_energy_retention(m1, m2)
    assert retention == ratio * ratio
    assert 0 <= retention <= 1
    scale = abs(ratio) if ratio else Fraction(1, 2)
    assert towers.retention_from_radii(m1, Fraction(3), 3 * scale) == scale * scale
    assert towers.retention_from_radii(m2, Fraction(3), 3 * scale) == scale * scale


@given(
    st.floats(min_value=0.1, max_value=10),
    st.floats(min_value=0.1, max_value=10),
    st.floats(min_value=1e-4, max_value=1),
)
def test_retained_radius_shrinks_as_the_root_of_the_retention(
    mass: float, radius: float, retention: float
) -> None:
    """The ellipse keeping the share R of the energy has sqrt(R) times the radius along each
    axis (Fig. 8.3b), whatever the axis's mass: its radius gives R back."""
    kept = towers.retained_ellipse_radius(mass, radius, retention)
    assert math.isclose(kept, radius * math.sqrt(retention), rel_tol=1e-12)
    assert math.isclose(towers.retention_from_radii(mass, radius, kept), retention, rel_tol=1e-12)
    with pytest.raises(ValueError, match="between 0 and 1"):
        towers.retained_ellipse_radius(mass, radius, 2)


@given(st.floats(min_value=1e-4, max_value=1 - 1e-4))
@example(0.25)  # m2 / m1 = 1/3
def test_mass_ratio_for_retention_inverts_it(r_min: float) -> None:
    """The mass ratio m2/m1 <= 1 found for a lowest retention gives that retention back."""
    q = towers.mass_ratio_for_retention(r_min)
    assert 0 < q <= 1
    assert math.isclose(towers.min_energy_retention(1.0, q), r_min, rel_tol=1e-12, abs_tol=1e-15)
    with pytest.raises(ValueError, match="between 0 and 1"):
        towers.mass_ratio_for_retention(1.5)


@given(st.integers(2, 15), moderate_fraction_masses(), fraction_quantities(), st.data())
def test_rocket_blast_is_one_step_of_the_rocket(
    n: int, m: Fraction, speed: Fraction, data: st.DataObject
) -> None:
    """Blast b keeps momentum: the rocket left, (N - 1 - b) m, takes the boost m |ve| / M_b
    (8.7b), and its velocity is the sum of the boosts so far; the blasts leaving k balls
    number N - k, and the first ball left is labelled with that count (Fig. 8.8)."""
    b = data.draw(st.integers(0, n - 2))
    blast = towers.rocket_blast(n, m, -speed, b)
    assert blast.rocket_mass == (n - 1 - b) * m
    assert blast.rocket_mass * blast.boost == m * speed
    assert blast.velocity == sum(towers.rocket_blast(n, m, -speed, j).boost for j in range(b + 1))
    if speed:  # the b + 1 partial sums of the boosts (the harmonic terms for unit pellets)
        assert blast.terms == b + 1
    with pytest.raises(ValueError, match="blasts 0 to"):
        towers.rocket_blast(n, m, -speed, n - 1)
    k = data.draw(st.integers(1, n - 1))
    count = towers.blasts_leaving(n, k)
    assert count == n - k
    assert towers.rocket_remaining(n, k)[0] == count


@given(st.lists(soft_masses(), min_size=2, max_size=3), contact_powers())
# Newton once hopped between two ends three roundings apart, where the integrations' own
# noise outweighed the overlap, and gave up ("touch or release not located")
@example([2.525782766927532, 0.8749282611017211], 1.1689268825665489)
def test_zero_gap_tower_keeps_energy_scales_and_stays_under_inf_limit(
    masses: list[float], power: float
) -> None:
    """A zero-gap tower (Fig. 8.1(a), (c)) conserves energy: the balls' final kinetic energy is
    what they fell with, and no ball beats the INF limit 2^N - 1. With one power law for every
    contact its final velocities are proportional to the drop speed and independent of the
    force constant (scaling time and length removes both)."""
    run = towers.zero_gap_tower(masses, power)
    finals = [e.value for e in run.velocities]
    before = kinetic_energy(masses, [1.0] * len(masses))
    assert run.energy_error <= SOFT_ENERGY_DRIFT
    assert math.isclose(kinetic_energy(masses, finals), before, rel_tol=1e-9)
    assert max(finals) < 2 ** len(masses) - 1
    other = towers.zero_gap_tower(masses, power, 3.0, 0.2)
    for a, b in zip(run.velocities, other.velocities, strict=True):
        assert abs(b.value / 3.0 - a.value) <= a.error + b.error / 3.0
    # the time scale (m / k)^(1/(n+1)) v^((1-n)/(n+1)) of F = k y^n (unit k and v by default)
    stretch = (1 / 0.2 * 3.0 ** (1 - power)) ** (1 / (power + 1))
    assert math.isclose(other.duration, stretch * run.duration, rel_tol=1e-9)
