"""Laws of the quantum and relativistic scales (mechmodel.quanta): the front matter.

Floats are compared within 1e-12 of the magnitudes involved (1e-9 where a square root of a
difference near zero is taken); Fraction inputs to ``photon_energy`` give exact equality.
The strategies are local: they draw the scales of this module (frequencies, energies, box
lengths), which no other module uses.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from checks.properties.strategies import masses, rationals
from mechmodel.quanta import (
    one_ball_state_count,
    photon_energy,
    speed_fraction,
    two_ball_wavefunction_size,
)

pytestmark = pytest.mark.properties
REL = 1e-12


def decades(low: int, high: int) -> st.SearchStrategy[float]:
    """A positive float from 10^low to 10^high, spread evenly over the decades."""
    return st.floats(min_value=low, max_value=high, allow_nan=False).map(lambda k: 10.0**k)


def frequencies() -> st.SearchStrategy[float]:
    """A frequency in Hz, from radio (1e3) to gamma rays (1e24)."""
    return decades(3, 24)


def planck_constants() -> st.SearchStrategy[float]:
    """A value of h in J s, around the real one (units other than SI scale it)."""
    return decades(-36, -30)


def energies() -> st.SearchStrategy[float]:
    """An energy in J, from 1e-6 to 1e6."""
    return decades(-6, 6)


def lengths() -> st.SearchStrategy[float]:
    """A box length in m, from 1e-3 to 1e3."""
    return decades(-3, 3)


def energy_ratios() -> st.SearchStrategy[float]:
    """Total over rest energy, gamma, from 1 to 1e6."""
    return decades(0, 6)


@given(frequencies(), frequencies(), planck_constants())
def test_photon_energy_is_additive_in_frequency(f1: float, f2: float, h: float) -> None:
    """E = h nu: the energies of two frequencies add to the energy of their sum."""
    total = float(photon_energy(f1 + f2, h))
    parts = float(photon_energy(f1, h)) + float(photon_energy(f2, h))
    assert abs(total - parts) <= REL * (abs(total) + abs(parts))


@given(
    rationals(Fraction(1, 1000), 10**6, 1000),
    rationals(Fraction(1, 1000), 10, 1000),
)
def test_photon_energy_over_frequency_is_h_exactly(f: Fraction, h: Fraction) -> None:
    """With exact inputs E / nu is exactly h."""
    assert photon_energy(f, h) / f == h


@given(energy_ratios(), energies())
@example(4.0e12 / 938272088.943, 1.0)  # the LHC protons of line 902
def test_speed_fraction_gives_back_the_lorentz_factor(gamma: float, rest: float) -> None:
    """beta < 1 and 1 / sqrt(1 - beta^2) is E / mc^2. (Rounding beta to a double moves 1 - beta
    by about 1e-16, a relative error of 1e-16 gamma^2 in 1 - beta^2 near the speed of light.)"""
    beta = speed_fraction(gamma * rest, rest)
    assert 0 <= beta < 1
    back = 1 / math.sqrt((1 - beta) * (1 + beta))
    assert abs(back - gamma) <= 1e-15 * gamma**3 + REL * gamma


@given(energies(), energy_ratios(), energy_ratios())
def test_speed_fraction_grows_with_energy(rest: float, g1: float, g2: float) -> None:
    """More energy, more speed: beta is nondecreasing in E at fixed rest energy."""
    low, high = sorted((g1, g2))
    assert speed_fraction(low * rest, rest) <= speed_fraction(high * rest, rest)


def test_speed_fraction_at_rest_is_zero_and_below_rest_is_refused() -> None:
    assert speed_fraction(2.0, 2.0) == 0
    with pytest.raises(ValueError, match="below the rest energy"):
        speed_fraction(1.0, 2.0)


@given(masses(), energies(), lengths(), planck_constants())
def test_two_equal_balls_fill_pi_over_4_of_the_square_of_one(
    m: float, e: float, length: float, h: float
) -> None:
    """For equal masses the momentum region of two balls sharing E is the disc inscribed in the
    square of the momentum ranges of one ball with E each: N2 = (pi / 4) N1^2."""
    two = two_ball_wavefunction_size(m, m, e, length, h, 1).states
    one = one_ball_state_count(m, e, length, h)
    expected = math.pi / 4 * one**2
    assert abs(two - expected) <= REL * (two + expected)


@given(masses(), masses(), energies(), lengths(), planck_constants(), st.integers(1, 64))
def test_two_ball_size_scales_and_is_symmetric(
    m1: float, m2: float, e: float, length: float, h: float, per_state: int
) -> None:
    """Swapping the balls changes nothing; the count grows as E L^2 and as 1/h^2, and the bytes
    are the states times the bytes per amplitude."""
    size = two_ball_wavefunction_size(m1, m2, e, length, h, per_state)
    swapped = two_ball_wavefunction_size(m2, m1, e, length, h, per_state)
    assert abs(size.states - swapped.states) <= REL * size.states
    bigger = two_ball_wavefunction_size(m1, m2, 2 * e, 2 * length, h / 2, per_state)
    assert abs(bigger.states - 32 * size.states) <= REL * bigger.states
    assert abs(size.bytes - per_state * size.states) <= REL * size.bytes


def test_bad_inputs_are_refused() -> None:
    with pytest.raises(ValueError, match="frequency must be positive"):
        photon_energy(-1.0, 1.0)
    with pytest.raises(ValueError, match="mass must be a positive number"):
        one_ball_state_count(float("nan"), 1.0, 1.0, 1.0)
    with pytest.raises(ValueError, match="bytes_per_amplitude must be at least 1"):
        two_ball_wavefunction_size(1.0, 1.0, 1.0, 1.0, 1.0, 0)
