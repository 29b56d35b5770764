"""Laws of complex derivatives, potentials and fields (mechmodel.complexfields): chapter 10.

Polynomial algebra is exact (Gaussian rationals), so its laws hold with equality. Contour
integrals are numerical and carry their own error estimate; a law holds within that estimate
(plus a few units of rounding of the float result). Float geometry is compared within 1e-9.
"""

from __future__ import annotations

import cmath
import math
import re
from collections.abc import Callable
from fractions import Fraction

import mpmath
import pytest
from hypothesis import example, given, target
from hypothesis import strategies as st

from checks.properties.closeness import assert_close
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
from mechmodel.algebra import I_UNIT, Gaussian, Laurent
from mechmodel.complexfields import cauchy

pytestmark = pytest.mark.properties
HALF = Fraction(1, 2)
EPS = 2.0**-52
XyTerms = dict[tuple[int, int], tuple[int, int]]  # {(i, j): (re, im)}: (re + i im) x^i y^j
ONES = {(i, j): (1, 1) for i in range(3) for j in range(3)}  # every term (1 + i) x^i y^j
NONNEGATIVE_POWERS = field_powers().map(abs)


def gaussian(parts: tuple[int, int]) -> Gaussian:
    return Gaussian(Fraction(parts[0]), Fraction(parts[1]))


def xy_poly(terms: dict[tuple[int, int], tuple[int, int]]) -> Laurent:
    return Laurent.from_powers(("x", "y"), {k: gaussian(c) for k, c in terms.items()})


def z_poly(terms: dict[int, tuple[int, int]]) -> Laurent:
    """An analytic polynomial sum c_k z^k written in x, y."""
    zs: dict[tuple[int, ...], Gaussian] = {(k, 0): gaussian(c) for k, c in terms.items()}
    return cf.zpoly_to_xy(Laurent.from_powers(("z", cf.ZSTAR), zs))


def view_at(view: cf.PolyView, z: complex) -> float:
    """The real polynomial printed as ``view`` ("x2y1": coefficient of x^2 y) at x + i y."""
    total = 0.0
    for name, c in view.coefficients.items():
        match = re.fullmatch(r"x(\d+)y(\d+)", name)
        assert match is not None
        i, j = map(int, match.groups())
        total += float(c) * z.real**i * z.imag**j
    return total


def combined(*weighted: tuple[Fraction, cf.PolyView]) -> dict[str, Fraction]:
    """The coefficients of sum w_k p_k for printed polynomials p_k (zero terms dropped)."""
    out: dict[str, Fraction] = {}
    for w, view in weighted:
        for name, c in view.coefficients.items():
            out[name] = out.get(name, Fraction(0)) + w * c
    return {k: c for k, c in out.items() if c != 0}


# --- exact polynomials and their printed form ------------------------------------------------


@given(xy_polynomials(), gaussian_integers())
@example(ONES, (2, 1))
def test_a_polynomial_in_z_and_zstar_keeps_its_values_in_x_and_y(
    terms: XyTerms, point: tuple[int, int]
) -> None:
    """A polynomial in z, z* rewritten in x, y (z = x + i y, z* = x - i y, (10.31)) has at the
    real point (x, y) the value it has at z = x + i y, z* = x - i y."""
    zs = Laurent.from_powers(("z", cf.ZSTAR), {k: gaussian(c) for k, c in terms.items()})
    x, y = point
    z, zstar = Gaussian(x, y), Gaussian(x, -y)
    assert cf.zpoly_to_xy(zs).evaluate({"x": x, "y": y}) == zs.evaluate({"z": z, cf.ZSTAR: zstar})


@given(xy_polynomials(), st.integers(1, 12))
@example({(i, j): (0, 0) for i in range(3) for j in range(3)}, 1)  # the zero polynomial
def test_a_printed_polynomial_is_over_its_least_common_denominator(terms: XyTerms, q: int) -> None:
    """The book prints a real polynomial over the least common denominator of its
    coefficients, (3x^2 + y^2)/2 (10.35), (10.54): numerator/denominator gives back each
    coefficient, no integer above 1 divides the denominator and all numerators (the zero
    polynomial is 0/1), and only a real polynomial has such a form."""
    p = xy_poly(terms)
    view = cf.poly_view(p.real_part() * Fraction(1, q))
    back = {k: Fraction(n, view.denominator) for k, n in view.numerators.items()}
    assert back == view.coefficients
    assert math.gcd(view.denominator, *view.numerators.values()) == 1
    assert view.size == max((abs(c) for c in view.coefficients.values()), default=0)
    both = cf.complex_view(p * Fraction(1, q))
    assert both.denominator == math.lcm(both.real.denominator, both.imag.denominator)
    if not p.imag_part().is_zero():
        with pytest.raises(ValueError, match="real coefficients"):
            cf.poly_view(p)


