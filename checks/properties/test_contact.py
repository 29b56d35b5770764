"""Laws of contact geometry, targets and the soft-contact integrator (mechmodel.contact):
chapter 7.

Geometry is compared within 1e-12 of the magnitudes involved, exactly with Fractions. The
integrator is held to its own declared error and to energy conserved within 1e-9 relative.
Integrator properties draw small systems (two or three balls): each example integrates a
collision twice (for its error).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from fractions import Fraction
from typing import Any

import pytest
from hypothesis import assume, example, given, target
from hypothesis import strategies as st

from checks.properties.closeness import real, reals
from checks.properties.strategies import (
    SOFT_ENERGY_DRIFT,
    closing_speeds,
    contact_powers,
    fraction_quantities,
    gaps,
    positive_quantities,
    rationals,
    soft_masses,
)
from mechmodel import contact, fields
from mechmodel.collisions import collide
from mechmodel.softcontact import collision as softrun

pytestmark = pytest.mark.properties
REL = 1e-12


# --- the dent (7.1)-(7.4) -----------------------------------------------------------------------


@given(gaps(), st.floats(min_value=0, max_value=2))
@example(1.0, 2.0)  # pressed flat through the whole diameter: a point again
def test_flat_radius_is_the_geometric_mean(radius: float, fraction: float) -> None:
    """r^2 = x (2R - x): the flat's radius is the geometric mean of the depth and the rest of
    the diameter (7.1a), widest (r = R) at x = R; the exact sagitta takes r back to x (7.1b) on
    the near half; d(r^2)/dx is 2R - 2x, the 2R of r^2 ~ 2 R x at first contact. A depth beyond
    the diameter, or a flat wider than the ball, is a ValueError."""
    depth = fraction * radius
    r = contact.flat_spot_radius(radius, depth)
    assert math.isclose(r * r, depth * (2 * radius - depth), rel_tol=4 * REL, abs_tol=REL)
    assert r <= radius * (1 + REL)
    if depth <= radius:
        near = contact.sagitta(radius, r)
        assert math.isclose(near, depth, rel_tol=1e-9, abs_tol=1e-9 * radius)
    h = 1e-6 * radius
    quotient = (depth + h) * (2 * radius - depth - h) - (depth - h) * (2 * radius - depth + h)
    slope = contact.flat_area_slope(radius, depth)
    assert math.isclose(slope, quotient / (2 * h), rel_tol=1e-6, abs_tol=1e-6 * radius)
    assert math.isclose(contact.flat_area_slope(radius, 0), 2 * radius, rel_tol=4 * REL)
    with pytest.raises(ValueError, match="diameter"):
        contact.flat_spot_radius(radius, 2.5 * radius)
    with pytest.raises(ValueError, match="between 0 and R"):
        contact.sagitta(radius, 1.5 * radius)


@given(fraction_quantities(), rationals(0, 1, 12))
def test_dent_volume_is_the_integral_of_the_flat(radius: Fraction, fraction: Fraction) -> None:
    """V(X) = R pi X^2 - pi X^3 / 3 (7.4); at X = 2R the whole ball, 4/3 pi R^3, exactly."""
    depth = 2 * radius * fraction
    dent = contact.dent_volume(radius, depth)
    assert math.isclose(
        dent.volume,
        math.pi * float(radius * depth**2 - depth**3 / 3),
        rel_tol=4 * REL,
        abs_tol=REL,
    )
    assert dent.whole_ball == Fraction(4, 3)
    # the powers of X of its terms, the 3 of X^3 / 3, V ~ R pi X^2 for a shallow dent, and the
    # whole ball's R^3
    assert (dent.quadratic_power, dent.cubic_power, dent.cubic_denominator) == (2, 3, 3)
    assert abs(dent.small_dent_power - 2) <= 1e-8
    assert abs(dent.whole_ball_power - 3) <= 1e-12
    with pytest.raises(ValueError, match="diameter"):  # no dent goes deeper than the ball
        contact.dent_volume(radius, radius * Fraction(5, 2))


@given(positive_quantities(), gaps(), st.floats(min_value=0, max_value=1))
def test_balloon_stiffness_is_the_slope_of_its_force(p: float, radius: float, u: float) -> None:
    """dF/dx of the balloon P pi x (2R - x) is 2 pi P (R - x): 2 pi P R at first contact (7.2)."""
    depth = u * radius
    k = contact.balloon_stiffness(p, radius, depth)
    assert math.isclose(k, 2 * math.pi * p * (radius - depth), rel_tol=8 * REL, abs_tol=REL * p)


# --- targets (Figs. 7.3-7.4, (7.8)) -----------------------------------------------------------


@given(fraction_quantities(), fraction_quantities())
def test_constant_target_removes_the_fall_energy(height: Fraction, distance: Fraction) -> None:
    """A constant target's force times its stopping distance is the fall's energy (7.5a)."""
    target_ = contact.constant_force_target(height, distance)
    assert target_.force * distance == height
    assert target_.potential_slope == -target_.force
    assert contact.work_of_constant_force(target_.force, distance) == target_.energy == height
    # in units of g the deceleration is the force per weight, whichever sign g is written with
    assert contact.deceleration(target_.force, -distance) == target_.force * distance == height
    # a longer stop: the force falls as the distance grows (Fig. 7.3c)
    assert contact.stopping_force_reduction(height, distance, 5 * distance) == 5


@given(fraction_quantities(), fraction_quantities())
@example(Fraction(0), Fraction(0))  # no force over no distance
def test_ramp_work_is_half_force_times_distance(force: Fraction, distance: Fraction) -> None:
    """A linear force ramp does the triangle's work F d / 2 (the area under F(x), (7.5a)),
    exactly; over no distance it does none."""
    assert contact.ramp_work(force, distance) == force * distance / 2
    assert contact.ramp_work(force, 0) == 0


@given(fraction_quantities(), fraction_quantities())
def test_vertex_is_where_the_force_vanishes(a: Fraction, b: Fraction) -> None:
    """The vertex of a y^2 + b y is at -b/2a, depth -b^2/4a (7.8), where the force -2a y - b
    vanishes; exactly."""
    v = contact.parabola_vertex(a, b)
    f = contact.quadratic_potential_force(a, b)
    assert f.slope * v.y_shift + f.constant == 0
    assert (v.y_shift, v.u_shift) == (-b / (2 * a), -b * b / (4 * a))
    assert (v.shift_denominator, v.depth_denominator) == (2, 4)
    # f = -du/dy: minus the central difference quotient, exact for a parabola
    h = Fraction(1, 7)
    for y in (v.y_shift, Fraction(0), b):
        quotient = (a * (y + h) ** 2 + b * (y + h) - a * (y - h) ** 2 - b * (y - h)) / (2 * h)
        assert f.slope * y + f.constant == -quotient
    assert (f.slope_magnitude, f.constant_magnitude) == (abs(f.slope), abs(f.constant))


@given(positive_quantities(), positive_quantities(), positive_quantities())
def test_linear_target_takes_up_the_energy(a: float, h: float, scale: float) -> None:
    """The target a y^2 stops the fall where a y^2 = h, and its ramp does that work."""
    stop = contact.linear_target(a, h, h * scale)
    assert stop.stop < 0
    assert math.isclose(a * stop.stop**2, h, rel_tol=4 * REL)
    assert math.isclose(stop.energy, h, rel_tol=8 * REL)
    # the force at the stop is -dU/dy, and the same stop in metres
    assert math.isclose(stop.max_force, -2 * a * stop.stop, rel_tol=4 * REL)
    assert math.isclose(stop.stop_m, stop.stop * scale, rel_tol=4 * REL)
    assert stop.stop_depth_m == -stop.stop_m
    # with the weight counted, a y^2 + y = h turns lower down
    total = stop.total_stop
    assert total < stop.stop
    assert math.isclose(a * total * total + total, h, rel_tol=1e-9, abs_tol=1e-9 * abs(total))


# --- the soft-contact integrator --------------------------------------------------------------


def _contact_time(m1: float, m2: float, speed: float, power: float, strength: float = 1.0) -> float:
    """How long two balls closing at ``speed`` stay in touch under F = k y^n: the overlap obeys
    mu y'' = -k y^n (mu the reduced mass), so the time is 2 (y_max / v) times the integral of
    1 / sqrt(1 - u^(n+1)) over [0, 1], sqrt(pi) Gamma(1 + q) / Gamma(1/2 + q), q = 1/(n+1)."""
    mu = m1 * m2 / (m1 + m2)
    q = 1 / (power + 1)
    deepest = ((power + 1) * mu * speed * speed / (2 * strength)) ** q
    return 2 * deepest / speed * math.sqrt(math.pi) * math.gamma(1 + q) / math.gamma(0.5 + q)


def _check_record(run: contact.SoftCollision, starts: Sequence[float], duration: float) -> None:
    """The run's record: its masses, a trajectory that starts at the start and ends at the last
    release, whose time is ``duration`` (within 1e-9 relative)."""
    assert math.isclose(run.duration, duration, rel_tol=1e-9)
    assert run.times[0] == 0
    assert run.times[-1] == run.duration
    assert list(run.times) == sorted(run.times)
    assert [row[0] for row in run.positions] == list(starts)
    assert all(len(row) == len(run.times) for row in run.positions)


@given(soft_masses(), soft_masses(), closing_speeds(), contact_powers())
@example(7.0, 1.0, 2.0, 4.0)  # the 7:1 pair of Fig. 7.6, quartic
@example(7.0, 1.0, 2.0, 1.0)  # and linear (Fig. 7.7)
@example(10.0**-0.625, 10.0**0.5, 10.0**0.625, 2.9799782166336746)  # first run drifts 1.6e-10
def test_soft_collision_conserves_energy_and_momentum(
    m1: float, m2: float, speed: float, power: float
) -> None:
    """Two balls pushing with F = k y^n while they overlap leave with the kinetic energy and
    the momentum they came with, for any power law and mass ratio (Figs. 7.5-7.7); they part
    once (their first touch is the start), after the contact time of mu y'' = -k y^n."""
    run = contact.soft_collision([m1, m2], [0.0, 0.0], [speed, 0.0], power)
    v1, v2 = (e.value for e in run.velocities)
    assert run.masses == (m1, m2)
    assert run.touches == 1
    # each error bound includes the floor of 1e-12 times the speeds involved, in and out
    floor = 1e-12 * (abs(v1) + abs(v2) + speed)
    assert all(e.error >= floor for e in run.velocities)
    _check_record(run, [0.0, 0.0], _contact_time(m1, m2, speed, power))
    p_in, p_out = m1 * speed, m1 * v1 + m2 * v2
    target(run.energy_error, label="relative energy error")
    assert run.energy_error <= SOFT_ENERGY_DRIFT
    assert abs(p_out - p_in) <= 1e-12 * (abs(m1 * v1) + abs(m2 * v2) + p_in)


@given(soft_masses(), soft_masses(), closing_speeds(), contact_powers(), gaps())
# a light ball and a power just under 3: at 1e-12 the run's error (1e-10) exceeded its bound
@example(10.0, 10.0**-0.671875, 1.0, 2.966796875, 2.0)
def test_separated_balls_follow_the_elastic_collision_map(
    m1: float, m2: float, speed: float, power: float, gap: float
) -> None:
    """Balls that start apart and collide once leave with the velocities of the elastic bang
    (4.1), mechmodel.collisions.collide, within the integrator's declared error: they touch
    after flying the gap and part after the contact time of mu y'' = -k y^n. At rest, balls
    apart (or a ball above the floor) never touch."""
    run = contact.soft_collision([m1, m2], [0.0, gap], [speed, 0.0], power, strength=1.0)
    assert run.touches == 2
    # at rest, nothing ever touches (no step is integrated): two balls apart, or one above a floor
    for still in (
        contact.soft_collision([m1, m2], [0.0, gap], [0.0, 0.0], power),
        contact.soft_collision([m1], [gap], [0.0], power, floor=True),
    ):
        assert (still.touches, still.duration, still.energy_error) == (0, 0.0, 0.0)
        assert all((e.value, e.error) == (0.0, 0.0) for e in still.velocities)
    _check_record(run, [0.0, gap], gap / speed + _contact_time(m1, m2, speed, power))
    expected = reals(collide(m1, m2, speed, 0.0).after)
    errors = [abs(got.value - want) for got, want in zip(run.velocities, expected, strict=True)]
    target(max(errors) / speed, label="relative velocity error")
    for got, error in zip(run.velocities, errors, strict=True):
        assert error <= got.error
        assert got.error <= 1e-7 * speed


# Radau (implicit, about half a second here) takes the same solve_ivp path as these three
@pytest.mark.parametrize("method", ["DOP853-ode", "DOP853", "RK45", "LSODA"])
def test_every_integrator_gives_the_elastic_map_within_its_error(method: str) -> None:
    """The 7:1 pair of Fig. 7.7 (linear contact, unit closing speed), and the same pair started
    apart, leave with the elastic bang's velocities (4.1) within the declared error of the
    Fortran DOP853 (the default) and of each solve_ivp method, with the energy kept to 1e-10."""
    expected = reals(collide(7, 1, 1, 0).after)
    for start in ([0, 0], [0, 0.5]):
        run = contact.soft_collision([7, 1], start, [1, 0], 1, method=method)
        assert run.energy_error <= SOFT_ENERGY_DRIFT
        _check_record(run, start, start[1] + _contact_time(7, 1, 1, 1))
        for got, want in zip(run.velocities, expected, strict=True):
            assert abs(got.value - want) <= got.error <= 1e-8


@given(soft_masses(), soft_masses(), contact_powers(), st.floats(min_value=0.01, max_value=2))
def test_balls_released_pressed_together_share_the_stored_energy(
    m1: float, m2: float, power: float, overlap: float
) -> None:
    """Two balls at rest, pressed together by an overlap y0, fly apart with the energy stored
    in the contact, k y0^(n+1) / (n+1) (the area under F = k y^n), and no momentum: each
    leaves with the share of that energy the other's mass gives it. They only part (one
    event), after half the contact time of a bang at the speed they part with: y falls from
    its deepest, y0, to 0."""
    run = contact.soft_collision([m1, m2], [overlap, 0.0], [0.0, 0.0], power)
    stored = overlap ** (power + 1) / (power + 1)
    leaving = (
        -math.sqrt(2 * stored * m2 / (m1 * (m1 + m2))),
        math.sqrt(2 * stored * m1 / (m2 * (m1 + m2))),
    )
    assert run.touches == 1
    assert run.energy_error <= SOFT_ENERGY_DRIFT
    for got, want in zip(run.velocities, leaving, strict=True):
        assert abs(got.value - want) <= got.error
    closing = leaving[1] - leaving[0]  # the speed at which they would meet again
    _check_record(run, [overlap, 0.0], _contact_time(m1, m2, closing, power) / 2)


@given(soft_masses(), soft_masses(), closing_speeds(), contact_powers())
def test_touching_balls_that_do_not_close_are_left_alone(
    m1: float, m2: float, speed: float, power: float
) -> None:
    """Balls that touch without overlap and move together (or apart, or up off the floor)
    exert no force: the run ends at once with their velocities unchanged and no touch."""
    for run, velocities in (
        (contact.soft_collision([m1, m2], [0.0, 0.0], [speed, speed], power), [speed, speed]),
        (contact.soft_collision([m1, m2], [0.0, 0.0], [-speed, 0.0], power), [-speed, 0.0]),
        (contact.soft_collision([m1, m2], [0.0, 0.0], [speed] * 2, power, floor=True), [speed] * 2),
    ):
        assert (run.touches, run.duration, run.energy_error) == (0, 0.0, 0.0)
        assert [e.value for e in run.velocities] == velocities


def test_a_drifting_run_is_redone_down_the_ladder(monkeypatch: pytest.MonkeyPatch) -> None:
    """A run whose energy keeps within the goal is made once, and once ten times looser for its
    error. While a run's energy drifts by more than the goal it is redone at each tighter rung
    of the ladder (tolerance, step cap) in turn; the error estimate then comes from the last
    rung and a run ten times looser. With an unreachable goal every rung runs, and the result
    still meets the elastic map (the 7:1 quartic pair of Fig. 7.6, started apart)."""
    rungs = []
    integrate = softrun._integrate

    def spy(*args: Any, **kwargs: Any) -> softrun._Run:  # _integrate's arguments, passed on
        rungs.append((kwargs["rtol"], kwargs["cap_fraction"]))
        return integrate(*args, **kwargs)

    monkeypatch.setattr(softrun, "_integrate", spy)
    first_rtol, first_cap = softrun._LADDER[0]
    contact.soft_collision([7, 1], [0, 0.5], [1, 0], 4)
    assert rungs == [(first_rtol, first_cap), (10 * first_rtol, first_cap)]  # within the goal
    rungs.clear()
    monkeypatch.setattr(softrun, "_ENERGY_GOAL", 0.0)
    run = contact.soft_collision([7, 1], [0, 0.5], [1, 0], 4)
    last_rtol, last_cap = softrun._LADDER[-1]
    assert rungs == [*softrun._LADDER, (10 * last_rtol, last_cap)]
    for got, want in zip(run.velocities, reals(collide(7, 1, 1, 0).after), strict=True):
        assert abs(got.value - want) <= got.error <= 1e-8


@pytest.mark.parametrize("power", [1, 1.5, 4])
def test_both_dop853_codes_agree_on_a_tower(power: float) -> None:
    """The 100/30/10 tower of Fig. 8.1 dropped onto the floor (several contacts at once, and
    the floor's): the Fortran DOP853 and solve_ivp's agree within the sum of their declared
    errors, touch as often, and end at the same time."""
    runs = [
        contact.soft_collision([100, 30, 10], [0, 0, 0], [-1, -1, -1], power, 1, True, method)
        for method in ("DOP853-ode", "DOP853")
    ]
    fortran, python = runs
    assert fortran.touches == python.touches
    for run in runs:
        _check_record(run, [0.0, 0.0, 0.0], fortran.duration)
    assert math.isclose(fortran.duration, python.duration, rel_tol=1e-9)
    for a, b in zip(fortran.velocities, python.velocities, strict=True):
        assert abs(a.value - b.value) <= a.error + b.error


@given(positive_quantities(), gaps(), st.floats(min_value=0.01, max_value=0.5))
def test_balloon_stiffness_is_the_slope_of_the_balloon_force(
    pressure: float, radius: float, fraction: float
) -> None:
    """The balloon force P pi r^2 of a flat of radius r (7.2) grows with the depth at the rate the
    stiffness gives."""
    depth = fraction * radius
    h = depth * 1e-6
    force = contact.balloon_force
    slope = (force(pressure, radius, depth + h) - force(pressure, radius, depth - h)) / (2 * h)
    assert math.isclose(slope, contact.balloon_stiffness(pressure, radius, depth), rel_tol=1e-5)


# --- shallow-dent forms of (7.1)-(7.4), the ball's volume, the completed square (7.8a) ----------


@given(gaps(), st.floats(min_value=1e-6, max_value=1))
@example(1.0, 1e-6)  # first contact: the leading terms are exact to first order
def test_shallow_dent_forms_are_the_leading_terms(radius: float, fraction: float) -> None:
    """For a dent of depth x = f R the leading-order forms bound the exact ones and agree with
    them to first order in f: sqrt(2Rx) >= r with r^2 / (2Rx) = 1 - f/2; the bow formula
    r^2/2R <= the exact sagitta with ratio >= 1 - (r/R)^2; the balloon's 2 pi P R x >= P pi r^2
    with the same ratio 1 - f/2; the dent's R pi X^2 >= its volume with ratio 1 - f/3."""
    depth = fraction * radius
    r = contact.flat_spot_radius(radius, depth)
    shallow = contact.flat_radius_shallow(radius, depth)
    assert r <= shallow * (1 + REL)
    assert math.isclose(r * r / (shallow * shallow), 1 - fraction / 2, rel_tol=1e-9)
    flat = contact.flat_spot_radius(radius, depth / 2)  # within the near half: sagitta applies
    exact = contact.sagitta(radius, flat)
    bow = contact.sagitta_small_flat(radius, flat)
    assert bow <= exact * (1 + 1e-9)
    assert bow >= exact * (1 - (flat / radius) ** 2) * (1 - 1e-9)
    pressure = 1 / radius
    ratio = contact.balloon_force(pressure, radius, depth) / contact.balloon_force_shallow(
        pressure, radius, depth
    )
    assert math.isclose(ratio, 1 - fraction / 2, rel_tol=1e-9)
    volume = contact.dent_volume(radius, depth).volume
    assert math.isclose(
        volume / contact.dent_volume_shallow(radius, depth), 1 - fraction / 3, rel_tol=1e-9
    )


@given(gaps(), st.floats(min_value=0.05, max_value=2))
def test_the_flat_area_integrates_to_the_dent_volume(radius: float, fraction: float) -> None:
    """The flat's area pi r(x)^2, integrated from 0 to X (Simpson's rule, exact for the
    quadratic pi x (2R - x)), is the dent's volume (7.4); at X = 2R the whole ball's volume
    is 4/3 pi R^3 (the volume of a ball by any other method: ``fields.sphere_volume``)."""
    depth = fraction * radius
    middle = contact.flat_area(radius, depth / 2)
    simpson = depth / 6 * (contact.flat_area(radius, 0) + 4 * middle)
    simpson += depth / 6 * contact.flat_area(radius, depth)
    assert math.isclose(simpson, contact.dent_volume(radius, depth).volume, rel_tol=1e-9)
    whole = contact.whole_ball_volume(radius)
    assert math.isclose(whole, fields.sphere_volume(radius), rel_tol=1e-12)
    assert math.isclose(contact.whole_ball_volume(2 * radius), 8 * whole, rel_tol=1e-12)


@given(fraction_quantities(), rationals(-10, 10, 12), rationals(-10, 10, 12))
def test_quadratic_potential_bottoms_at_the_vertex(a: Fraction, b: Fraction, y: Fraction) -> None:
    """U = a y^2 + b y (7.8a) is a (y - y_shift)^2 + U_shift with the vertex of
    ``parabola_vertex``: exactly, with Fractions, and no point lies below the vertex."""
    assume(b != 0)
    vertex = contact.parabola_vertex(a, b)
    u = real(contact.quadratic_potential(a, b, y))
    assert u == a * (y - vertex.y_shift) ** 2 + vertex.u_shift
    assert u >= real(contact.quadratic_potential(a, b, vertex.y_shift)) == vertex.u_shift
