"""Laws of complex derivatives, potentials and fields (mechmodel.complexfields): chapter 10.

Polynomial algebra is exact (Gaussian rationals), so its laws hold with equality. Contour
integrals are numerical and carry their own error estimate; a law holds within that estimate
(plus a few units of rounding of the float result). Float geometry is compared within 1e-9.
"""

from __future__ import annotations

import cmath
import math
from fractions import Fraction

import mpmath
import pytest
from hypothesis import given, target

from checks.properties.strategies import (
    analytic_polynomials,
    field_powers,
    gaussian_integers,
    laurent_terms,
    loop_circles,
    off_origin_points,
    small_fractions,
    sphere_angles,
    sphere_diameters,
    xy_polynomials,
)
from mechmodel import complexfields as cf

pytestmark = pytest.mark.properties
HALF = Fraction(1, 2)
NONNEGATIVE_POWERS = field_powers().filter(lambda n: n >= 0)


def gaussian(parts: tuple[int, int]) -> cf.Gaussian:
    return cf.Gaussian(Fraction(parts[0]), Fraction(parts[1]))


def xy_poly(terms: dict[tuple[int, int], tuple[int, int]]) -> cf.Poly:
    return cf.Poly({k: gaussian(c) for k, c in terms.items()})


def z_poly(terms: dict[int, tuple[int, int]]) -> cf.Poly:
    """An analytic polynomial sum c_k z^k written in x, y."""
    return cf.zpoly_to_xy(cf.Poly({(k, 0): gaussian(c) for k, c in terms.items()}))


def close(a: float, b: float, tol: float) -> bool:
    return abs(a - b) <= tol


# --- (10.31)-(10.32): the z- and z*-derivatives ---------------------------------------------


@given(xy_polynomials())
def test_z_derivatives_follow_the_chain_rule_and_hold_div_and_curl(terms: dict) -> None:
    """df/dz = (1/2)(df/dx - i df/dy) and df/dz* = (1/2)(df/dx + i df/dy) for every polynomial
    f(x, y) (10.31), the model's factors coming from inverting z = x + iy, z* = x - iy; and
    for f = Fx + i Fy, df/dz = (1/2) div F + (i/2) curl F (10.32)."""
    f = xy_poly(terms)
    assert cf.d_dz(f) == (f.d_first() - f.d_second() * cf.I_UNIT) * HALF
    assert cf.d_dzstar(f) == (f.d_first() + f.d_second() * cf.I_UNIT) * HALF
    fx, fy = f.real_part(), f.imag_part()
    df = cf.d_dz(f)
    assert df.real_part() == cf.divergence(fx, fy) * HALF
    assert df.imag_part() == cf.curl_z(fx, fy) * HALF


@given(analytic_polynomials())
def test_analytic_potentials_obey_cauchy_riemann(terms: dict) -> None:
    """A potential phi = Phi + iA analytic in z has dphi/dz* = 0 and d/dz the ordinary
    derivative (10.31)-(10.33); dPhi/dx = dA/dy and dPhi/dy = -dA/dx, so F = grad Phi = curl A
    (10.35b-c), and the level curves of Phi and A cross at right angles (grad Phi . grad A = 0)."""
    phi = z_poly(terms)
    assert cf.d_dzstar(phi).is_zero()
    derivative = {k - 1: (re * k, im * k) for k, (re, im) in terms.items() if k}
    assert cf.d_dz(phi) == z_poly(derivative)
    big_phi, a = phi.real_part(), phi.imag_part()
    assert big_phi.d_first() == a.d_second()
    assert big_phi.d_second() == -a.d_first()
    assert cf.gradient(big_phi) == cf.curl_of_z_vector(a)
    gx, gy = cf.gradient(big_phi)
    ax, ay = cf.gradient(a)
    assert (gx * ax + gy * ay).is_zero()


