"""Hypothesis strategies for the property suite, named for what they draw.

Inputs are built valid rather than filtered; floats are bounded and never NaN or infinite.
"""

from __future__ import annotations

import math
from fractions import Fraction

from hypothesis import strategies as st

from mechmodel.algebra import Laurent

MASS_RANGE = (1e-6, 1e6)
SPEED_LIMIT = 1e3


def rationals(
    low: Fraction | int, high: Fraction | int, max_denominator: int
) -> st.SearchStrategy[Fraction]:
    """An exact p/q in [low, high] with 1 <= q <= max_denominator, unpacked from one drawn
    integer n (q from n mod max_denominator, p from the rest): one draw is a third cheaper than
    two, and ``st.fractions`` draws the same numbers several times more slowly. Shrinking n
    towards 0 gives the least whole number in the range (q = 1)."""
    low, high = Fraction(low), Fraction(high)

    def build(n: int) -> Fraction:
        q, u = n % max_denominator + 1, n // max_denominator
        first, last = math.ceil(low * q), math.floor(high * q)
        return Fraction(first + u % (last - first + 1), q)

    return st.integers(0, max_denominator * 2**31 - 1).map(build)


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


# --- slope geometry and trigonometry (mechmodel.geometry, chapter 1) -------------------------
ANGLE_MARGIN = 0.01  # radians kept away from the zeros of sin and cos


def angles() -> st.SearchStrategy[float]:
    """Any angle from -4π to 4π radians (two turns either way)."""
    return st.floats(min_value=-4 * 3.141592653589793, max_value=4 * 3.141592653589793)


def oblique_angles() -> st.SearchStrategy[float]:
    """An angle at least ANGLE_MARGIN away from every multiple of π/2, built as a whole number
    of quarter turns (-8 to 7) plus an offset, so that all six trigonometric segments are
    finite."""
    quarter = 3.141592653589793 / 2
    return st.tuples(
        st.integers(min_value=-8, max_value=7),
        st.floats(min_value=ANGLE_MARGIN, max_value=quarter - ANGLE_MARGIN),
    ).map(lambda kd: kd[0] * quarter + kd[1])


def acute_angles() -> st.SearchStrategy[float]:
    """A slope angle strictly inside the first quadrant, ANGLE_MARGIN from its ends."""
    return st.floats(min_value=ANGLE_MARGIN, max_value=3.141592653589793 / 2 - ANGLE_MARGIN)


def unit_interval_values() -> st.SearchStrategy[float]:
    """A value of sine or cosine: -1 to 1."""
    return st.floats(min_value=-1.0, max_value=1.0)


def slopes() -> st.SearchStrategy[float]:
    """A slope Δy/Δx from -1e3 to 1e3."""
    return st.floats(min_value=-1e3, max_value=1e3)


def lengths() -> st.SearchStrategy[float]:
    """A positive length (or scale factor) from 1e-3 to 1e3, spread evenly over the decades."""
    return st.floats(min_value=-3, max_value=3).map(lambda k: 10.0**k)


def secants() -> st.SearchStrategy[float]:
    """A secant sec σ >= 1: the distance of a point outside the unit circle, 1 to 1e3."""
    return st.floats(min_value=0, max_value=3).map(lambda k: 10.0**k)


def fraction_lengths() -> st.SearchStrategy[Fraction]:
    """An exact positive length (or speed, or scale factor) p/q."""
    return rationals(Fraction(1, 1000), 1000, 1000)


def fraction_slopes() -> st.SearchStrategy[Fraction]:
    """An exact non-zero slope or speed p/q from -1000 to 1000."""
    sign = st.sampled_from((-1, 1))
    return st.builds(lambda s, x: s * x, sign, rationals(Fraction(1, 1000), 1000, 1000))


def molecule_sizes() -> st.SearchStrategy[int]:
    """Number of atoms N of a non-linear molecule, 3 to 1000."""
    return st.integers(min_value=3, max_value=1000)


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


# --- chapter 10: series, binomials, phasors (mechmodel.series) --------------------------------

SERIES_ARGUMENT_LIMIT = 10.0


