"""Strategies of force laws, contact geometry, soft collisions and towers (chapters 6-8)
and of the common potential fields (mechmodel.fields, chapter 9)."""

from __future__ import annotations

from fractions import Fraction

from hypothesis import strategies as st

from checks.properties.strategies.collisions import moderate_fraction_masses
from checks.properties.strategies.exact import rationals

# --- chapters 6-8: force laws, contact geometry, soft collisions, towers ----------------------


def gaps() -> st.SearchStrategy[float]:
    """A gap Y between a ball and a wall (or a length), 0.1 to 10."""
    return st.floats(min_value=0.1, max_value=10)


def positive_quantities() -> st.SearchStrategy[float]:
    """A positive mass, speed or force constant, 0.1 to 10, spread over the decades."""
    return st.floats(min_value=-1, max_value=1).map(lambda k: 10.0**k)


def fraction_quantities() -> st.SearchStrategy[Fraction]:
    """An exact positive quantity p/q from 1/10 to 10."""
    return rationals(Fraction(1, 10), 10, 12)


def force_powers() -> st.SearchStrategy[float]:
    """A power p of a force law F = k y^p, -4 to 4, kept away from the logarithmic p = -1."""
    return st.one_of(
        st.floats(min_value=-4, max_value=-1.05), st.floats(min_value=-0.95, max_value=4)
    )


def well_powers() -> st.SearchStrategy[float]:
    """A power p of a symmetric well U = s |x|^p, 1.5 to 6."""
    return st.floats(min_value=1.5, max_value=6)


def contact_powers() -> st.SearchStrategy[float]:
    """A power n of a soft contact force F = k y^n, 1 (linear) to 4 (the superball's quartic)."""
    return st.floats(min_value=1, max_value=4)


SOFT_ENERGY_DRIFT = 1e-10  # the soft-contact integrator's energy drift over a collision, relative


def soft_masses() -> st.SearchStrategy[float]:
    """A ball's mass for the soft-collision integrator, 0.1 to 10 (mass ratios up to 100)."""
    return st.floats(min_value=-1, max_value=1).map(lambda k: 10.0**k)


def closing_speeds() -> st.SearchStrategy[float]:
    """A closing speed of two balls, 0.1 to 10."""
    return st.floats(min_value=-1, max_value=1).map(lambda k: 10.0**k)


def fraction_tower_masses() -> st.SearchStrategy[list[Fraction]]:
    """The exact masses of a tower of 1 to 6 balls, each 1/20 to 20 (any order)."""
    return st.lists(moderate_fraction_masses(), min_size=1, max_size=6)


def ball_counts() -> st.SearchStrategy[int]:
    """A number of balls N of a tower or a column, 1 to 7."""
    return st.integers(min_value=1, max_value=7)


# --- common potential fields (mechmodel.fields, chapter 9) -------------------------------------
def surface_gravities() -> st.SearchStrategy[float]:
    """A planet's surface gravity g from 0.1 to 100 m/s^2, spread evenly over the decades."""
    return st.floats(min_value=-1, max_value=2).map(lambda k: 10.0**k)


def planet_radii() -> st.SearchStrategy[float]:
    """A planet's radius from 1 km to 100,000 km, spread evenly over the decades."""
    return st.floats(min_value=3, max_value=8).map(lambda k: 10.0**k)


def chord_offsets() -> st.SearchStrategy[float]:
    """Distance of a tunnel's chord from the centre, as a fraction of the radius (-0.99 to 0.99)."""
    return st.floats(min_value=-0.99, max_value=0.99)


def radial_fractions() -> st.SearchStrategy[float]:
    """A distance from the centre in planet radii, 0 to 10 (inside and outside)."""
    return st.floats(min_value=0.0, max_value=10.0)


def oscillator_frequencies() -> st.SearchStrategy[float]:
    """An angular frequency from 0.1 to 10 rad per unit time."""
    return st.floats(min_value=-1, max_value=1).map(lambda k: 10.0**k)


def oscillator_amplitudes() -> st.SearchStrategy[float]:
    """An oscillation amplitude from -10 to 10 (a negative one is a half-period phase shift)."""
    return st.floats(min_value=-10.0, max_value=10.0)


def oscillator_times() -> st.SearchStrategy[float]:
    """A time from 0 to 100 (up to some 160 periods at the highest frequency)."""
    return st.floats(min_value=0.0, max_value=100.0)


def fraction_coefficients() -> st.SearchStrategy[Fraction]:
    """An exact positive coefficient p/q (of a parabola a x^2, or a planet's radius)."""
    return rationals(Fraction(1, 100), 100, 100)


def clock_sizes() -> st.SearchStrategy[int]:
    """Hours on a phasor clock, 1 to 48."""
    return st.integers(min_value=1, max_value=48)


def clock_hours() -> st.SearchStrategy[int]:
    """An hour or a lead on a clock, -100 to 100."""
    return st.integers(min_value=-100, max_value=100)