@pytest.mark.parametrize("n", [n for n in range(-6, 7) if n != -1])
def test_level_lines_of_power_potentials_cross_at_right_angles(n: int) -> None:
    """The Phi-equipotentials and A-streamlines of the potential of z^n meet at 90 degrees
    everywhere off the poles (Fig. 10.13), numerically by central differences."""
    for z in (complex(0.7, 0.4), complex(-1.3, 0.2), complex(0.1, -2.0)):
        angle = cf.level_line_angle(n, z.real, z.imag)
        assert close(angle.value, math.pi / 2, angle.error)


@given(gaussian_integers())
def test_the_laminar_field_has_no_divergence_and_no_curl(a: tuple[int, int]) -> None:
    """f(z) = a z plotted as f*(z*) = a* z* has df*/dz = 0, div F = 0 and curl F = 0 (10.32),
    Fig. 10.7, for every complex a."""
    field = cf.conjugate_linear_field(*a)
    assert field.dfstar_dz_size == field.divergence_size == field.curl_size == 0


@given(small_fractions())
def test_factor_pairs_of_the_potentials_sum_to_one(f: Fraction) -> None:
    """F = f grad Phi + j curl A for an analytic potential exactly when f + j = 1 (10.34)."""
    assert cf.complementary_potential_factor(f).j == 1 - f


@given(NONNEGATIVE_POWERS, gaussian_integers())
def test_the_power_potential_gives_its_field(n: int, a: tuple[int, int]) -> None:
    """phi = a z^(n+1)/(n+1): grad Phi = curl A = F, the plotted field of f = a z^n (10.35)."""
    if a == (0, 0):
        a = (1, 0)
    p = cf.power_field_potential(n, *a)
    assert (p.grad_x, p.grad_y) == (p.field_x, p.field_y) == (p.curl_x, p.curl_y)


# --- power rule, multipoles ------------------------------------------------------------------


@pytest.mark.parametrize("n", [n for n in range(-8, 9) if n != -1])
def test_the_power_potential_differentiates_back_to_its_field(n: int) -> None:
    """d/dz [z^(n+1)/(n+1)] = z^n for every n but -1 (10.35a), (10.44)."""
    anti = cf.power_antiderivative(n)
    back = cf.laurent_derivative(anti.coefficient, anti.power)
    assert (back.coefficient, back.power) == (1, n)


def test_only_z_to_the_minus_one_lacks_a_power_potential() -> None:
    """The logarithmic case n = -1 is the one exception to the power rule (10.38)."""
    assert cf.exceptional_power(-20, 20) == -1


@pytest.mark.parametrize("k", range(8))
def test_each_z_derivative_doubles_the_sources(k: int) -> None:
    """A 2^k-pole built by k (-)copies has 2^k distinct sources (10.41), (10.43)."""
    assert cf.multipole_pole_count(k) == 2**k


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
    assert close(slope, -(k + 1), 1e-3)


@pytest.mark.parametrize("n", range(-8, 9))
def test_laurent_terms_and_multipoles_correspond_one_to_one(n: int) -> None:
    """Each Laurent term a_n z^n is one 2^k-pole at z = 0 (n < 0) or z = infinity (n >= 0),
    and that multipole gives back the term (10.44)."""
    term = cf.multipole_of_laurent_term(n)
    assert term.poles == 2**term.order
    assert cf.laurent_term_of_multipole(term.order, term.location) == n


@given(off_origin_points())
def test_the_dipole_pair_tends_to_the_point_dipole(z: complex) -> None:
    """f_dipole / Delta -> -a/z^2 as the separation Delta -> 0 (10.41): the error is O(Delta^2)."""
    pair = cf.dipole_pair(2)
    separation = 1e-4
    limit = complex(pair.point_dipole_coefficient) / z**2
    ratio = cf.dipole_pair_field(z, separation) / separation
    assert abs(ratio - limit) <= 10 * (separation / abs(z)) ** 2 * abs(limit) + 1e-9 * abs(limit)