# --- (10.31)-(10.32): the z- and z*-derivatives ---------------------------------------------


@given(xy_polynomials())
def test_z_derivatives_follow_the_chain_rule_and_hold_div_and_curl(terms: XyTerms) -> None:
    """df/dz = (1/2)(df/dx - i df/dy) and df/dz* = (1/2)(df/dx + i df/dy) for every polynomial
    f(x, y) (10.31), the model's factors coming from inverting z = x + iy, z* = x - iy; and
    for f = Fx + i Fy, df/dz = (1/2) div F + (i/2) curl F (10.32)."""
    f = xy_poly(terms)
    assert cf.d_dz(f) == (f.diff("x") - f.diff("y") * I_UNIT) * HALF
    assert cf.d_dzstar(f) == (f.diff("x") + f.diff("y") * I_UNIT) * HALF
    fx, fy = f.real_part(), f.imag_part()
    df = cf.d_dz(f)
    assert df.real_part() == cf.divergence(fx, fy) * HALF
    assert df.imag_part() == cf.curl_z(fx, fy) * HALF


@given(analytic_polynomials())
def test_analytic_potentials_obey_cauchy_riemann(terms: dict[int, tuple[int, int]]) -> None:
    """A potential phi = Phi + iA analytic in z has dphi/dz* = 0 and d/dz the ordinary
    derivative (10.31)-(10.33); dPhi/dx = dA/dy and dPhi/dy = -dA/dx, so F = grad Phi = curl A
    (10.35b-c), and the level curves of Phi and A cross at right angles (grad Phi . grad A = 0)."""
    phi = z_poly(terms)
    assert cf.d_dzstar(phi).is_zero()
    derivative = {k - 1: (re * k, im * k) for k, (re, im) in terms.items() if k}
    assert cf.d_dz(phi) == z_poly(derivative)
    big_phi, a = phi.real_part(), phi.imag_part()
    assert big_phi.diff("x") == a.diff("y")
    assert big_phi.diff("y") == -a.diff("x")
    assert cf.gradient(big_phi) == cf.curl_of_z_vector(a)
    gx, gy = cf.gradient(big_phi)
    ax, ay = cf.gradient(a)
    assert (gx * ax + gy * ay).is_zero()


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


@given(gaussian_integers(), off_origin_points())
def test_the_laminar_field_has_no_divergence_and_no_curl(a: tuple[int, int], z: complex) -> None:
    """f(z) = a z plotted as f*(z*) = a* z* has df*/dz = 0, div F = 0 and curl F = 0 (10.32),
    Fig. 10.7, for every complex a; its printed components are the plotted vector
    F = (Re f*, Im f*) at every point, F = (x, -y) for the book's f(z) = z (Fig. 10.7)."""
    field = cf.conjugate_linear_field(*a)
    assert field.dfstar_dz_size == field.divergence_size == field.curl_size == 0
    fx, fy = cf.plot_field(lambda w: complex(*a) * w, z)
    tol = 1e-12 * (1 + abs(complex(*a))) * abs(z)
    assert_close(view_at(field.field_x, z), fx, rel=0, abs=tol)
    assert_close(view_at(field.field_y, z), fy, rel=0, abs=tol)
    unit = cf.conjugate_linear_field()
    assert (unit.field_x.coefficients, unit.field_y.coefficients) == (
        {"x1y0": Fraction(1)},
        {"x0y1": Fraction(-1)},
    )


@given(small_fractions())
def test_factor_pairs_of_the_potentials_sum_to_one(f: Fraction) -> None:
    """F = f grad Phi + j curl A for an analytic potential exactly when f + j = 1 (10.34)."""
    pair = cf.complementary_potential_factor(f)
    assert pair.j == 1 - f
    assert pair.total == 1 == cf.potential_factor_sum()


@given(NONNEGATIVE_POWERS, gaussian_integers())
def test_the_power_potential_gives_its_field(n: int, a: tuple[int, int]) -> None:
    """phi = a z^(n+1)/(n+1): grad Phi = curl A = F, the plotted field of f = a z^n (10.35)."""
    if a == (0, 0):
        a = (1, 0)
    p = cf.power_field_potential(n, *a)
    assert (p.grad_x, p.grad_y) == (p.field_x, p.field_y) == (p.curl_x, p.curl_y)


