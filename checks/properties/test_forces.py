"""Laws of the bang forces, potentials and bang sequences (mechmodel.forces): chapter 6.

Floats are compared within 1e-12 of the magnitudes involved (1e-9 for local powers and slopes of
slopes, which come from a central difference); Fraction inputs must give exact equality.
"""

from __future__ import annotations

import itertools
import math
from fractions import Fraction

import pytest
from hypothesis import example, given, target
from hypothesis import strategies as st

from checks.properties.strategies import (
    force_powers,
    fraction_quantities,
    gaps,
    positive_quantities,
    rationals,
    well_powers,
)
from mechmodel import forces

pytestmark = pytest.mark.properties
REL = 1e-12
POWER = 1e-9  # a local power from a central difference in ln x


@given(fraction_quantities(), fraction_quantities())
def test_bang_rate_is_the_inverse_of_the_period(gap: Fraction, speed: Fraction) -> None:
    """B = 1/dt exactly, and the period is the round trip 2Y / v2 (6.1)."""
    period = forces.bang_period(gap, speed)
    assert forces.bang_rate(gap, speed) * period == 1
    assert period * speed == 2 * gap


@given(fraction_quantities(), fraction_quantities())
def test_a_closing_wall_adds_twice_its_speed(v_wall: Fraction, speed: Fraction) -> None:
    """A bang with a closing wall (m1 >> m2) adds 2 v1 to m2's speed (6.2), exactly."""
    assert forces.moving_wall_bounce(v_wall, speed) == speed + 2 * v_wall
    assert forces.wall_speed_gain(v_wall, speed) == 2


@given(positive_quantities(), positive_quantities(), gaps())
def test_isothermal_force_is_twice_the_energy_over_the_gap(m2: float, v2: float, y: float) -> None:
    """F = m2 v2^2 / Y = 2 KE / Y (6.4): powers -1 in Y and 2 in v2."""
    law = forces.isothermal_force(m2, v2, y)
    assert math.isclose(law.force, m2 * v2 * v2 / y, rel_tol=REL)
    assert math.isclose(law.force_gap_per_energy, 2, rel_tol=REL)
    assert abs(law.inverse_power - 1) <= POWER
    assert abs(law.speed_exponent - 2) <= POWER


@given(positive_quantities(), positive_quantities(), gaps(), gaps())
@example(0.1, 20.0, 3.0, 2.5)  # the gas balls of Fig. 6.3(c)
def test_adiabatic_potential_gives_the_bang_force(
    m2: float, v0: float, y0: float, y: float
) -> None:
    """-dU/dY of U = 1/2 m2 (v0 Y0 / Y)^2 is the adiabatic bang force m2 (v0 Y0)^2 / Y^3:
    "It checks!!" (6.10), and it needs the 1/2 of the kinetic energy."""
    bang = forces.adiabatic_force(m2, v0, y0, y)
    slope = forces.adiabatic_potential_force(m2, v0, y0, y)
    error = abs(float(slope.force - bang.force)) / bang.force
    target(error, label="relative force error")
    assert error <= 8 * REL
    assert abs(bang.inverse_power - 3) <= POWER
    assert abs(slope.inverse_power - 3) <= POWER
    assert math.isclose(bang.force_gap_per_energy, 2, rel_tol=8 * REL)  # F = 2 KE / Y
    assert math.isclose(slope.force_gap_per_energy, 2, rel_tol=16 * REL)
    assert math.isclose(forces.kinetic_energy_factor(m2, v0, y0, y), 0.5, rel_tol=8 * REL)


@given(fraction_quantities(), fraction_quantities(), fraction_quantities())
def test_adiabatic_action_is_constant(v0: Fraction, y0: Fraction, y: Fraction) -> None:
    """v2 Y stays v0 Y0 as the gap closes (6.5b): the adiabatic speed law, exactly."""
    assert forces.adiabatic_speed(v0, y0, y) * y == v0 * y0


@given(positive_quantities(), positive_quantities(), gaps())
def test_isothermal_potential_gives_the_isothermal_force(m2: float, v2: float, y: float) -> None:
    """-dU/dY of U = -m2 v2^2 ln Y is the isothermal force m2 v2^2 / Y = 2 KE / Y (6.11): the
    slope of the potential itself (a central difference), zero at Y = 1, and the slope the
    model takes."""
    law = forces.isothermal_potential_force(m2, v2, y)
    assert math.isclose(law.force, m2 * v2 * v2 / y, rel_tol=8 * REL)
    assert math.isclose(law.force_gap_per_energy, 2, rel_tol=8 * REL)
    h = y * 1e-5
    potential = forces.isothermal_potential
    quotient = (potential(m2, v2, y + h) - potential(m2, v2, y - h)) / (2 * h)
    assert math.isclose(-quotient, law.force, rel_tol=1e-8)
    assert potential(m2, v2, 1) == 0


