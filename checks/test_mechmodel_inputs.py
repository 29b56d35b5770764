"""Bad physical inputs get a clear ValueError, never a wrong number (design section 5)."""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import pytest

from mechmodel.bangs import ceiling_sequence
from mechmodel.collisions import collide, kinetic_energy, momentum
from mechmodel.fields import circular_orbit_speed, tunnel_period, tunnel_transit_time
from mechmodel.series import exp_partial_sum, exp_series_term
from mechmodel.towers import independent_tower

NAN = float("nan")


@pytest.mark.parametrize("bad", [0, -1, -1e-9, NAN, -math.inf, True, 1j])
def test_a_mass_must_be_positive(bad: object) -> None:
    with pytest.raises(ValueError, match="m1"):
        collide(bad, 1, 1, 0)  # type: ignore[call-overload]  # deliberate: the run-time check is tested


@pytest.mark.parametrize("bad", [NAN, math.inf, -math.inf])
def test_a_velocity_must_be_finite(bad: float) -> None:
    with pytest.raises(ValueError, match="v2"):
        collide(1, 1, 0, bad)


@pytest.mark.parametrize("bad", [-0.1, 1.1, NAN])
def test_restitution_is_between_zero_and_one(bad: float) -> None:
    with pytest.raises(ValueError, match="restitution"):
        collide(1, 1, 1, 0, bad)


def test_two_walls_cannot_collide() -> None:
    with pytest.raises(ValueError, match="two infinite masses"):
        collide(math.inf, math.inf, 1, 0)


def test_an_infinite_mass_has_no_finite_momentum_or_energy() -> None:
    with pytest.raises(ValueError, match="finite"):
        momentum((math.inf, 1), (0, 1))
    with pytest.raises(ValueError, match="finite"):
        collide(math.inf, 1, 0, -1).ke_before  # noqa: B018 - the property raises


def test_one_velocity_per_mass() -> None:
    with pytest.raises(ValueError, match="one velocity per mass"):
        kinetic_energy((1, 2), (3,))


def test_towers_bangs_and_fields_check_their_inputs() -> None:
    with pytest.raises(ValueError, match="masses"):
        independent_tower([100, -30, 10])
    with pytest.raises(ValueError, match="v_drop"):
        independent_tower([100, 30], v_drop=-1)
    with pytest.raises(ValueError, match="at least one ball"):
        independent_tower([])
    with pytest.raises(ValueError, match="m2"):
        ceiling_sequence(49, 0, 1, -1)
    with pytest.raises(ValueError, match="radius"):
        tunnel_period(9.8, -6.4e6)
    with pytest.raises(ValueError, match="g"):
        circular_orbit_speed(NAN, 6.4e6)


def test_series_orders_are_counts() -> None:
    with pytest.raises(ValueError, match="order"):
        exp_partial_sum(1, 2.5)  # type: ignore[arg-type]  # deliberate: a float order is refused
    with pytest.raises(ValueError, match="order"):
        exp_partial_sum(1, -1)


def test_exact_inputs_give_exact_results() -> None:
    assert exp_partial_sum(Fraction(1), 3) == Fraction(8, 3)
    assert exp_partial_sum(1, 3, exact=True) == Fraction(8, 3)
    assert isinstance(exp_partial_sum(1, 3), float)
    assert exp_series_term(Fraction(1, 2), 2) == Fraction(1, 8)
    hit = collide(Fraction(49), Fraction(1), Fraction(1), Fraction(-1))
    assert (hit.v1, hit.v2) == (Fraction(23, 25), Fraction(73, 25))


def test_mpmath_numbers_pass_through() -> None:
    with mpmath.workdps(30):
        total = exp_partial_sum(mpmath.mpf(1), 20)
        assert isinstance(total, mpmath.mpf)
        assert abs(total - mpmath.e) < mpmath.mpf(10) ** -18


def test_transit_is_half_the_tunnel_period() -> None:
    assert tunnel_transit_time(9.8, 6.4e6) == tunnel_period(9.8, 6.4e6) / 2


def test_the_soft_collision_integrator_is_one_of_scipys() -> None:
    from mechmodel.contact import soft_collision

    with pytest.raises(ValueError, match="method must be one of"):
        soft_collision([7, 1], [0, 0], [1, 0], 4, method="Euler")