@given(NONNEGATIVE_POWERS, gaussian_integers(), off_origin_points())
def test_the_power_potential_is_linear_in_the_strength_and_plots_its_field(
    n: int, a: tuple[int, int], z: complex
) -> None:
    """phi = a z^(n+1)/(n+1) is linear in the complex strength: Phi_a + i A_a = a (Phi_1 + i A_1)
    with the unit potential of z^n, phi = z^2/2 with Phi = (x^2 - y^2)/2 and A = xy for the
    field z of Fig. 10.7; at every point Phi and A are Re phi and Im phi, and the printed field
    is the plotted F = (Re f*, Im f*) of f = a z^n (10.35)."""
    re_a, im_a = Fraction(a[0]), Fraction(a[1])
    unit, p = cf.power_field_potential(n), cf.power_field_potential(n, *a)
    assert p.phi.coefficients == combined((re_a, unit.phi), (-im_a, unit.a))
    assert p.a.coefficients == combined((im_a, unit.phi), (re_a, unit.a))
    if n == 1:
        assert unit.phi.coefficients == {"x0y2": -HALF, "x2y0": HALF}
        assert unit.a.coefficients == {"x1y1": 1}
    strength = complex(*a)
    tol = 1e-12 * (1 + abs(strength)) * (1 + 2 * abs(z)) ** (n + 1)
    big_phi, big_a = cf.potential_parts(lambda w: strength * w ** (n + 1) / (n + 1), z)
    assert_close(big_phi, view_at(p.phi, z), rel=0, abs=tol)
    assert_close(big_a, view_at(p.a, z), rel=0, abs=tol)
    fx, fy = cf.plot_field(lambda w: strength * w**n, z)
    assert_close(fx, view_at(p.field_x, z), rel=0, abs=tol)
    assert_close(fy, view_at(p.field_y, z), rel=0, abs=tol)


# --- power rule, multipoles ------------------------------------------------------------------


@pytest.mark.parametrize("n", [n for n in range(-8, 9) if n != -1])
def test_the_power_potential_differentiates_back_to_its_field(n: int) -> None:
    """d/dz [z^(n+1)/(n+1)] = z^n for every n but -1 (10.35a), (10.44)."""
    anti = cf.power_antiderivative(n)
    back = cf.laurent_derivative(anti.coefficient, anti.power)
    assert (back.coefficient, back.power) == (Fraction(1), n)


@given(st.integers(-8, 6), st.integers(-8, 6))
@example(-1, -1)
@example(-8, -2)
@example(-1, 6)  # the scan's whole range
def test_only_z_to_the_minus_one_lacks_a_power_potential(first: int, second: int) -> None:
    """In every range of powers the logarithmic case n = -1 is the one exception to the power
    rule (10.38), and the one power whose loop integral around the origin is not zero (10.39):
    the 2^0-pole, m = n + 1 = 0 (10.44); a range without it has neither."""
    lowest, highest = sorted((first, second))
    assert cf.exceptional_power(-20, 20) == -1
    if lowest <= -1 <= highest:
        assert cf.exceptional_power(lowest, highest) == -1
        loop = cf.nonzero_loop_powers(lowest, highest)
        assert (loop.powers, loop.field_power, loop.m) == ((-1,), -1, 0)
        return
    with pytest.raises(ArithmeticError, match="found"):
        cf.exceptional_power(lowest, highest)
    with pytest.raises(ArithmeticError, match="found"):
        cf.nonzero_loop_powers(lowest, highest)


@pytest.mark.parametrize(("lowest", "highest"), [(-9, 0), (-2, 7)])
def test_the_loop_scan_stays_where_its_rule_is_exact(lowest: int, highest: int) -> None:
    """The 16-node rule (checked on 8 nodes) integrates z^n exactly only for |n + 1| < 8
    (10.39): a scan of the loop integrals beyond that is refused."""
    with pytest.raises(ValueError, match="scan range"):
        cf.nonzero_loop_powers(lowest, highest)


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


# --- contour integrals (10.39), (10.44), (10.45) ----------------------------------------------


