"""Laws of bang sequences and space-time histories (mechmodel.bangs): chapters 4-5.

Fraction inputs must give exact equality; floats are compared within 1e-9 of the magnitudes
involved (a history compounds rounding over its bangs).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from decimal import Decimal
from fractions import Fraction

import mpmath
import pytest
from hypothesis import assume, example, given, target
from hypothesis import strategies as st

from checks.properties.strategies import (
    MASS_RANGE,
    drop_speeds,
    exact_histories,
    fraction_masses,
    fraction_restitutions,
    fraction_velocities,
    masses,
    moderate_fraction_masses,
)
from mechmodel.bangs import (
    BALLS,
    CEILING,
    FLOOR,
    BangSequence,
    History,
    bang_changes,
    bang_count,
    bang_history,
    bang_possible,
    bangs_in_chain,
    bounce_impulse,
    ceiling_bounce,
    ceiling_sequence,
    earth_recoil,
    figures_of_agreement,
    floor_bounce,
    floor_impulse,
    galileo_shifted_collision,
    game_over_bang,
    mass_ratio,
    sagitta_small_spot_depth,
    state_after_bangs,
    velocities_after_bang,
    x2_final_locus_angle,
    x2_full_transfer_ratio,
    x2_infinite_ratio_launch,
    x2_launch,
)
from mechmodel.collisions import center_of_mass_velocity, collide, kinetic_energy, momentum
from mechmodel.operators import bang_angle, rotation_picture_bang_count
from mechmodel.typing import Real

pytestmark = pytest.mark.properties
REL = 1e-9
HISTORY_BANGS = 12


def _history(
    args: Mapping[str, Real], max_bangs: int, floor: Real = 0, floor_bounces: int | None = None
) -> History:
    """``bang_history`` of the balls and walls of ``args`` (masses, heights, velocities and the
    ceiling, as ``exact_histories`` draws them), with the options named."""
    return bang_history(**args, floor=floor, floor_bounces=floor_bounces, max_bangs=max_bangs)


@given(fraction_velocities(), fraction_restitutions(), moderate_fraction_masses())
def test_floor_and_ceiling_reverse_the_velocity(v: Fraction, e: Fraction, m: Fraction) -> None:
    """An elastic bounce off the floor or the ceiling (an infinite mass) reverses the ball's
    velocity and keeps its speed: (V1, V2) -> (-V1, V2) off the floor, (V1, -V2) off the
    ceiling (p. 4.11, Fig. 4.7b); with restitution e it leaves at -e v. The floor takes the
    ball's momentum change m (1 + e) |v|: 2 m |v| elastic, m |v| for a Ka-runch (Fig. 4.2a)."""
    assert floor_bounce(v) == -v
    assert ceiling_bounce(v) == -v
    assert floor_bounce(v, e) == -e * v == ceiling_bounce(v, e)
    assert floor_impulse(m, v, e) == abs(m * floor_bounce(v, e) - m * v)
    assert floor_impulse(m, v) == 2 * floor_impulse(m, v, 0) == 2 * m * abs(v)


@given(moderate_fraction_masses(), drop_speeds(), fraction_restitutions())
@example(Fraction(3, 50), Fraction(1), Fraction(1))  # 2 M2 V0 of the 60 gm super-ball
def test_a_ball_hitting_the_floor_at_speed_v0_gives_it_m_1_plus_e_v0(
    m: Fraction, v0: Fraction, e: Fraction
) -> None:
    """A ball of mass m arriving at -V0 (point I0 of Fig. 4.2a) gives the floor the momentum
    m (1 + e) V0: 2 M2 V0 for an elastic bounce, M2 V0 for a Ka-runch (after Fig. 4.2a); a
    negative speed is refused."""
    assert bounce_impulse(m, v0, e) == floor_impulse(m, -v0, e) == m * (1 + e) * v0
    assert bounce_impulse(m, v0) == 2 * m * v0 == 2 * bounce_impulse(m, v0, 0)
    with pytest.raises(ValueError, match="negative"):
        bounce_impulse(m, -v0)