def test_the_quadrupole_factors_are_exact() -> None:
    """f_4 = (1/2) df_2/dz and phi_4 = -a/(2 z^2) = (1/2) dphi_2/dz (10.43)."""
    q = cf.quadrupole_relations()
    assert (q.field_factor, q.potential_divisor_magnitude, q.potential_factor) == (HALF, 2, HALF)


# --- contour integrals (10.39), (10.44), (10.45) ----------------------------------------------


@given(
    laurent_terms().map(lambda ts: [t for t in ts if t[2] >= 0] or [(1.0, 0.0, 0)]), loop_circles()
)
def test_the_loop_integral_of_an_analytic_function_vanishes(terms: list, circle: tuple) -> None:
    """Cauchy's theorem: a polynomial (analytic everywhere) has zero loop integral around any
    circle (10.39)."""
    loop = cf.laurent_loop_integral([list(t) for t in terms], *circle)
    scale = (
        sum(
            abs(complex(re, im)) * (abs(complex(*circle[:2])) + circle[2]) ** k
            for re, im, k in terms
        )
        * 2
        * math.pi
        * circle[2]
    )
    tol = loop.real.error + 1e-12 * scale
    target(abs(complex(loop.real.value, loop.imag.value)) / (scale or 1), label="relative loop")
    assert abs(loop.real.value) <= tol
    assert abs(loop.imag.value) <= tol


@given(laurent_terms(), loop_circles())
def test_a_pole_gives_its_residue(terms: list, circle: tuple) -> None:
    """The loop integral of sum c_k z^k is 2 pi i c_-1 if the circle encloses the pole at the
    origin and zero if it does not (10.39), (10.44)."""
    cx, cy, radius = circle
    loop = cf.laurent_loop_integral([list(t) for t in terms], cx, cy, radius)
    residue = sum(complex(re, im) for re, im, k in terms if k == -1)
    expected = 2j * math.pi * residue if abs(complex(cx, cy)) < radius else 0j
    got = complex(loop.real.value, loop.imag.value)
    size = max(abs(complex(re, im)) for re, im, _ in terms)
    reach = max(abs(complex(cx, cy)) + radius, 1 / max(abs(abs(complex(cx, cy)) - radius), 1e-3))
    tol = loop.real.error + 1e-12 * size * 2 * math.pi * radius * reach**4
    assert abs(got - expected) <= tol


@pytest.mark.parametrize("n", range(-6, 7))
def test_only_the_monopole_term_has_a_loop_integral(n: int) -> None:
    """The loop integral of a (z - c)^n around c is 2 pi i a for n = -1 and zero otherwise
    (10.39), (10.45), at 30 digits."""
    for a, centre, radius in ((1 + 0j, 0j, 1.0), (-2 + 3j, 0.5 - 1.5j, 0.25), (0.5j, -3 + 1j, 4.0)):
        loop = cf.power_loop_integral(n, a.real, a.imag, centre.real, centre.imag, radius)
        expected = 2j * math.pi * a if n == -1 else 0j
        got = complex(loop.real.value, loop.imag.value)
        assert abs(got - expected) <= loop.real.error + 1e-14 * (1 + abs(a))


@given(gaussian_integers())
def test_a_line_source_has_flux_2_pi_re_a_and_circulation_minus_2_pi_im_a(a: tuple) -> None:
    """Im loop f dz counts the real source (flux) and Re loop f dz the imaginary source
    (vorticity) of f = a/z (10.37)-(10.39), Figs. 10.9-10.10."""
    src = cf.line_source(*a)
    tol = src.flux.error + 1e-13 * (1 + abs(complex(float(a[0]), float(a[1]))))
    assert close(src.flux.value, 2 * math.pi * float(a[0]), tol)
    assert close(src.circulation.value, -2 * math.pi * float(a[1]), tol)


@pytest.mark.parametrize("index", range(-5, 6))
def test_contour_integration_recovers_every_laurent_coefficient(index: int) -> None:
    """a_n = (1/(2 pi i)) loop z^(-n-1) f(z) dz for every n of a test Laurent series (10.44)."""
    check = cf.laurent_coefficient_check(index)
    assert close(check.two_pi.value, 2 * math.pi, check.two_pi.error + 1e-14)
    assert abs(check.residual.value) <= check.residual.error + 1e-14


