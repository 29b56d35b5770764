"""Laws of multipoles (mechmodel.complexfields.multipoles): chapter 10, (10.40)-(10.44),
Figs. 10.9-10.14.

Dipoles, 4-poles and 2^k-poles, their sources and far fields, Laurent terms, level lines.
Float geometry is compared within 1e-12 of the magnitudes involved, central differences
within their truncation error; far fields at 60 digits (mpmath).

Shared helpers of the complexfields modules are in ``_complexfields_helpers``.
"""

from __future__ import annotations

import cmath
import math

import mpmath
import pytest
from hypothesis import given
from hypothesis import strategies as st

from checks.properties._complexfields_helpers import HALF, z_derivative
from checks.properties.closeness import assert_close
from checks.properties.strategies import off_origin_points
from mechmodel import complexfields as cf

pytestmark = pytest.mark.properties


@pytest.mark.parametrize("n", [n for n in range(-6, 7) if n != -1])
def test_level_lines_of_power_potentials_cross_at_right_angles(n: int) -> None:
    """The Phi-equipotentials and A-streamlines of the potential of z^n meet at 90 degrees
    everywhere off the poles, at every distance from them (Fig. 10.13), numerically by
    central differences; the origin itself is a pole or a zero of the field (no angle)."""
    for z in (complex(0.7, 0.4), complex(-1.3, 0.2), complex(0.1, -2.0), 1 + 0j, 600 - 800j):
        angle = cf.level_line_angle(n, z.real, z.imag)
        assert_close(angle.value, math.pi / 2, rel=0, abs=angle.error)
    with pytest.raises(ValueError, match="origin"):
        cf.level_line_angle(n, 0, 0)


@pytest.mark.parametrize("k", range(8))
def test_each_z_derivative_doubles_the_sources(k: int) -> None:
    """A 2^k-pole built by k (-)copies of a unit 1-pole has 2^k distinct sources of strength
    +1 and -1 (10.41), (10.43), and its moments sum q p^m below the k-th vanish: its
    expansion starts at z^-(k+1) (10.44)."""
    assert cf.multipole_pole_count(k) == 2**k
    sources = cf.multipole_sources(k)
    strengths = sorted(q for q, _ in sources)
    assert strengths == ([1] if k == 0 else [-1] * 2 ** (k - 1) + [1] * 2 ** (k - 1))
    size = max(abs(p) for _, p in sources) or 1.0
    for m in range(k):
        assert abs(sum(q * p**m for q, p in sources)) <= 1e-12 * 2**k * size**m


@pytest.mark.parametrize("k", range(7))
def test_a_two_to_the_k_pole_has_the_far_field_of_z_to_the_minus_k_minus_one(k: int) -> None:
    """The field of the 2^k-pole construction falls off as |z|^-(k+1): it is the z^-(k+1)
    term of the multipole expansion (10.44). (At 60 digits: the sources nearly cancel.)"""
    with mpmath.workdps(60):
        sources = cf.multipole_sources(k, spacing=mpmath.mpf("1e-4"))
        f1, f2 = (
            abs(cf.multipole_field(mpmath.mpc(cmath.rect(r, 0.37)), sources)) for r in (1.0, 2.0)
        )
        slope = float(mpmath.log(f2 / f1) / mpmath.log(2))
    assert_close(slope, -(k + 1), rel=0, abs=1e-3)


@pytest.mark.parametrize("n", range(-8, 9))
def test_laurent_terms_and_multipoles_correspond_one_to_one(n: int) -> None:
    """Each Laurent term a_n z^n is one 2^k-pole at z = 0 (n < 0) or z = infinity (n >= 0),
    and that multipole gives back the term (10.44)."""
    term = cf.multipole_of_laurent_term(n)
    assert term.poles == 2**term.order
    assert cf.laurent_term_of_multipole(term.order, term.location) == n


@given(off_origin_points())
def test_the_dipole_pair_tends_to_the_point_dipole(z: complex) -> None:
    """f_dipole / Delta -> -a/z^2 as the separation Delta -> 0 (10.41): the error is O(Delta^2);
    at any separation it is the sum of the fields a/(z - p) of its two line sources."""
    pair = cf.dipole_pair(2)
    separation = 1e-4
    limit = complex(pair.point_dipole_coefficient) / z**2
    ratio = cf.dipole_pair_field(z, separation) / separation
    assert abs(ratio - limit) <= 10 * (separation / abs(z)) ** 2 * abs(limit) + 1e-9 * abs(limit)
    wide = 0.25  # the pair is the sum of its two line-source fields a/(z - p) (10.38)
    sources = [(1, complex(-wide / 2)), (-1, complex(wide / 2))]
    total = cf.multipole_field(z, sources)
    assert abs(total - cf.dipole_pair_field(z, wide)) <= 1e-12 * (abs(total) + 1 / abs(z))
    assert abs(cf.multipole_field(z, [(1, z / 2)]) * z / 2 - 1) <= 1e-12


def test_the_quadrupole_factors_are_exact() -> None:
    """f_4 = (1/2) df_2/dz and phi_4 = -a/(2 z^2) = (1/2) dphi_2/dz (10.43)."""
    q = cf.quadrupole_relations()
    assert (q.field_factor, q.potential_divisor_magnitude, q.potential_factor) == (HALF, 2, HALF)


# --- formulas at a point (the models of the formula claims) -----------------------------------


