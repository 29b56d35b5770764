"""Strategies of collisions, bangs and operators (chapters 2-5): masses, velocities and
restitutions as floats, as fractions and as exact draws; bang histories."""

from __future__ import annotations

from fractions import Fraction

from hypothesis import strategies as st

from checks.properties.strategies.exact import rationals

MASS_RANGE = (1e-6, 1e6)
SPEED_LIMIT = 1e3


def masses() -> st.SearchStrategy[float]:
    """A finite positive mass from 1e-6 to 1e6, spread evenly over the decades."""
    return st.floats(min_value=-6, max_value=6, allow_nan=False).map(lambda k: 10.0**k)


def velocities() -> st.SearchStrategy[float]:
    """A velocity from -1e3 to 1e3; magnitudes below 1e-9 are drawn as exactly 0, so that
    products with masses stay normal floats (a subnormal has no relative precision)."""
    return st.floats(min_value=-SPEED_LIMIT, max_value=SPEED_LIMIT, allow_nan=False).map(
        lambda v: v if abs(v) >= 1e-9 else 0.0
    )


def restitutions() -> st.SearchStrategy[float]:
    """A restitution coefficient from 0 (sticking) to 1 (elastic)."""
    return st.floats(min_value=0.0, max_value=1.0, allow_nan=False)


def fraction_masses() -> st.SearchStrategy[Fraction]:
    """An exact positive mass p/q."""
    return rationals(Fraction(1, 1000), 1000, 1000)


def fraction_velocities() -> st.SearchStrategy[Fraction]:
    """An exact velocity p/q from -1000 to 1000."""
    return rationals(-1000, 1000, 1000)


def fraction_restitutions() -> st.SearchStrategy[Fraction]:
    """An exact restitution coefficient in [0, 1]."""
    return rationals(0, 1, 100)


# Exact draws built from integers p/q: a few times cheaper than st.fractions, whose draws
# dominate the run time of the exact collision properties.


def exact_masses() -> st.SearchStrategy[Fraction]:
    """An exact positive mass p/q, from 1/1000 to 10^6."""
    return st.builds(Fraction, st.integers(1, 10**6), st.integers(1, 1000))


def exact_velocities() -> st.SearchStrategy[Fraction]:
    """An exact velocity p/q from -1000 to 1000."""
    return st.builds(Fraction, st.integers(-(10**6), 10**6), st.integers(1, 1000))


def exact_restitutions() -> st.SearchStrategy[Fraction]:
    """An exact restitution coefficient p/q in [0, 1], with 0 and 1 among the draws."""
    return st.builds(
        lambda p, q: Fraction(p % (q + 1), q), st.integers(0, 10**4), st.integers(1, 100)
    )


def exact_velocity_pairs() -> st.SearchStrategy[tuple[Fraction, Fraction]]:
    """An exact velocity vector (V1, V2), a point of the velocity-velocity plane (Fig. 3.1)."""
    return st.tuples(exact_velocities(), exact_velocities())


def exact_symmetric_matrices() -> st.SearchStrategy[tuple[tuple[Fraction, ...], ...]]:
    """An exact transpose-symmetric 2 x 2 matrix ((a, c), (c, b)): an inertia tensor with
    M_jk = M_kj (3.9b) that need not be diagonal."""
    entry = exact_velocities()
    return st.tuples(entry, entry, entry).map(lambda t: ((t[0], t[2]), (t[2], t[1])))


# --- bangs and operators (chapters 4-5) ---------------------------------------------------------
def moderate_fraction_masses() -> st.SearchStrategy[Fraction]:
    """An exact mass p/q from 1/20 to 20: exact bang sequences and histories stay small."""
    return rationals(Fraction(1, 20), 20, 20)


def drop_speeds() -> st.SearchStrategy[Fraction]:
    """An exact drop speed v0 > 0 of the X2 launcher, 1/10 to 10."""
    return rationals(Fraction(1, 10), 10, 10)


def mirror_angles() -> st.SearchStrategy[float]:
    """An angle in radians from -3 to 3 (inside (-pi, pi)): a reflection's phi or a turn."""
    return st.floats(min_value=-3.0, max_value=3.0, allow_nan=False)


def square_roots() -> st.SearchStrategy[int]:
    """A positive integer k, so that k^2 is a perfect-square mass (Fig. 5.2(f))."""
    return st.integers(min_value=1, max_value=50)


@st.composite
def exact_histories(draw: st.DrawFn) -> dict[str, Fraction]:
    """Arguments of bangs.bang_history: exact masses, 0 <= y1 <= y2 <= ceiling, velocities."""
    ceiling = draw(rationals(1, 10, 10))
    y2 = draw(rationals(0, ceiling, 10))
    y1 = draw(rationals(0, y2, 10))
    speeds = rationals(-5, 5, 10)
    return {
        "m1": draw(moderate_fraction_masses()),
        "m2": draw(moderate_fraction_masses()),
        "y1": y1,
        "y2": y2,
        "v1": draw(speeds),
        "v2": draw(speeds),
        "ceiling": ceiling,
    }