@given(positive_quantities(), force_powers(), gaps())
def test_power_law_potential_slope_is_the_force(k: float, p: float, y: float) -> None:
    """U = -k y^(p+1)/(p+1) has -dU/dy = k y^p, and its power is p + 1."""
    pot = forces.power_law_potential(k, p, y)
    expected = k * y**p
    assert math.isclose(pot.force, expected, rel_tol=8 * REL)
    assert abs(pot.exponent_gain - 1) <= POWER * (1 + abs(p))


@given(positive_quantities(), gaps())
def test_the_logarithmic_potential_gives_the_inverse_force(k: float, y: float) -> None:
    """For p = -1 the potential is U = -k ln y (like the isothermal (6.11)), and -dU/dy is the
    force k / y."""
    pot = forces.power_law_potential(k, -1, y)
    assert pot.logarithmic
    assert math.isclose(pot.force, k / y, rel_tol=8 * REL)


@given(st.integers(min_value=1, max_value=9), fraction_quantities())
def test_opposed_gases_leave_only_odd_powers(order: int, gap: Fraction) -> None:
    """f/(Y + x) - f/(Y - x) = -2 f x / Y^2 - 2 f x^3 / Y^4 - ...: the even powers cancel."""
    series = forces.opposed_isothermal_series(order, gap)
    for k, c in enumerate(series.total):
        assert c == (0 if k % 2 == 0 else -2 / gap ** (k + 1))
    assert series.spring_per_force_constant == 2 / gap**2
    unit = forces.opposed_isothermal_series(order)  # the gap defaults to 1: k = 2 f
    assert unit == forces.opposed_isothermal_series(order, 1)
    assert unit.total[1] == -2


@given(positive_quantities(), positive_quantities(), gaps())
def test_spring_constant_of_two_gases(m2: float, v2: float, y: float) -> None:
    """k = 2 m2 v2^2 / Y^2 for m1 between two isothermal gases (6.12)."""
    k = forces.isothermal_spring_constant(m2, v2, y)
    assert math.isclose(k, 2 * m2 * v2 * v2 / (y * y), rel_tol=8 * REL)


@given(fraction_quantities(), fraction_quantities())
def test_hooke_potential_is_half_k_x_squared(k: Fraction, x: Fraction) -> None:
    """U = -integral of -k x dx = k x^2 / 2 (6.12), exactly."""
    assert forces.hooke_potential(k, x) == k * x * x / 2


@given(positive_quantities(), positive_quantities(), positive_quantities())
def test_harmonic_period_does_not_depend_on_amplitude(k: float, m: float, a: float) -> None:
    """The Hooke oscillator's period is 2 pi / omega whatever the amplitude (after (6.12))."""
    period = forces.oscillation_period(m, k / 2, 2, a)
    assert math.isclose(period * math.sqrt(k / m), 2 * math.pi, rel_tol=16 * REL)


@given(positive_quantities(), well_powers(), positive_quantities())
def test_power_well_period_scales_with_amplitude(m: float, p: float, a: float) -> None:
    """In U = s |x|^p the period goes as A^(1 - p/2): doubling the amplitude multiplies it by
    2^(1 - p/2) (a dimensional law the quadrature must obey)."""
    one = forces.oscillation_period(m, 1, p, a)
    two = forces.oscillation_period(m, 1, p, 2 * a)
    assert math.isclose(two / one, 2 ** (1 - p / 2), rel_tol=1e-9)


@given(positive_quantities(), well_powers(), positive_quantities())
@example(1.0, 1.5, 1.0)  # the sharpest kink of |x|^p at the centre that the wells draw
def test_power_well_period_is_the_turning_point_integral(m: float, p: float, a: float) -> None:
    """The period in U = s |x|^p (s = 1) is 4 sqrt(m / 2) A^(1 - p/2) times the integral of
    1 / sqrt(1 - u^p) over [0, 1], sqrt(pi) Gamma(1 + 1/p) / Gamma(1/2 + 1/p) (E = KE + PE
    (6.6)-(6.7) solved for the speed); 2 pi sqrt(m / 2) for the Hooke well (6.12). Gauss-Chebyshev
    quadrature meets it within 1e-5 (its error comes from the kink of |x|^p at x = 0)."""
    beta = math.sqrt(math.pi) * math.gamma(1 + 1 / p) / math.gamma(0.5 + 1 / p)
    expected = 4 * math.sqrt(m / 2) * a ** (1 - p / 2) * beta
    assert math.isclose(forces.oscillation_period(m, 1, p, a), expected, rel_tol=1e-5)