@given(
    laurent_terms().map(lambda ts: [t for t in ts if t[2] >= 0] or [(1.0, 0.0, 0)]), loop_circles()
)
def test_the_loop_integral_of_an_analytic_function_vanishes(
    terms: list[tuple[float, float, int]], circle: tuple[float, float, float]
) -> None:
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
@example([(7.0, -3.0, -1)], (0.0, 0.0, 2.0))
def test_a_pole_gives_its_residue(
    terms: list[tuple[float, float, int]], circle: tuple[float, float, float]
) -> None:
    """The loop integral of sum c_k z^k is 2 pi i c_-1 if the circle encloses the pole at the
    origin and zero if it does not (10.39), (10.44). The error estimate of the double-precision
    rule never claims more than double precision: it is at least eps |result|."""
    cx, cy, radius = circle
    loop = cf.laurent_loop_integral([list(t) for t in terms], cx, cy, radius)
    residue = sum(complex(re, im) for re, im, k in terms if k == -1)
    expected = 2j * math.pi * residue if abs(complex(cx, cy)) < radius else 0j
    got = complex(loop.real.value, loop.imag.value)
    size = max(abs(complex(re, im)) for re, im, _ in terms)
    reach = max(abs(complex(cx, cy)) + radius, 1 / max(abs(abs(complex(cx, cy)) - radius), 1e-3))
    tol = loop.real.error + 1e-12 * size * 2 * math.pi * radius * reach**4
    assert abs(got - expected) <= tol
    assert loop.real.error >= EPS * abs(got)


@pytest.mark.parametrize(
    ("centre", "allowed"), [(11.0, True), (10.95, False), (-9.0, True), (-9.1, False)]
)
def test_a_loop_may_pass_no_closer_to_the_pole_than_a_tenth_of_its_radius(
    centre: float, allowed: bool
) -> None:
    """A circle of radius 10 whose edge passes 1 = r/10 from the pole of 1/z is integrated (to
    zero outside, 2 pi i inside: (10.39)); one passing closer is refused."""
    if not allowed:
        with pytest.raises(ValueError, match="too close"):
            cf.laurent_loop_integral([[1, 0, -1]], centre, 0, 10)
        return
    loop = cf.laurent_loop_integral([[1, 0, -1]], centre, 0, 10)
    expected = 2j * math.pi if abs(centre) < 10 else 0j
    assert abs(complex(loop.real.value, loop.imag.value) - expected) <= loop.real.error + 1e-12


@pytest.mark.parametrize("n", range(-9, 8))
def test_only_the_monopole_term_has_a_loop_integral(n: int) -> None:
    """The loop integral of a (z - c)^n around c is 2 pi i a for n = -1 and zero otherwise
    (10.39), (10.45), at 30 digits; by default for the unit source on the unit circle. The
    error estimate is never below the working precision of the result. The rule on 16 nodes
    (and its check on 8) is exact only for |n + 1| < 8: other powers are refused."""
    if not -8 < n + 1 < 8:
        with pytest.raises(ValueError, match=r"power must be in \(-9, 7\)"):
            cf.power_loop_integral(n)
        return
    cases = ((1 + 0j, 0j, 1.0), (-2 + 3j, 0.5 - 1.5j, 0.25), (0.5j, -3 + 1j, 4.0))
    for a, centre, radius in (*cases, (300 - 400j, 0j, 2.0)):
        loop = cf.power_loop_integral(n, a.real, a.imag, centre.real, centre.imag, radius)
        expected = 2j * math.pi * a if n == -1 else 0j
        got = complex(loop.real.value, loop.imag.value)
        assert abs(got - expected) <= loop.real.error + 1e-14 * (1 + abs(a))
        assert loop.real.error >= 10.0**-cf.DIGITS * abs(got)
    unit = cf.power_loop_integral(n)
    got = complex(unit.real.value, unit.imag.value)
    assert abs(got - (2j * math.pi if n == -1 else 0j)) <= unit.real.error + 1e-14


@given(gaussian_integers())
def test_a_line_source_has_flux_2_pi_re_a_and_circulation_minus_2_pi_im_a(
    a: tuple[int, int],
) -> None:
    """Im loop f dz counts the real source (flux) and Re loop f dz the imaginary source
    (vorticity) of f = a/z (10.37)-(10.39), Figs. 10.9-10.10."""
    src = cf.line_source(*a)
    tol = src.flux.error + 1e-13 * (1 + abs(complex(float(a[0]), float(a[1]))))
    assert_close(src.flux.value, 2 * math.pi * float(a[0]), rel=0, abs=tol)
    assert_close(src.circulation.value, -2 * math.pi * float(a[1]), rel=0, abs=tol)
    assert (src.star_numerator_re, src.star_numerator_im) == (a[0], -a[1])
    unit = cf.line_source()  # the unit real source a = q = 1 of Fig. 10.9(a)
    assert_close(unit.flux.value, 2 * math.pi, rel=0, abs=unit.flux.error + 1e-13)
    assert_close(unit.circulation.value, 0, rel=0, abs=unit.circulation.error + 1e-13)


