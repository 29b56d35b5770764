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
    soft_masses,
)
from mechmodel import towers
from mechmodel.collisions import kinetic_energy

pytestmark = pytest.mark.properties


@given(fraction_tower_masses(), fraction_quantities())
@example([Fraction(100), Fraction(30), Fraction(10)], Fraction(1))  # Fig. 8.1(b)
def test_independent_tower_launch_law(masses: list[Fraction], v_drop: Fraction) -> None:
    """Dropped at speed v, an independent-collision tower launches its top ball at V_top with
    V_top + v = 2 v prod_k 2 m_k / (m_k + m_(k+1)) (Figs. 8.1(b), 8.2), exactly."""
    tower = towers.independent_tower(masses, v_drop)
    product = Fraction(1)
    for lower, upper in itertools.pairwise(masses):
        product *= 2 * lower / (lower + upper)
    assert tower.velocities[-1] + v_drop == 2 * v_drop * product


@given(fraction_tower_masses())
def test_independent_tower_stays_under_the_inf_limit(masses: list[Fraction]) -> None:
    """Finite masses launch the top ball of N balls below the INF limit 2^N - 1 (Fig. 4.5,
    exercise 1.8.2), which ``inf_limit_tower`` reaches exactly."""
    n = len(masses)
    limit = towers.inf_limit_tower(n, 1)[-1]
    assert limit == 2**n - 1
    assert towers.independent_tower(masses, 1).velocities[-1] < limit or n == 1


@given(ball_counts(), moderate_fraction_masses())
def test_geometric_tower_launch(n: int, ratio: Fraction) -> None:
    """A tower of N balls, each r times the next, launches at 2 (2r / (r + 1))^(N-1) - 1
    (Fig. 8.2: 5.75 for r = 3, 9.72 for r = 7, N = 4)."""
    top = towers.geometric_tower(n, ratio, 1).velocities[-1]
    assert top == 2 * (2 * ratio / (ratio + 1)) ** (n - 1) - 1


@given(ball_counts())
def test_identical_column_needs_triangular_number_of_bangs(n: int) -> None:
    """A column of N identical balls needs N (N + 1) / 2 independent bangs (Fig. 8.2(c-d))."""
    assert towers.column_bounce_bangs(n, 1) == n * (n + 1) // 2


@given(moderate_fraction_masses(), fraction_quantities(), st.integers(1, 6), st.integers(1, 6))
def test_pile_up_keeps_momentum_and_loses_energy(
    mass: Fraction, speed: Fraction, moving: int, still: int
) -> None:
    """Ka-runch pile-ups keep the momentum and lose energy (Figs. 8.5-8.6), exactly."""
    if moving > 1 and still > 1:
        still = 1
    pile = towers.pile_up(mass, speed, moving, still)
    assert pile.momentum_out == pile.momentum_in
    assert pile.final_mass == (moving + still) * mass
    assert pile.energy_lost >= 0
    assert pile.slopes == tuple(range(1, len(pile.slopes) + 1))


@given(st.integers(2, 15), moderate_fraction_masses(), fraction_quantities())
def test_pellet_rocket_momentum_is_zero_sum(n: int, m: Fraction, speed: Fraction) -> None:
    """Every blast keeps the total momentum zero (8.7), and the rocket's velocity is the partial
    sum of the boosts m |ve| / M_b: the harmonic series for unit pellets, exactly."""
    rocket = towers.pellet_rocket(n, m, -speed)
    assert all(p == 0 for p in rocket.total_momenta)
    for b, v in enumerate(rocket.velocities):
        assert v == speed * sum(Fraction(1, n - 1 - j) for j in range(b + 1))


@given(moderate_fraction_masses(), moderate_fraction_masses(), st.data())
def test_inelastic_quadratic_roots_keep_momentum_and_energy(
    m1: Fraction, m2: Fraction, data: st.DataObject
) -> None:
    """The roots of (8.4b) are the two velocities u1 with the given momentum and energy; their
    mean is V_COM, and the book's coefficients -2 pu and -2 ku are read off."""
    u1 = data.draw(st.fractions(-5, 5, max_denominator=10))
    u2 = data.draw(st.fractions(-5, 5, max_denominator=10))
    p = m1 * u1 + m2 * u2
    k = kinetic_energy((m1, m2), (u1, u2))
    quad = towers.inelastic_quadratic(m1, m2, p, k)
    assert quad.energy_coefficient == 2
    if p:
        assert quad.momentum_coefficient == 2
    assert quad.roots is not None
    assert any(math.isclose(r, float(u1), rel_tol=1e-9, abs_tol=1e-9) for r in quad.roots)
    assert math.isclose(sum(quad.roots) / 2, float(p / (m1 + m2)), rel_tol=1e-9, abs_tol=1e-9)


@given(st.lists(soft_masses(), min_size=2, max_size=3), contact_powers())
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