@given(moderate_fraction_masses(), moderate_fraction_masses(), drop_speeds())
def test_x2_final_points_lie_on_the_45_degree_line(
    m1: Fraction, m2: Fraction, v0: Fraction
) -> None:
    """Every elastic X2 final point has V2 - V1 = 2 V0 (the relative velocity reverses), so all
    lie on the 45-degree line CPL of Fig. 4.5a, and the bang keeps the kinetic energy. The
    launch depends on the mass ratio m1/m2 alone and is proportional to the drop speed (unit
    speed by default); ball 2 carries away its own share of the kinetic energy."""
    launch = x2_launch(m1, m2, v0)
    assert launch.v2 - launch.v1 == 2 * v0
    assert m1 * launch.v1**2 + m2 * launch.v2**2 == (m1 + m2) * v0**2
    unit = x2_launch(mass_ratio(m1, m2), 1)
    assert launch.start == (v0, -v0)
    assert (launch.v1, launch.v2) == (v0 * unit.v1, v0 * unit.v2)
    assert launch.speed_ratio == unit.v2
    assert launch.height_ratio == unit.v2**2
    share = kinetic_energy((m2,), (launch.v2,)) / kinetic_energy((m1, m2), launch.start)
    assert launch.energy_transfer == share
    other = mass_ratio(m1, m2) + 1
    angle = x2_final_locus_angle(float(v0), [float(mass_ratio(m1, m2)), float(other)])
    assert math.isclose(angle, math.pi / 4, rel_tol=REL)


@given(drop_speeds())
def test_x2_limits(v0: Fraction) -> None:
    """An infinite mass ratio launches ball 2 at 3 V0, nine times the drop height (point I);
    the ratio 3 stops ball 1 and gives ball 2 all the energy (point M of Fig. 4.5b)."""
    inf = x2_launch(math.inf, 1, v0)
    assert inf.speed_ratio == 3
    assert inf.height_ratio == 9
    assert x2_infinite_ratio_launch(v0).v2 == 3 * v0
    assert x2_infinite_ratio_launch().v2 == 3
    ratio = x2_full_transfer_ratio(v0)
    assert ratio == 3 == x2_full_transfer_ratio()
    full = x2_launch(Fraction(ratio), 1, v0)
    assert full.v1 == 0
    assert full.energy_transfer == 1


@given(exact_histories())
@example({"m1": 7, "m2": 1, "y1": 1, "y2": 3, "v1": -1, "v2": -1, "ceiling": 7})  # Fig. 4.7
@example({"m1": 7, "m2": 1, "y1": 0, "y2": 2, "v1": 1, "v2": -1, "ceiling": 2})  # at the walls
@example({"m1": 1, "m2": 2, "y1": 1, "y2": 1, "v1": 1, "v2": 0, "ceiling": 3})  # touching
def test_every_bang_of_a_history_conserves_what_it_should(args: dict[str, Fraction]) -> None:
    """Each bang of the independent collision model (Fig. 4.4-4.7): a ball bang keeps the total
    momentum and kinetic energy exactly and happens where the balls meet; a floor or ceiling
    bang reverses one ball's velocity where it touches, keeping every speed; time never runs
    back and ball 1 stays below ball 2 (the triangle of Fig. 4.11). Raising the floor, the
    ceiling and the balls by the same height raises every bang by it and changes nothing else.
    Bang-n is listed under its kind, and the balls move on straight lines between bangs."""
    m1, m2 = args["m1"], args["m2"]
    history = _history({k: Fraction(v) for k, v in args.items()}, max_bangs=HISTORY_BANGS)
    before: tuple[Real, Real] = (args["v1"], args["v2"])
    t: Real = 0
    for bang in history.bangs:
        after = (bang.v1, bang.v2)
        assert bang.time >= t
        assert 0 <= bang.y1 <= bang.y2 <= args["ceiling"]
        if bang.kind == BALLS:
            assert bang.y1 == bang.y2
            assert momentum((m1, m2), after) == momentum((m1, m2), before)
            assert kinetic_energy((m1, m2), after) == kinetic_energy((m1, m2), before)
        elif bang.kind == FLOOR:
            assert bang.y1 == 0
            assert after == (-before[0], before[1])
        else:
            assert bang.kind == CEILING
            assert bang.y2 == args["ceiling"]
            assert after == (before[0], -before[1])
        before, t = after, bang.time
    assert history.count <= HISTORY_BANGS
    assert history.ended or history.count == HISTORY_BANGS
    # Bang-n is listed under its kind, and every n under one kind (Fig. 4.7's numbering)
    kinds = {FLOOR: history.floor_bangs, BALLS: history.ball_bangs, CEILING: history.ceiling_bangs}
    assert sorted(n for numbers in kinds.values() for n in numbers) == list(
        range(1, history.count + 1)
    )
    for kind, numbers in kinds.items():
        assert all(history.bangs[n - 1].kind == kind for n in numbers)
    # the same walls and balls raised by a height s: the same bangs, s higher
    lift = Fraction(3, 2)
    raised = _history(
        {k: Fraction(v) + (lift if k in ("y1", "y2", "ceiling") else 0) for k, v in args.items()},
        floor=lift,
        max_bangs=HISTORY_BANGS,
    )
    assert [(e.kind, e.time, e.v1, e.v2) for e in raised.bangs] == [
        (e.kind, e.time, e.v1, e.v2) for e in history.bangs
    ]
    assert [(e.y1, e.y2) for e in raised.bangs] == [
        (e.y1 + lift, e.y2 + lift) for e in history.bangs
    ]
    # the balls move on straight space-time lines between bangs (Fig. 4.6)
    assert history.positions_at(0) == (args["y1"], args["y2"])
    y: tuple[Real, Real]
    t, y = Fraction(0), (Fraction(args["y1"]), Fraction(args["y2"]))
    for bang in history.bangs:
        assert history.positions_at(bang.time) == (bang.y1, bang.y2)
        mid = history.positions_at((t + bang.time) / 2)
        assert mid == ((y[0] + bang.y1) / 2, (y[1] + bang.y2) / 2)
        t, y = bang.time, (bang.y1, bang.y2)