@given(st.integers(0, 5), st.sampled_from(["origin", "infinity"]), off_origin_points())
def test_multipole_terms_scale_as_their_laurent_power(order: int, where: str, z: complex) -> None:
    """The field term of a 2^order-pole grows by 2^n when z doubles, n its Laurent power: a
    negative power for a pole at the origin, a non-negative one at infinity (10.44); there is
    no 2^0-pole (monopole) at infinity."""
    if order == 0 and where == "infinity":
        with pytest.raises(ArithmeticError, match="one term"):
            cf.multipole_term_at(order, where, z.real, z.imag)
        return
    n = cf.laurent_term_of_multipole(order, where)
    assert (n < 0) == (where == "origin")
    small = cf.multipole_term_at(order, where, z.real, z.imag)
    large = cf.multipole_term_at(order, where, 2 * z.real, 2 * z.imag)
    assert abs(large.field - 2.0**n * small.field) <= 1e-12 * abs(large.field)


@given(
    st.floats(min_value=0.1, max_value=5),
    st.floats(min_value=0.01, max_value=0.5),
    off_origin_points(),
)
def test_a_dipole_pair_is_two_opposite_line_sources(a: float, sep: float, z: complex) -> None:
    """The pair +a at -D/2, -a at +D/2 is the sum of two line sources (10.40); its potential
    differentiates to its field (10.33a); far away, or for a small separation D, the field
    divided by D is the point dipole -a/z^2 of (10.41a)."""
    if min(abs(z - sep / 2), abs(z + sep / 2)) < 0.1:
        z = z * 3
    pair = cf.dipole_pair_at(a, sep, z.real, z.imag)
    plus = cf.power_field_at(-1, z.real + sep / 2, z.imag, a, 0)
    minus = cf.power_field_at(-1, z.real - sep / 2, z.imag, a, 0)
    assert abs(pair.field - (plus.field - minus.field)) <= 1e-12 * (abs(plus.field) + 1)

    def potential(w: complex) -> complex:
        return cf.dipole_pair_at(a, sep, w.real, w.imag).potential

    for derivative in z_derivative(potential, z):
        assert abs(derivative - pair.field) <= 1e-5 * (abs(pair.field) + a)
    tiny = 1e-5
    small = cf.dipole_pair_at(a, tiny, z.real, z.imag).field / tiny
    point = cf.line_multipole_at(a, 1, z.real, z.imag).field
    assert abs(small - point) <= 1e-6 * abs(point)


@given(st.integers(0, 4), st.floats(min_value=0.1, max_value=5), off_origin_points())
def test_line_multipoles_are_derivatives_of_the_line_source(k: int, a: float, z: complex) -> None:
    """The k-th multipole is the line source a/z differentiated k times and its potential
    a ln z differentiated k times (10.40)-(10.43): the potential differentiates to the field,
    the next field is the derivative of this one, a factor scales both, and the polar form
    gives the same point."""
    m = cf.line_multipole_at(a, k, z.real, z.imag)
    nxt = cf.line_multipole_at(a, k + 1, z.real, z.imag)
    if k == 0:
        assert m.field == cf.power_field_at(-1, z.real, z.imag, a, 0).field

    def potential(w: complex) -> complex:
        return cf.line_multipole_at(a, k, w.real, w.imag).potential

    def field(w: complex) -> complex:
        return cf.line_multipole_at(a, k, w.real, w.imag).field

    for derivative in z_derivative(potential, z):
        assert abs(derivative - m.field) <= 1e-5 * (abs(m.field) + abs(m.potential) / abs(z))
    for derivative in z_derivative(field, z):
        assert abs(derivative - nxt.field) <= 1e-5 * (abs(nxt.field) + abs(m.field) / abs(z))
    half = cf.line_multipole_at(a, k, z.real, z.imag, HALF)
    assert abs(half.field - m.field / 2) <= 1e-15 * abs(m.field)
    polar = cf.line_multipole_polar(a, k, abs(z), cmath.phase(z))
    assert abs(polar.field - m.field) <= 1e-12 * abs(m.field)


@given(
    st.floats(min_value=0.1, max_value=5),
    st.floats(min_value=0.1, max_value=5),
    st.floats(min_value=0.1, max_value=1.4),
)
def test_dipole_level_lines_pass_through_their_level(a: float, level: float, theta: float) -> None:
    """On the ray at angle theta the point-dipole potential a/z (10.42) takes the level Phi or A
    at the distance the model gives, and twice the level at half that distance (Fig. 10.11);
    a ray that never reaches the level is refused."""
    for part, angle, value in (("phi", theta, level), ("a", -theta, level), ("a", theta, -level)):
        r = cf.dipole_level_radius(a, value, angle, part)
        at = cf.line_multipole_polar(a, 1, r, angle)
        assert_close(getattr(at, part), value, rel=0, abs=1e-12 * abs(value))
        assert_close(cf.dipole_level_radius(a, 2 * value, angle, part), r / 2, rel=0, abs=1e-12 * r)
    with pytest.raises(ValueError, match="does not reach"):
        cf.dipole_level_radius(a, -level, theta, "phi")


@pytest.mark.parametrize("m", [m for m in range(-6, 7) if m])
def test_a_potential_term_belongs_to_a_two_to_the_abs_m_pole(m: int) -> None:
    """The potential term a_(m-1) z^m/m comes from the field term a_(m-1) z^(m-1): a 2^|m|-pole,
    at z = 0 for m < 0 and at infinity for m > 0 (10.44); m = 0 is the logarithm."""
    assert cf.potential_term_poles(m) == 2 ** abs(m)
    with pytest.raises(ValueError, match="ln z"):
        cf.potential_term_poles(0)