@pytest.mark.parametrize("index", range(-5, 6))
def test_contour_integration_recovers_every_laurent_coefficient(index: int) -> None:
    """a_n = (1/(2 pi i)) loop z^(-n-1) f(z) dz for every n of a test Laurent series (10.44)."""
    check = cf.laurent_coefficient_check(index)
    assert_close(check.two_pi.value, 2 * math.pi, rel=0, abs=check.two_pi.error + 1e-14)
    assert abs(check.residual.value) <= check.residual.error + 1e-14
    assert check.weight_power == -index - 1
    with pytest.raises(ValueError, match="index"):
        cf.laurent_coefficient_check(index + 11 if index < 0 else index - 11)


@pytest.mark.parametrize("order", range(7))
def test_cauchys_derivative_formula_holds_for_every_order(order: int) -> None:
    """f^(n)(a) = (n!/(2 pi i)) loop f(z)/(z - a)^(n+1) dz (10.45), and the kernel power n + 1
    is the only one that works."""
    d = cf.cauchy_derivative(order)
    assert_close(d.two_pi.value, 2 * math.pi, rel=0, abs=d.two_pi.error + 1e-14)
    # the integral is 2 pi/|b - a|^(n+1) while the integrand reaches r^-n/(|b - a| + r) on the
    # circle |z - a| = r: at DIGITS digits, that cancellation bounds the relative precision
    distance, r = abs(cauchy._CAUCHY_POLE - cauchy._CAUCHY_CENTER), cauchy._CAUCHY_RADIUS
    floor = 10.0**-cf.DIGITS * (distance / r) ** order * distance / (distance + r)
    for part, size in ((d.two_pi, 2 * math.pi), (d.numerator, math.factorial(order))):
        assert part.error >= floor * size
    assert_close(d.numerator.value, math.factorial(order), rel=0, abs=d.numerator.error + 1e-12)
    assert_close(d.taylor_numerator.value, 1.0, rel=0, abs=d.taylor_numerator.error + 1e-14)
    assert cf.cauchy_kernel(order).power == order + 1


# --- stereographic projection (Fig. 10.15) ---------------------------------------------------


@given(sphere_angles(off_equator=True), sphere_diameters())
def test_the_stereographic_map_inverts_radii_through_half_angles(
    theta: float, diameter: float
) -> None:
    """The centre O is halfway up the sphere (radius D/2, exact for an exact D);
    |z| |w| = D^2 (w = 1/z on the unit-diameter sphere), |z| = D tan(theta/2), and the image
    of |z| through the sphere is |w|; the angles at the poles, the chords SP = D cos(theta/2),
    NP = D sin(theta/2) and the depths D sin^2(theta/2), D cos^2(theta/2) all use the half
    angle (Fig. 10.15). The poles (theta = 0, pi) and the equator (|z| = |w|) have no such
    construction."""
    p = cf.stereographic_projection(theta, diameter)
    for pole_or_equator in (0.0, math.pi / 2, math.pi):
        with pytest.raises(ValueError, match="theta"):
            cf.stereographic_projection(pole_or_equator, diameter)
    assert p.radius == diameter / 2
    assert cf.stereographic_projection(theta, Fraction(diameter)).radius == Fraction(diameter) / 2
    assert_close(p.z_radius * p.w_radius, diameter**2, rel=0, abs=1e-9 * diameter**2)
    assert_close(p.z_radius, diameter * math.tan(theta / 2), rel=0, abs=1e-9 * max(1, p.z_radius))
    image = cf.stereographic_image_radius(p.z_radius, diameter)
    assert_close(image, p.w_radius, rel=0, abs=1e-9 * max(1, p.w_radius))
    for divisor in (
        p.tan_angle_divisor,
        p.cot_angle_divisor,
        p.south_chord_angle_divisor,
        p.north_chord_angle_divisor,
        p.north_depth_angle_divisor,
        p.south_height_angle_divisor,
    ):
        assert_close(divisor, 2, rel=0, abs=1e-6)
    assert_close(p.north_depth_exponent, 2, rel=0, abs=1e-6)
    assert_close(p.south_height_exponent, 2, rel=0, abs=1e-6)


# --- non-analytic fields (10.46)-(10.56) -----------------------------------------------------