@given(exact_histories(), st.integers(min_value=0, max_value=3))
def test_an_opened_floor_lets_ball_1_through_after_its_bounces(
    args: dict[str, Fraction], bounces: int
) -> None:
    """With the floor opened after k bounces of ball 1 (k = 1: "the floor is open after the
    initial bounce", the exercise after Fig. 5.1) the history has at most k floor bangs, and it
    is the closed-floor history up to the (k + 1)-th floor bang that no longer happens."""
    closed = _history(args, max_bangs=HISTORY_BANGS)
    opened = _history(args, floor_bounces=bounces, max_bangs=HISTORY_BANGS)
    assert len(opened.floor_bangs) <= bounces
    floors = closed.floor_bangs
    same = floors[bounces] - 1 if len(floors) > bounces else closed.count
    assert opened.bangs[:same] == closed.bangs[:same]


@given(exact_histories())
@example({"m1": 7, "m2": 1, "y1": 1, "y2": 3, "v1": -1, "v2": -1, "ceiling": 7})  # Fig. 4.7
# equal masses reaching the floor together at bang 12: a tie just past the bangs compared
@example(
    {"m1": 1, "m2": 1, "y1": 2, "y2": 3, "v1": Fraction(7, 4), "v2": -2, "ceiling": Fraction(37, 4)}
)
def test_exact_and_float_histories_agree(args: dict[str, Fraction]) -> None:
    """The event-driven history is the same computed exactly (Fraction) and in floats, bang by
    bang, up to the first near-tie of two bangs (where rounding may order them either way).
    The exact history runs one bang further, to see a tie of the last bang compared."""
    exact = _history({k: Fraction(v) for k, v in args.items()}, max_bangs=HISTORY_BANGS + 1)
    floats = _history({k: float(v) for k, v in args.items()}, max_bangs=HISTORY_BANGS)
    scale = 1 + max(abs(float(v)) for v in args.values())
    worst = 0.0
    for k, (e, f) in enumerate(zip(exact.bangs, floats.bangs, strict=False)):
        if k and e.time - exact.bangs[k - 1].time < REL * scale * (1 + float(e.time)):
            break  # a near-tie: the float order may differ from here on
        if k + 1 < exact.count and exact.bangs[k + 1].time - e.time < REL * scale * (
            1 + float(e.time)
        ):
            break
        assert f.kind == e.kind
        for a, b in ((f.time, e.time), (f.y1, e.y1), (f.y2, e.y2), (f.v1, e.v1), (f.v2, e.v2)):
            error = abs(a - float(b))
            worst = max(worst, error / (scale * (1 + abs(float(b)))))
            assert error <= REL * scale * (1 + abs(float(b)))
    target(worst, label="relative history error")