def series_arguments() -> st.SearchStrategy[float]:
    """A real argument x (or w t) of the exponential, sine and cosine series, -10 to 10."""
    return st.floats(
        min_value=-SERIES_ARGUMENT_LIMIT, max_value=SERIES_ARGUMENT_LIMIT, allow_nan=False
    )


def series_orders() -> st.SearchStrategy[int]:
    """A precision order o of a partial sum, 0 to 30."""
    return st.integers(min_value=0, max_value=30)


def binomial_powers() -> st.SearchStrategy[int]:
    """A power n of (x + y)^n, a row of Pascal's triangle, 0 to 60."""
    return st.integers(min_value=0, max_value=60)


def phase_angles() -> st.SearchStrategy[float]:
    """A phase angle in radians, -2 pi to 2 pi."""
    return st.floats(min_value=-6.3, max_value=6.3, allow_nan=False)


def compounding_periods() -> st.SearchStrategy[int]:
    """A number m of compounding periods, 1 to 1e9, spread evenly over the decades."""
    return st.floats(min_value=0, max_value=9, allow_nan=False).map(lambda k: int(10.0**k))


def plane_points() -> st.SearchStrategy[tuple[float, float]]:
    """A point (x, y) of the plane with coordinates from -1e3 to 1e3."""
    coordinate = st.floats(min_value=-1e3, max_value=1e3, allow_nan=False)
    return st.tuples(coordinate, coordinate)


# --- complex fields (mechmodel.complexfields, chapter 10) -----------------------------------


def small_fractions() -> st.SearchStrategy[Fraction]:
    """An exact rational p/q with |p| <= 20 and 1 <= q <= 12."""
    return st.builds(Fraction, st.integers(-20, 20), st.integers(1, 12))


def gaussian_integers() -> st.SearchStrategy[tuple[int, int]]:
    """An exact complex number re + i im with integer parts from -9 to 9."""
    return st.tuples(st.integers(-9, 9), st.integers(-9, 9))


def xy_polynomials() -> st.SearchStrategy[dict[tuple[int, int], tuple[int, int]]]:
    """A polynomial in x, y of degree at most 2 in each with Gaussian-integer coefficients:
    {(i, j): (re, im)} for the term (re + i im) x^i y^j (zero terms included)."""
    keys = [(i, j) for i in range(3) for j in range(3)]
    return st.lists(st.integers(-9, 9), min_size=18, max_size=18).map(
        lambda c: {k: (c[2 * n], c[2 * n + 1]) for n, k in enumerate(keys)}
    )


def analytic_polynomials() -> st.SearchStrategy[dict[int, tuple[int, int]]]:
    """A polynomial in z alone, degree at most 3, with Gaussian-integer coefficients:
    {k: (re, im)} for the term (re + i im) z^k."""
    return st.lists(st.integers(-9, 9), min_size=8, max_size=8).map(
        lambda c: {k: (c[2 * k], c[2 * k + 1]) for k in range(4)}
    )


def laurent_terms() -> st.SearchStrategy[list[tuple[float, float, int]]]:
    """Terms (re, im, k) of a Laurent polynomial sum c_k z^k with powers -4 to 4."""
    coefficient = st.floats(min_value=-5, max_value=5, allow_nan=False)
    term = st.tuples(coefficient, coefficient, st.integers(-4, 4))
    return st.lists(term, min_size=1, max_size=6)


def loop_circles() -> st.SearchStrategy[tuple[float, float, float]]:
    """A circle (centre x, centre y, radius) whose edge keeps at least a third of its radius
    away from the origin: it either encloses the origin well or passes well clear of it."""

    def build(parts: tuple[float, float, float, bool]) -> tuple[float, float, float]:
        import math

        radius, angle, fraction, enclose = parts
        distance = fraction * radius * (0.6 if enclose else 1) + (0 if enclose else 1.4 * radius)
        return (distance * math.cos(angle), distance * math.sin(angle), radius)

    return st.tuples(
        st.floats(min_value=0.2, max_value=5),
        st.floats(min_value=-3.2, max_value=3.2),
        st.floats(min_value=0, max_value=1),
        st.booleans(),
    ).map(build)