@given(gaussian_integers(), NONNEGATIVE_POWERS)
def test_sources_and_potentials_rebuild_the_non_analytic_field(k: tuple[int, int], n: int) -> None:
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
    fstar = cf.zpoly_to_xy(Laurent.term(complex(*k).conjugate(), z=n))
    assert field.total_x == cf.poly_view(fstar.real_part())
    assert field.total_y == cf.poly_view(fstar.imag_part())


def test_the_definition_factors_make_rho_the_divergence() -> None:
    """s* = 2 df*/dz and f* = 2 dphi*/dz* (10.46)-(10.47): both factors are 2, and phi takes
    the prefactor 1/2."""
    factors = cf.source_field_factors()
    assert (factors.source, factors.potential, factors.potential_prefactor) == (
        Fraction(2),
        Fraction(2),
        HALF,
    )


# --- formulas at a point (the models of the formula claims) ----------------------------------

ANGLES = st.floats(min_value=-3.1, max_value=3.1)
RADII = st.floats(min_value=0.1, max_value=10)
COEFFICIENTS = st.floats(min_value=-5, max_value=5, allow_nan=False)


def z_derivative(func: Callable[[complex], complex], z: complex) -> tuple[complex, complex]:
    """Central differences of func along x and along i y (equal for an analytic function)."""
    h = 1e-6 * abs(z)
    along_x = (func(z + h) - func(z - h)) / (2 * h)
    along_y = (func(z + 1j * h) - func(z - 1j * h)) / (2j * h)
    return along_x, along_y


@given(RADII, ANGLES, RADII, ANGLES)
def test_phasor_sums_obey_the_parallelogram_law(
    r1: float, phi1: float, r2: float, phi2: float
) -> None:
    """|z + z'|^2 + |z - z'|^2 = 2(|z|^2 + |z'|^2) for the diagonals of the parallelogram of
    z = r e^(i phi) and z' (Fig. 10.6); each is the squared length of the sum, symmetric in z
    and z' and unchanged when both rotate together (10.25)."""
    total = cf.phasor_pair_square(r1, phi1, r2, phi2, 1)
    diff = cf.phasor_pair_square(r1, phi1, r2, phi2, -1)
    scale = (r1 + r2) ** 2
    assert_close(total + diff, 2 * (r1 * r1 + r2 * r2), rel=0, abs=1e-12 * scale)
    assert total >= -1e-12 * scale
    assert diff >= -1e-12 * scale
    z1, z2 = cmath.rect(r1, phi1), cmath.rect(r2, phi2)
    assert_close(total, abs(z1 + z2) ** 2, rel=0, abs=1e-12 * scale)
    assert_close(total, cf.phasor_pair_square(r2, phi2, r1, phi1, 1), rel=0, abs=1e-12 * scale)
    assert_close(
        diff, cf.phasor_pair_square(r1, phi1 + 0.7, r2, phi2 + 0.7, -1), rel=0, abs=1e-12 * scale
    )
    with pytest.raises(ValueError, match="sign"):
        cf.phasor_pair_square(r1, phi1, r2, phi2, 2)


@given(field_powers(), gaussian_integers(), off_origin_points())
def test_power_potentials_differentiate_to_their_fields(
    n: int, a: tuple[int, int], z: complex
) -> None:
    """The potential of f = a z^n has dphi/dz = f along x and along y (10.33a): a z^(n+1)/(n+1),
    and a ln z for n = -1 (10.38); Phi and A are its real and imaginary parts and the plotted
    vector is f* (10.33b); the polar form gives the same point (Figs. 10.9-10.14)."""
    if a == (0, 0):
        a = (1, 0)
    p = cf.power_field_at(n, z.real, z.imag, *a)
    assert p.field == complex(*a) * z**n
    assert p.plotted == p.field.conjugate()
    assert (p.phi, p.a) == (p.potential.real, p.potential.imag)

    def potential(w: complex) -> complex:
        return cf.power_field_at(n, w.real, w.imag, *a).potential

    scale = abs(p.field) + abs(p.potential) / abs(z)
    for derivative in z_derivative(potential, z):
        assert abs(derivative - p.field) <= 1e-5 * scale
    q = cf.power_field_polar(n, abs(z), cmath.phase(z), *a)
    assert abs(q.potential - p.potential) <= 1e-12 * (abs(p.potential) + 1)
    assert abs(q.field - p.field) <= 1e-12 * abs(p.field)
    with pytest.raises(ValueError, match="origin"):
        cf.power_field_at(n, 0, 0)


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