@pytest.mark.parametrize("order", range(7))
def test_cauchys_derivative_formula_holds_for_every_order(order: int) -> None:
    """f^(n)(a) = (n!/(2 pi i)) loop f(z)/(z - a)^(n+1) dz (10.45), and the kernel power n + 1
    is the only one that works."""
    d = cf.cauchy_derivative(order)
    assert close(d.two_pi.value, 2 * math.pi, d.two_pi.error + 1e-14)
    assert close(d.numerator.value, math.factorial(order), d.numerator.error + 1e-12)
    assert close(d.taylor_numerator.value, 1.0, d.taylor_numerator.error + 1e-14)
    assert cf.cauchy_kernel(order).power == order + 1


# --- stereographic projection (Fig. 10.15) ---------------------------------------------------


@given(sphere_angles().filter(lambda t: abs(t - math.pi / 2) > 1e-3), sphere_diameters())
def test_the_stereographic_map_inverts_radii_through_half_angles(
    theta: float, diameter: float
) -> None:
    """|z| |w| = D^2 (w = 1/z on the unit-diameter sphere), |z| = D tan(theta/2), and the image
    of |z| through the sphere is |w|; the angles at the poles, the chords SP = D cos(theta/2),
    NP = D sin(theta/2) and the depths D sin^2(theta/2), D cos^2(theta/2) all use the half
    angle (Fig. 10.15)."""
    p = cf.stereographic_projection(theta, diameter)
    assert close(p.z_radius * p.w_radius, diameter**2, 1e-9 * diameter**2)
    assert close(p.z_radius, diameter * math.tan(theta / 2), 1e-9 * max(1, p.z_radius))
    image = cf.stereographic_image_radius(p.z_radius, diameter)
    assert close(image, p.w_radius, 1e-9 * max(1, p.w_radius))
    for divisor in (
        p.tan_angle_divisor,
        p.cot_angle_divisor,
        p.south_chord_angle_divisor,
        p.north_chord_angle_divisor,
        p.north_depth_angle_divisor,
        p.south_height_angle_divisor,
    ):
        assert close(divisor, 2, 1e-6)
    assert close(p.north_depth_exponent, 2, 1e-6)
    assert close(p.south_height_exponent, 2, 1e-6)


# --- non-analytic fields (10.46)-(10.56) -----------------------------------------------------


@given(gaussian_integers(), NONNEGATIVE_POWERS)
def test_sources_and_potentials_rebuild_the_non_analytic_field(k: tuple, n: int) -> None:
    """For f = k (z*)^n: rho = div fL* = div f* and I = -curl fT* = -curl f* (10.48), (10.54);
    the longitudinal part has no curl and the transverse part no divergence, and
    fL* + fT* = f* = k* z^n (10.50a): the potentials of phi = (1/2) integral f dz rebuild the
    whole field (10.52)-(10.54)."""
    if k == (0, 0):
        k = (1, 0)
    field = cf.conjugate_power_field(*k, n)
    assert field.rho == field.div_longitudinal
    neg_curl = {key: -c for key, c in field.curl_transverse.coefficients.items()}
    assert field.current.coefficients == neg_curl
    fstar = cf.zpoly_to_xy(cf.Poly({(n, 0): complex(*k).conjugate()}))
    assert field.total_x == cf.poly_view(fstar.real_part())
    assert field.total_y == cf.poly_view(fstar.imag_part())


def test_the_definition_factors_make_rho_the_divergence() -> None:
    """s* = 2 df*/dz and f* = 2 dphi*/dz* (10.46)-(10.47): both factors are 2, and phi takes
    the prefactor 1/2."""
    factors = cf.source_field_factors()
    assert (factors.source, factors.potential, factors.potential_prefactor) == (2, 2, HALF)
