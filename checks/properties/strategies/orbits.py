"""Strategies of chapters 11-12: oscillator orbits, quadratic forms, triads and rods
(mechmodel.oscillators, rotation); Lagrange vs Hamilton (mechmodel.lagrange)."""

from __future__ import annotations

from fractions import Fraction

from hypothesis import strategies as st

# --- chapter 11: oscillator orbits, quadratic forms, triads, rods ------------------------------


def orbit_radii() -> st.SearchStrategy[float]:
    """A semi-axis a or b of an oscillator orbit ellipse, 0.1 to 10, spread over the decades."""
    return st.floats(min_value=-1, max_value=1).map(lambda k: 10.0**k)


def orbit_omegas() -> st.SearchStrategy[float]:
    """An angular frequency w of the oscillator, 0.1 to 10 rad per unit time."""
    return st.floats(min_value=-1, max_value=1).map(lambda k: 10.0**k)


def orbit_phases() -> st.SearchStrategy[float]:
    """A phase w t of the orbit, -2 to 2 turns (in radians)."""
    return st.floats(min_value=-4 * 3.141592653589793, max_value=4 * 3.141592653589793)


def orbit_fractions() -> st.SearchStrategy[float]:
    """A fraction of a period, 0.01 to 0.99 (a time interval shorter than one orbit)."""
    return st.floats(min_value=0.01, max_value=0.99)


def exact_radii() -> st.SearchStrategy[Fraction]:
    """An exact positive semi-axis or length p/q, from 1/12 to 12."""
    return st.builds(Fraction, st.integers(1, 144), st.integers(1, 12))


def exact_distinct_radii() -> st.SearchStrategy[tuple[Fraction, Fraction]]:
    """Two exact unequal semi-axes (a, b) of an ellipse (a drawn tie becomes (a, 2a))."""
    return st.tuples(exact_radii(), exact_radii()).map(
        lambda ab: ab if ab[0] != ab[1] else (ab[0], 2 * ab[0])
    )


def rational_half_angle_tans() -> st.SearchStrategy[Fraction]:
    """An exact tan(u/2) from -20 to 20: a rational point (cos u, sin u) of the unit circle."""
    return st.builds(Fraction, st.integers(-240, 240), st.integers(1, 12))


def form_angles() -> st.SearchStrategy[float]:
    """A rotation angle of an ellipse, -pi to pi radians."""
    return st.floats(min_value=-3.141592653589793, max_value=3.141592653589793)


def derivative_orders() -> st.SearchStrategy[int]:
    """An order n of a time derivative of the orbit, 0 to 12."""
    return st.integers(min_value=0, max_value=12)


def matrix_powers() -> st.SearchStrategy[int]:
    """A power p of the slope operator R, -4 to 4."""
    return st.integers(min_value=-4, max_value=4)


def triad_indices() -> st.SearchStrategy[int]:
    """An index k of the triad sequence of Fig. 11.7, -3 to 3."""
    return st.integers(min_value=-3, max_value=3)


def triad_start_angles() -> st.SearchStrategy[float]:
    """A starting angle phi_0 of a triad sequence, inside the first quadrant (0.05 to 1.5)."""
    return st.floats(min_value=0.05, max_value=1.5)


def hit_fractions() -> st.SearchStrategy[Fraction]:
    """An exact hit height h/l of an impulse on a rod, 1/12 to 1 (the end of the rod)."""
    return st.builds(Fraction, st.integers(1, 12), st.just(12))


def riemann_steps() -> st.SearchStrategy[int]:
    """A number of slices N of a Riemann sum, 1 to 50."""
    return st.integers(min_value=1, max_value=50)


# --- Lagrange vs Hamilton (mechmodel.lagrange, chapter 12) ------------------------------------


def convex_lagrangian_coefficients() -> st.SearchStrategy[tuple[float, float]]:
    """Coefficients (a, b) of a convex Lagrangian L(v) = a v^2/2 + b v^4/4: a mass a from 0.1 to
    10 and a quartic stiffening b from 0 to 1."""
    return st.tuples(
        st.floats(min_value=-1, max_value=1).map(lambda k: 10.0**k),
        st.floats(min_value=0, max_value=1),
    )


def legendre_slopes() -> st.SearchStrategy[float]:
    """A slope (a momentum p or a velocity v) from -5 to 5 at which to take a Legendre
    transform."""
    return st.floats(min_value=-5, max_value=5)


def exact_square_mass_ratios() -> st.SearchStrategy[Fraction]:
    """A mass ratio m1/m2 = (p/q)^2 with a rational root, so the V-plane slopes stay exact."""
    return st.builds(lambda p, q: Fraction(p, q) ** 2, st.integers(1, 30), st.integers(1, 30))


def launch_speeds() -> st.SearchStrategy[float]:
    """A launch speed v0 from 0.5 to 50 (m/s or scaled)."""
    return st.floats(min_value=0.5, max_value=50)


def launch_angles() -> st.SearchStrategy[float]:
    """An elevation angle strictly between horizontal and vertical (0.05 rad from each)."""
    return st.floats(min_value=0.05, max_value=3.141592653589793 / 2 - 0.05)


def gravities() -> st.SearchStrategy[float]:
    """A uniform gravity g from 1 to 25 (m/s^2 or scaled): Io's 1.8 to Jupiter's 24.8."""
    return st.floats(min_value=1, max_value=25)


def oscillator_orbits() -> st.SearchStrategy[tuple[float, float, float, float, float]]:
    """A 2-D isotropic oscillator orbit x = A cos(t + a), y = B cos(t + b) (omega = 1): the
    amplitudes A, B from 0.2 to 5, the phases a, b, and a time t, all in radians."""
    amplitude = st.floats(min_value=0.2, max_value=5)
    phase = st.floats(min_value=-3.141592653589793, max_value=3.141592653589793)
    return st.tuples(amplitude, amplitude, phase, phase, phase)