@given(st.lists(COEFFICIENTS, min_size=1, max_size=8), st.integers(-4, 1), off_origin_points())
def test_laurent_potentials_differentiate_to_their_series(
    coeffs: list[float], lowest: int, z: complex
) -> None:
    """The potential series of (10.44) differentiates term by term to the field series
    sum a_n z^n; with z replaced by w = 1/z it is the same series evaluated at w."""
    total = cf.laurent_potential_at(coeffs, lowest, z.real, z.imag)
    series = sum(c * z ** (lowest + j) for j, c in enumerate(coeffs))

    def potential(w: complex) -> complex:
        return cf.laurent_potential_at(coeffs, lowest, w.real, w.imag)

    scale = sum(abs(c) * abs(z) ** (lowest + j) for j, c in enumerate(coeffs))
    for derivative in z_derivative(potential, z):
        assert abs(derivative - series) <= 1e-5 * (scale + abs(total) / abs(z) + 1)
    w = 1 / z
    inverted = cf.inverted_laurent_potential_at(coeffs, lowest, z.real, z.imag)
    assert inverted == cf.laurent_potential_at(coeffs, lowest, w.real, w.imag)


@pytest.mark.parametrize("index", range(-5, 6))
def test_the_laurent_weight_is_z_to_minus_n_minus_one(index: int) -> None:
    """The loop integral (1/(2 pi i)) loop z^p f dz returns a_n for p = -n - 1 only (10.44)."""
    p = cf.laurent_weight_power(index)
    assert p == -index - 1
    z = complex(0.7, -0.4)
    assert cf.laurent_weight_at(index, z.real, z.imag) == z**p
    with pytest.raises(ValueError, match="index"):
        cf.laurent_weight_power(index + 11)


@given(st.lists(COEFFICIENTS, min_size=1, max_size=6), off_origin_points())
def test_a_polynomial_is_its_own_taylor_series(coeffs: list[float], z: complex) -> None:
    """f(z) = sum c_k z^k, k >= 0: f(0) = c_0 (the n = 0 term of (10.45c)) and f'(0) = c_1."""
    f = cf.analytic_polynomial_at(coeffs, z.real, z.imag)
    assert abs(f - sum(c * z**k for k, c in enumerate(coeffs))) <= 1e-9 * (1 + abs(f))
    assert cf.analytic_polynomial_at(coeffs, 0, 0) == coeffs[0]
    h = 1e-6
    slope = cf.analytic_polynomial_at(coeffs, h, 0) - cf.analytic_polynomial_at(coeffs, -h, 0)
    c1 = coeffs[1] if len(coeffs) > 1 else 0.0
    assert abs(slope / (2 * h) - c1) <= 1e-6 * (1 + sum(map(abs, coeffs)))


@given(gaussian_integers(), NONNEGATIVE_POWERS, off_origin_points())
def test_non_analytic_fields_at_a_point_are_their_polynomials(
    k: tuple[int, int], n: int, z: complex
) -> None:
    """At every point the sources, potentials and fields of f = k (z*)^n are the values of the
    printed polynomials (10.51)-(10.56); fL* + fT* = f* = k* z^n, and s* = 2 df*/dz is twice
    (1/2)(d/dx - i d/dy) of f* by central differences (10.46a)."""
    if k == (0, 0):
        k = (1, 0)
    field = cf.conjugate_power_field(*k, n)
    at = cf.conjugate_power_field_at(*k, n, z.real, z.imag)
    size = (1 + abs(complex(*k))) * (1 + abs(z)) ** (n + 1)
    for value, view in ((at.rho, field.rho), (at.phi, field.phi), (at.a, field.a)):
        assert_close(value, view_at(view, z), rel=0, abs=1e-9 * size)
    lx = view_at(field.longitudinal_x, z) + 1j * view_at(field.longitudinal_y, z)
    assert abs(at.longitudinal - lx) <= 1e-9 * size
    fstar = complex(*k).conjugate() * z**n
    assert abs(at.field_star - fstar) <= 1e-9 * size
    assert abs(at.longitudinal + at.transverse - fstar) <= 1e-9 * size
    h = 1e-5

    def star(w: complex) -> complex:
        return cf.conjugate_power_field_at(*k, n, w.real, w.imag).field_star

    d_dx = (star(z + h) - star(z - h)) / (2 * h)
    d_dy = (star(z + 1j * h) - star(z - 1j * h)) / (2 * h)
    assert abs(at.source_star - (d_dx - 1j * d_dy)) <= 1e-6 * size