@given(moderate_fraction_masses(), moderate_fraction_masses(), fraction_velocities())
def test_without_a_floor_the_history_is_the_velocity_sequence(
    m1: Fraction, m2: Fraction, v1: Fraction
) -> None:
    """With no floor, ball 2 falling at the start, the space-time history bangs exactly as the
    velocity-only sequence (C M)^p of (5.3)-(5.4): ball and ceiling bangs alternate, with the
    same velocities, and both end at the same game-over point."""
    v2 = Fraction(-1)
    history = bang_history(
        m1, m2, Fraction(1), Fraction(2), v1, v2, ceiling=Fraction(5), floor=None
    )
    sequence = ceiling_sequence(m1, m2, v1, v2)
    assert history.ended
    assert [b.kind for b in history.bangs] == [b.kind for b in sequence.bangs]
    assert [(b.v1, b.v2) for b in history.bangs] == [(b.v1, b.v2) for b in sequence.bangs]


@given(moderate_fraction_masses(), moderate_fraction_masses(), drop_speeds())
@example(Fraction(49), Fraction(1), Fraction(1))  # Fig. 5.1: 21 bangs after the floor
def test_an_elastic_sequence_ends_as_the_rotation_picture_predicts(
    m1: Fraction, m2: Fraction, v0: Fraction
) -> None:
    """After the floor bounce (V0, -V0) the ball and ceiling bangs end after as many bangs as
    the bang clock predicts: the least n with (n + 2) theta/2 >= pi, theta the bang angle
    (5.11)-(5.13); then no bang is possible (the game-over point of Exercise 1.5.1)."""
    beta = bang_angle(float(m1), float(m2)).angle / 2
    ratio = math.pi / beta
    assume(abs(ratio - round(ratio)) > 1e-9)  # away from exact ties, where rounding decides
    sequence = ceiling_sequence(m1, m2, v0, -v0)
    assert sequence.count == rotation_picture_bang_count(m1, m2)
    assert not bang_possible(*sequence.velocities[-1])
    assert game_over_bang(m1, m2, v0, -v0) == sequence.count + 1
    # the floor bounce F, then (C M)^p: 2 p + 1 bangs, and one more if it ends on a ball bang
    p, odd = divmod(sequence.count, 2)
    assert bangs_in_chain(p) + odd == sequence.count + 1
    assert bangs_in_chain(p, 2) == bangs_in_chain(p) + 1


@given(masses(), st.floats(min_value=-5, max_value=5))
def test_the_float_sequence_ends_too(m1: float, decades: float) -> None:
    """Whatever the masses (1e-6 to 1e6, ratios up to 1e5, which keeps the count, about
    pi sqrt(m1/m2), small), the elastic sequence of (5.4) ends, with no bang possible after its
    last: the bang clock cannot tick more than pi/(theta/2) times."""
    m2 = min(max(m1 * 10.0**decades, MASS_RANGE[0]), MASS_RANGE[1])
    sequence = ceiling_sequence(m1, m2, 1.0, -1.0)
    beta = bang_angle(m1, m2).angle / 2
    assert sequence.count <= math.ceil(math.pi / beta)
    assert not bang_possible(*sequence.velocities[-1])


@given(moderate_fraction_masses(), moderate_fraction_masses(), drop_speeds())
def test_the_book_numbering_of_bangs(m1: Fraction, m2: Fraction, v0: Fraction) -> None:
    """Bang-1 is the floor bounce that leaves (V0, -V0); Bang-n (n >= 2) is the (n - 1)th bang
    of the sequence (5.4): even bangs are ball bangs (12), odd ones ceiling bangs (02). No bang
    is numbered past the last."""
    sequence = ceiling_sequence(m1, m2, v0, -v0)
    last = sequence.count + 1
    for n in range(1, last + 1):
        assert velocities_after_bang(m1, m2, v0, -v0, n) == sequence.velocities[n - 1]
        if n >= 2:
            assert sequence.bangs[n - 2].kind == (BALLS if n % 2 == 0 else CEILING)
    with pytest.raises(ValueError, match=f"ends at Bang-{last}"):
        velocities_after_bang(m1, m2, v0, -v0, last + 1)