@given(fraction_quantities(), fraction_quantities())
def test_toss_height_and_launch_speed_agree(v: Fraction, g: Fraction) -> None:
    """g h = V^2 / 2 (6.13a), exactly; and sqrt(2 g h) gives back V (6.13b)."""
    h = forces.toss_height(v, g)
    assert g * h == v * v / 2
    assert math.isclose(forces.launch_speed(h, g), v, rel_tol=4 * REL)
    fall = forces.fall_from_height(h, g)  # the toss backwards: from rest, h = g t^2 / 2
    assert math.isclose(float(g) * fall.time * fall.time / 2, h, rel_tol=8 * REL)
    assert math.isclose(fall.speed, float(g) * fall.time, rel_tol=4 * REL)
    assert math.isclose(fall.speed_squared_per_g, 2 * h, rel_tol=4 * REL)
    assert forces.toss_height(v, -g) == h  # the sign of g is the book's up-positive convention


@given(fraction_quantities())
def test_height_gain_is_the_square_of_the_speed_gain(gain: Fraction) -> None:
    """A 3-fold velocity gain means a 3^2 = 9-fold height gain (after (6.13))."""
    assert forces.toss_height_gain(gain) == gain * gain


@given(
    fraction_quantities(), fraction_quantities(), st.integers(min_value=1, max_value=12), st.data()
)
def test_trapped_ball_action_is_constant(
    v_wall: Fraction, gap: Fraction, bangs: int, data: st.DataObject
) -> None:
    """The range times the speed stays the same bang after bang (Fig. 6.4): Delta x v2 is an
    adiabatic invariant of the ball trapped by a steadily closing wall, exactly; the range is
    what the big ball, closing steadily from -gap at t = 0, leaves of the gap at each wall bang.
    A little ball as fast as the big one, or faster, is never caught: a ValueError."""
    v_ball = v_wall * data.draw(rationals(-1, Fraction(11, 12), 12))
    run = forces.trapped_ball(v_wall, v_ball, gap, bangs)
    assert len(set(run.products)) == 1
    assert all(b - a == 2 * v_wall for a, b in itertools.pairwise(run.speeds))
    # the big ball closes steadily from -gap at t = 0; the first crossing takes gap / v2
    assert run.times[0] * run.speeds[0] == gap
    for t, x, v, action in zip(run.times, run.ranges, run.speeds, run.products, strict=True):
        assert x == gap - v_wall * t > 0
        assert action == x * v
    assert list(run.times) == sorted(set(run.times))
    for uncaught in (v_wall, 2 * v_wall):
        with pytest.raises(ValueError, match="does not catch"):
            forces.trapped_ball(v_wall, uncaught, gap, bangs)


@given(fraction_quantities(), st.integers(min_value=0, max_value=12), st.data())
def test_monster_bongs_add_twice_the_monster_speed(
    v_monster: Fraction, bongs: int, data: st.DataObject
) -> None:
    """Each bong with a closing monster adds 2 V1 to the atom's speed (Figs. 6.5-6.6), exactly,
    and the atom's velocity alternates in sign: from rest 0, 2, -4, 6, ... times V1."""
    start = data.draw(rationals(-v_monster, v_monster, 12))
    path = forces.monster_pair(v_monster, start, bongs)
    from_rest = (0, 2 * v_monster, -4 * v_monster, 6 * v_monster)  # the left one hits first
    assert forces.monster_pair(v_monster, 0, 3) == from_rest
    for before, after in itertools.pairwise(path):
        assert abs(Fraction(after)) - abs(Fraction(before)) == 2 * v_monster
        assert before == 0 or (after > 0) != (before > 0)


@given(positive_quantities(), positive_quantities(), positive_quantities())
def test_thermal_speed_carries_the_energy_kt(m: float, t: float, k: float) -> None:
    """1/2 m v^2 = k T, the book's KE = kT of (6.4)."""
    v = forces.thermal_speed(m, t, k)
    assert math.isclose(m * v * v / 2, k * t, rel_tol=4 * REL)