@given(sphere_angles(), sphere_diameters(), RADII)
def test_stereographic_lengths_obey_thales_and_invert_radii(
    theta: float, diameter: float, rho: float
) -> None:
    """The angle NPS is right (Thales): SP^2 + NP^2 = D^2, the depth of P below N is NP^2/D and
    its height above S is SP^2/D; |z| |w| = D^2, |z| = D tan(NSP) with the inscribed angle NSP
    half the central angle (Fig. 10.15); the image of a z-radius through the sphere and back is
    that radius."""
    s = cf.stereographic_lengths(theta, diameter)
    d2 = diameter * diameter
    assert_close(s.south_chord**2 + s.north_chord**2, d2, rel=0, abs=1e-12 * d2)
    assert_close(s.north_depth * diameter, s.north_chord**2, rel=0, abs=1e-12 * d2)
    assert_close(s.south_height * diameter, s.south_chord**2, rel=0, abs=1e-12 * d2)
    assert_close(s.z_radius * s.w_radius, d2, rel=0, abs=1e-9 * d2)
    assert_close(
        s.z_radius, diameter * math.tan(s.south_angle), rel=0, abs=1e-9 * max(1, s.z_radius)
    )
    assert_close(2 * s.south_angle, theta, rel=0, abs=1e-12)
    back = cf.stereographic_preimage_radius(cf.stereographic_image_radius(rho, diameter), diameter)
    assert_close(back, rho, rel=0, abs=1e-9 * rho)
    with pytest.raises(ValueError, match="theta"):
        cf.stereographic_lengths(0.0, diameter)


@given(st.floats(min_value=-1e3, max_value=1e3), st.floats(min_value=-1e3, max_value=1e3))
def test_the_inverse_map_rebuilds_x_and_y_from_z_and_zstar(x: float, y: float) -> None:
    """x and y are recovered from z = x + iy and z* = x - iy through the inverse map (10.31)."""
    p = cf.coordinates_from_z(x, y)
    assert_close(p.x, x, rel=0, abs=1e-12 * (1 + abs(x) + abs(y)))
    assert_close(p.y, y, rel=0, abs=1e-12 * (1 + abs(x) + abs(y)))


@given(gaussian_integers(), gaussian_integers(), gaussian_integers())
def test_the_chain_rule_sees_z_and_zstar_apart(
    c: tuple[int, int], p: tuple[int, int], q: tuple[int, int]
) -> None:
    """For an analytic f (df/dy = i df/dx, Cauchy-Riemann) df/dz is df/dx and df/dz* = 0; for
    f = c z*, df/dz = 0 and df/dz* = c; both derivatives are linear in the partials (10.31).
    The conjugate potential phi* = Phi - iA of an analytic phi with dphi/dz = f has
    dphi*/dz* = f*, the plotted field (10.33b)."""
    fx = complex(*c)
    analytic = cf.chain_rule_derivatives(fx.real, fx.imag, (1j * fx).real, (1j * fx).imag)
    assert abs(analytic.dz - fx) <= 1e-12 * (1 + abs(fx))
    assert abs(analytic.dzstar) <= 1e-12 * (1 + abs(fx))
    anti = cf.chain_rule_derivatives(fx.real, fx.imag, (-1j * fx).real, (-1j * fx).imag)
    assert abs(anti.dz) <= 1e-12 * (1 + abs(fx))
    assert abs(anti.dzstar - fx) <= 1e-12 * (1 + abs(fx))
    a, b = cf.chain_rule_derivatives(*p, 0, 0), cf.chain_rule_derivatives(0, 0, *q)
    both = cf.chain_rule_derivatives(*p, *q)
    assert abs(both.dz - (a.dz + b.dz)) <= 1e-12 * (1 + abs(complex(*p)) + abs(complex(*q)))
    # phi analytic with phi' = f: Phi_x = Re f, Phi_y = -Im f, A_x = Im f, A_y = Re f
    star = cf.conjugate_potential_derivative(fx.real, -fx.imag, fx.imag, fx.real)
    assert abs(star - fx.conjugate()) <= 1e-12 * (1 + abs(fx))


@pytest.mark.parametrize("m", [m for m in range(-6, 7) if m])
def test_a_potential_term_belongs_to_a_two_to_the_abs_m_pole(m: int) -> None:
    """The potential term a_(m-1) z^m/m comes from the field term a_(m-1) z^(m-1): a 2^|m|-pole,
    at z = 0 for m < 0 and at infinity for m > 0 (10.44); m = 0 is the logarithm."""
    assert cf.potential_term_poles(m) == 2 ** abs(m)
    with pytest.raises(ValueError, match="ln z"):
        cf.potential_term_poles(0)