@given(
    st.floats(min_value=-3, max_value=3).map(lambda k: 10.0**k),
    st.floats(min_value=-3, max_value=3).map(lambda k: 10.0**k),
    st.floats(min_value=-10, max_value=10),
    st.floats(min_value=-10, max_value=10),
)
@example(49.0, 1.0, 1.0, -1.0)  # Fig. 5.1: 21 bangs after the floor bounce
@example(1.0, 1.0, 1.0, 0.0)  # equal masses: a tie on a count boundary
@example(3.0, 1.0, 1.0, -1.0)  # ratio 3: another tie
@example(1.0, 1.0, 1.0, 1e-12)  # just off a tie of the ceiling count: mpmath decides
@example(6.0, 2.0, 1.0, -1.0 + 1e-12)  # just off the ratio-3 tie of the ball count
@example(6.0, 2.0, 1.0, -1.0)  # ties of ratio 3 and 1/3, and with ball 1 at rest
@example(1.0, 3.0, 1.0, -1.0)
@example(3.0, 1.0, 0.0, -1.0)
@example(1.0, 1.0, -1.0, 5e-182)  # ball 2 barely rising: one ceiling bang (its angle rounds to pi)
@example(2.0, 1.0, 1.0, 1.0)  # equal velocities: no ball bang first, whatever the angles round to
@example(1.0, 1.0, 1.0, 4.4e-19)  # in floats the first bang leaves ball 1 at 0.0, not at 4.4e-19
@example(1.0, 1.0, 2.0, 1.1125369292536007e-308)  # subnormal speeds: 300 digits decide
@example(1.0, 1.0, 0.0, 2.225073858507203e-309)
@example(1.0, 1.0, 0.0, 2.2250738585e-313)
def test_the_o1_counter_agrees_with_the_simulation(
    m1: float, m2: float, v1: float, v2: float
) -> None:
    """The rotation picture (5.12)-(5.13) counts the bangs of a pair under a ceiling without
    simulating them, and says which state follows bang n: both as bang-by-bang simulation.
    The float simulation is the reference while every state it passes stays clear of the
    boundaries v1 = v2 and v2 = 0; near one, its rounding can decide a bang (2 v_com - v1
    loses a tiny v2), so the same inputs, exact as they are, are simulated at high precision."""
    sequence = ceiling_sequence(m1, m2, v1, v2)
    if _passes_near_a_boundary(m1, m2, sequence):
        sequence = _high_precision_sequence(m1, m2, v1, v2)
    count = bang_count(m1, m2, v1, v2)
    kinds = [b.kind for b in sequence.bangs]
    assert count.total == sequence.count
    assert count.ball_bangs == kinds.count(BALLS)
    assert count.first == (kinds[0] if kinds else None)
    scale = math.hypot(v1, v2) * (1 + math.sqrt(max(m1, m2) / min(m1, m2)))
    for n in {0, sequence.count // 2, sequence.count}:
        got, want = state_after_bangs(m1, m2, v1, v2, n), sequence.velocities[n]
        assert abs(got[0] - float(want[0])) <= 1e-9 * scale
        assert abs(got[1] - float(want[1])) <= 1e-9 * scale


def _passes_near_a_boundary(m1: float, m2: float, sequence: BangSequence) -> bool:
    """Whether a state of the sequence lies within 1e-9 |V| of v2 = 0 or v1 = v2 in the
    mass-scaled plane V = (v1 sqrt(m1), v2 sqrt(m2)) of (5.6)."""
    reach = math.sqrt(1 / m1 + 1 / m2)
    for a, b in sequence.velocities:
        radius = math.hypot(a * math.sqrt(m1), b * math.sqrt(m2))
        if min(abs(float(b)) * math.sqrt(m2), abs(float(a - b)) / reach) <= 1e-9 * radius:
            return True
    return False


def _high_precision_sequence(m1: float, m2: float, v1: float, v2: float) -> BangSequence:
    """``ceiling_sequence`` of the exact values of the floats, in mpmath with 40 digits more
    than the inputs' spread of decades (so a v2 of 1e-182 next to a v1 of 1 is kept)."""
    values = [abs(x) for x in (m1, m2, v1, v2) if x]
    with mpmath.workdps(40 + math.ceil(math.log10(max(values)) - math.log10(min(values)))):
        return ceiling_sequence(*(mpmath.mpf(x) for x in (m1, m2, v1, v2)))


@given(
    moderate_fraction_masses(),
    moderate_fraction_masses(),
    fraction_velocities(),
    fraction_velocities(),
)
@example(Fraction(1), Fraction(1), Fraction(1), Fraction(1, 10**12))  # near-ties: mpmath
@example(Fraction(6), Fraction(2), Fraction(1), Fraction(1, 10**12) - 1)
@example(Fraction(2), Fraction(1), Fraction(1), Fraction(1))  # v1 = v2: the ceiling is first
def test_the_o1_counter_agrees_with_the_exact_simulation(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction
) -> None:
    """The rotation picture (5.12)-(5.13) counts the bangs of exact states as the exact
    bang-by-bang sequence (5.4) makes them, kind by kind."""
    sequence = ceiling_sequence(m1, m2, v1, v2)
    count = bang_count(m1, m2, v1, v2)
    kinds = [b.kind for b in sequence.bangs]
    assert (count.total, count.ball_bangs) == (sequence.count, kinds.count(BALLS))
    assert count.first == (kinds[0] if kinds else None)


@given(st.integers(min_value=0, max_value=3))
def test_a_mass_ratio_of_100_to_the_k_counts_the_digits_of_pi(k: int) -> None:
    """A heavy ball of mass ratio 100^k driving a light one at rest against a wall (the
    ceiling) makes as many bangs as the first k+1 digits of pi: the bang angle of (5.11) is
    about 2 / 10^k and the double bangs turn through pi in all."""
    digits = int(str(math.pi).replace(".", "")[: k + 1])
    assert bang_count(100**k, 1, 1, 0).total == digits == ceiling_sequence(100**k, 1, 1, 0).count


@given(fraction_masses(), fraction_masses(), fraction_velocities(), fraction_velocities())
def test_an_elastic_bang_changes_neither_momentum_nor_energy(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction
) -> None:
    """The independent collision model's two equations (Fig. 4.4): a ball bang leaves
    Delta P = 0 and Delta KE = 0, exactly for exact inputs."""
    changes = bang_changes(m1, m2, v1, v2)
    assert (changes.momentum_change, changes.energy_change) == (0, 0)


@given(
    moderate_fraction_masses(),
    moderate_fraction_masses(),
    fraction_velocities(),
    fraction_velocities(),
    fraction_velocities(),
    drop_speeds(),
)
@example(Fraction(1), Fraction(1), Fraction(1), Fraction(-1), Fraction(-1), Fraction(1))
def test_a_boosted_and_rescaled_collision_is_the_same_collision(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction, boost: Fraction, scale: Fraction
) -> None:
    """Galileo: boosting every velocity by u and rescaling by s turns the bang's result the same
    way (Fig. 4.5b: the U line (+1, -1) -> (-1, +1) boosted by -1 is the pool shot
    (0, -2) -> (-2, 0)); the share of the energy that changes hands, ball 1's loss and ball 2's
    gain, does not depend on the scale; equal masses, one at rest, hand over all of it."""
    if v1 + boost == 0 and v2 + boost == 0:
        boost += 1
    shifted = galileo_shifted_collision(m1, m2, v1, v2, boost, scale)
    assert shifted.before == (scale * (v1 + boost), scale * (v2 + boost))
    hit = collide(m1, m2, v1, v2)
    assert shifted.after == tuple(scale * (v + boost) for v in hit.after)
    total = 2 * kinetic_energy((m1, m2), shifted.before)
    gained = m2 * (shifted.after[1] ** 2 - shifted.before[1] ** 2)
    assert isinstance(gained, Fraction)  # exact: Fraction inputs
    assert shifted.energy_transfer == abs(gained) / total
    unscaled = galileo_shifted_collision(m1, m2, v1, v2, boost)
    assert unscaled.energy_transfer == shifted.energy_transfer
    assert unscaled.after == tuple(v + boost for v in hit.after)
    if v1 != 0 or v2 != 0:
        assert galileo_shifted_collision(m1, m2, v1, v2).after == hit.after  # no boost
    if v1 != v2:
        assert galileo_shifted_collision(m1, m1, v1, v2, -v2, scale).energy_transfer == 1


@given(fraction_masses(), fraction_masses(), fraction_velocities())
def test_the_earth_takes_a_share_m_over_m_of_a_bounce(
    m: Fraction, earth: Fraction, v0: Fraction
) -> None:
    """A ball of mass m hitting an Earth of mass M at rest (Fig. 4.2a): in the COM frame the
    Earth moves at V_COM = m V0/(m + M), a fraction m/M of the ball's speed for m << M, with
    the kinetic energy m M/(m + M)^2 of the ball's; swapping the roles keeps the share."""
    recoil = earth_recoil(m, earth)
    assert recoil.mass_fraction * earth == m
    if v0:
        com = center_of_mass_velocity((m, earth), (v0, 0))
        share = kinetic_energy((earth,), (com,)) / kinetic_energy((m,), (v0,))
        assert recoil.energy_fraction == share
    assert earth_recoil(earth, m).energy_fraction == recoil.energy_fraction
    assert recoil.energy_fraction <= Fraction(1, 4)


@given(
    st.floats(min_value=-3, max_value=3).map(lambda k: 10.0**k),
    st.floats(min_value=1e-6, max_value=0.999),
)
def test_the_saggital_depth_is_the_small_spot_limit(radius: float, spot: float) -> None:
    """The saggital d = r^2/(2R) of Fig. 4.1 is below the exact depth R - sqrt(R^2 - r^2) by
    less than a share (r/R)^2/2 of it, so it is the depth to leading order in r/R; with
    Fraction inputs it is exact."""
    r = spot * radius
    approx = sagitta_small_spot_depth(r, radius)
    exact = r * r / (radius + math.sqrt(radius * radius - r * r))  # R - sqrt(R^2 - r^2)
    assert approx <= exact * (1 + REL)
    assert exact - approx <= exact * (spot * spot / 2 + REL)
    assert sagitta_small_spot_depth(Fraction(3), Fraction(5)) == Fraction(9, 10)
    with pytest.raises(ValueError, match="positive"):
        sagitta_small_spot_depth(0.0, radius)


@given(
    st.integers(min_value=2, max_value=9),
    st.integers(min_value=0, max_value=10),
    st.integers(min_value=1, max_value=4),
    st.booleans(),
    st.integers(min_value=-30, max_value=30),
)
@example(6, 1, 3, False, 24)  # the Earth's 6e24 kg for 5.97e24 kg: good to 2 figures
def test_figures_of_agreement_count_the_rounded_figures(
    digit: int, zeros: int, last: int, above: bool, exponent: int
) -> None:
    """A one-figure value d x 10^e agrees with d.00...0j x 10^e (z zeros after the point, j
    from 1 to 4) or with the value as far below d to z + 1 significant figures: rounding it to
    that many gives d, one more figure does not (the Earth's 6e24 kg, 'good to 2 figures',
    after Fig. 4.2), and with d.6 x 10^e to none; several pairs agree to the fewest figures of
    any. A one-figure value agrees with itself to all 15 figures a double holds."""
    step = Decimal(last).scaleb(-(zeros + 1))
    precise = float((digit + step if above else digit - step).scaleb(exponent))
    approx = float(Decimal(digit).scaleb(exponent))
    assert figures_of_agreement([approx], [precise]) == zeros + 1
    assert figures_of_agreement([approx, approx], [precise, precise]) == zeros + 1
    assert figures_of_agreement([approx, approx], [precise, approx]) == zeros + 1
    assert figures_of_agreement([approx], [approx]) == 15
    off = float((digit + Decimal("0.6")).scaleb(exponent))  # rounds to d + 1: no figure agrees
    assert figures_of_agreement([approx], [off]) == 0
    with pytest.raises(ValueError, match="positive"):
        figures_of_agreement([0.0], [precise])
    with pytest.raises(ValueError, match="positive"):
        figures_of_agreement([approx], [0.0])


@given(
    st.integers(min_value=-2, max_value=2),
    st.integers(min_value=-2, max_value=2),
    st.booleans(),
    st.booleans(),
)
def test_the_game_is_over_when_the_history_has_no_next_bang(
    v1: int, v2: int, floor: bool, ceiling: bool
) -> None:
    """Another bang is possible exactly when the space-time history from that state has one:
    ball 1 gaining on ball 2, ball 2 rising to a ceiling or ball 1 falling to a floor; balls
    at rest relative to each other and to the walls are at the game-over point (5.13)."""
    history = bang_history(
        Fraction(2),
        Fraction(1),
        Fraction(1),
        Fraction(2),
        Fraction(v1),
        Fraction(v2),
        ceiling=Fraction(3) if ceiling else None,
        floor=0 if floor else None,
        max_bangs=1,
    )
    assert bang_possible(v1, v2, floor=floor, ceiling=ceiling) == (history.count == 1)