def off_origin_points() -> st.SearchStrategy[complex]:
    """A point z of the plane with 0.3 <= |z| <= 3 (away from the poles at the origin)."""

    def build(parts: tuple[float, float]) -> complex:
        import cmath

        radius, angle = parts
        return cmath.rect(radius, angle)

    return st.tuples(
        st.floats(min_value=0.3, max_value=3), st.floats(min_value=-3.1, max_value=3.1)
    ).map(build)


def field_powers() -> st.SearchStrategy[int]:
    """An integer power n of a field z^n, -6 to 6."""
    return st.integers(-6, 6)


def sphere_angles(*, off_equator: bool = False) -> st.SearchStrategy[float]:
    """A central angle theta of a point on the projection sphere, 0.05 to 3.09 rad (not the
    poles); with ``off_equator`` also more than 1e-3 from the equator pi/2 (the draws above
    it are moved 2.5e-3 up, over it)."""
    if not off_equator:
        return st.floats(min_value=0.05, max_value=3.09)
    return st.floats(min_value=0.05, max_value=3.09 - 2.5e-3).map(
        lambda t: t if t < math.pi / 2 - 1e-3 else t + 2.5e-3
    )


def sphere_diameters() -> st.SearchStrategy[float]:
    """A sphere diameter from 0.1 to 10."""
    return st.floats(min_value=0.1, max_value=10)


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


# --- Lagrange vs Hamilton (mechmodel.lagrange, chapter 12) and vectors (Appendix 1.A) ------------


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


def exact_vectors3() -> st.SearchStrategy[tuple[Fraction, Fraction, Fraction]]:
    """An exact 3-vector with rational components p/q, |p| <= 50, q <= 12."""
    comp = st.builds(Fraction, st.integers(-50, 50), st.integers(1, 12))
    return st.tuples(comp, comp, comp)


def exact_plane_vectors() -> st.SearchStrategy[tuple[Fraction, Fraction]]:
    """An exact plane vector with rational components p/q, |p| <= 50, q <= 12."""
    comp = st.builds(Fraction, st.integers(-50, 50), st.integers(1, 12))
    return st.tuples(comp, comp)


def levi_civita_index_quads() -> st.SearchStrategy[tuple[int, int, int, int]]:
    """Four Cartesian indices (i, j, m, n), each 1, 2 or 3."""
    index = st.integers(min_value=1, max_value=3)
    return st.tuples(index, index, index, index)


def exact_square_matrices() -> st.SearchStrategy[list[list[int]]]:
    """An exact n x n integer matrix, n from 1 to 4, entries -9 to 9."""
    return st.integers(min_value=1, max_value=4).flatmap(
        lambda n: st.lists(
            st.lists(st.integers(-9, 9), min_size=n, max_size=n), min_size=n, max_size=n
        )
    )


def printed_decimals() -> st.SearchStrategy[str]:
    """A number as the book prints it: a sign or none, digits with the point anywhere (or no
    point), from "0" to "-98765.4321", never with a leading zero before other digits."""

    def build(sign: bool, digits: str, point: int) -> str:
        digits = digits.lstrip("0") or "0"
        place = min(point, len(digits))
        text = digits if place == 0 else f"{digits[:-place] or '0'}.{digits[-place:]}"
        return f"-{text}" if sign and text.strip("0.") else text

    return st.builds(
        build,
        st.booleans(),
        st.text(alphabet="0123456789", min_size=1, max_size=9),
        st.integers(0, 6),
    )


# --- exact algebra (mechmodel.algebra) ---------------------------------------------------------


def laurent_polynomials() -> st.SearchStrategy[Laurent]:
    """A Laurent polynomial in x and y of one to four terms c x^i y^j, c from -3 to 3, i and j
    from -2 to 3 (negative powers included)."""
    term = st.tuples(st.integers(-3, 3), st.integers(-2, 3), st.integers(-2, 3))
    return st.lists(term, min_size=1, max_size=4).map(
        lambda terms: sum(
            (Laurent.term(c, x=i, y=j) for c, i, j in terms),
            Laurent(),
        )
    )