@given(fraction_quantities(), fraction_quantities(), fraction_quantities())
def test_speed_grows_at_the_gain_per_bang_times_the_bang_rate(
    v_wall: Fraction, speed: Fraction, gap: Fraction
) -> None:
    """dv2/dt = 2 v1 B = 2 v1 v2 / 2Y (6.5a), exactly: the gain of one bang, whatever m2's
    speed, at the bang rate of (6.1b)."""
    rate = forces.bang_rate(gap, speed)
    assert forces.speed_gain_rate(v_wall, rate) == 2 * v_wall * rate
    gain = forces.moving_wall_bounce(v_wall, speed) - speed
    assert forces.speed_gain_rate(v_wall, rate) == gain * rate
    assert forces.adiabatic_speed_growth(v_wall, speed, gap) == 2 * v_wall * speed / (2 * gap)


@given(positive_quantities(), positive_quantities(), positive_quantities(), gaps())
def test_the_isothermal_force_depends_on_the_energy_alone(
    m2: float, other: float, v2: float, y: float
) -> None:
    """F = 2 KE / Y (6.4): m2 of any mass carrying the energy KE = 1/2 m2 v2^2 pushes as hard."""
    energy = m2 * v2 * v2 / 2
    force = forces.isothermal_force(m2, v2, y).force
    assert math.isclose(forces.isothermal_force_of_energy(energy, y, m2), force, rel_tol=8 * REL)
    assert math.isclose(forces.isothermal_force_of_energy(energy, y, other), force, rel_tol=8 * REL)
    assert math.isclose(
        forces.isothermal_force_of_energy(energy, y), 2 * energy / y, rel_tol=8 * REL
    )


@given(positive_quantities(), positive_quantities(), positive_quantities())
def test_a_one_dimensional_atom_holds_half_kt(k: float, t: float, m: float) -> None:
    """Equipartition: the mean of 1/2 m v^2 over the 1-D Maxwell distribution
    exp(-m v^2 / 2kT) is k T / 2 (Gauss-Hermite quadrature, exact for this polynomial)."""
    from numpy.polynomial.hermite_e import hermegauss

    nodes, weights = hermegauss(8)  # weight exp(-x^2/2): v = x sqrt(kT/m)
    energies = [m * (x * math.sqrt(k * t / m)) ** 2 / 2 for x in nodes]
    mean = math.fsum(w * e for w, e in zip(weights, energies, strict=True)) / math.fsum(weights)
    assert math.isclose(forces.thermal_kinetic_energy(k, t), mean, rel_tol=1e-12)


@given(positive_quantities(), positive_quantities(), gaps(), gaps())
def test_the_one_atom_gas_law_is_kt_at_any_gap(k: float, t: float, y: float, other: float) -> None:
    """F Y = k T for one atom in one dimension (the ideal gas law P V = N k T), whatever the
    gap: the bang force 2 KE / Y (6.4) with the thermal KE = k T / 2."""
    assert math.isclose(forces.isothermal_gas_law(k, t, y), k * t, rel_tol=8 * REL)
    assert math.isclose(
        forces.isothermal_gas_law(k, t, y), forces.isothermal_gas_law(k, t, other), rel_tol=8 * REL
    )


@given(fraction_quantities(), rationals(Fraction(-1, 2), Fraction(1, 2), 12), st.integers(1, 7))
def test_the_opposed_force_series_approach_the_forces(f: Fraction, x: Fraction, order: int) -> None:
    """f [1 - x + x^2 - ...] and f [1 + x + x^2 + ...] at unit gap (before (6.12)) are the
    geometric series of f/(1 + x) and f/(1 - x): each misses by its next term over 1 -/+ x,
    exactly; the total is their difference."""
    series = forces.opposed_isothermal_forces(f, x, order, Fraction(1))
    assert f / (1 + x) - series.left == f * (-x) ** (order + 1) / (1 + x)
    assert f / (1 - x) - series.right == f * x ** (order + 1) / (1 - x)
    assert series.total == series.left - series.right


@given(positive_quantities(), gaps())
def test_the_spring_constant_of_two_gases_is_twice_f(f: float, y: float) -> None:
    """k = -dF_total/dx at x = 0 is 2 f / Y^2 for F_total = f/(Y + x) - f/(Y - x) (6.12)."""
    assert math.isclose(forces.opposed_spring_constant(f, y), 2 * f / (y * y), rel_tol=8 * REL)


@given(positive_quantities())
def test_the_harmonic_period_is_two_pi_over_omega(omega: float) -> None:
    """tau = 2 pi / omega from the turning-point integral (after (6.12))."""
    assert math.isclose(forces.harmonic_period(omega) * omega, 2 * math.pi, rel_tol=8 * REL)
