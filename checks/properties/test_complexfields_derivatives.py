"""Laws of z- and z*-derivatives (mechmodel.complexfields.derivatives): chapter 10,
(10.25), (10.31)-(10.34).

Polynomial algebra is exact (Gaussian rationals), so its laws hold with equality: the
polynomials in z, z* and in x, y, their printed form, d/dz, d/dz*, div and curl, the laminar
field (Fig. 10.7). Float geometry (phasors, the chain rule at a point) is compared within
1e-12 of the magnitudes involved.

Shared helpers of the complexfields modules are in ``_complexfields_helpers``.
"""

from __future__ import annotations

import cmath
import math
from fractions import Fraction

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from checks.properties._complexfields_helpers import HALF, RADII, view_at
from checks.properties.closeness import assert_close
from checks.properties.strategies import (
    analytic_polynomials,
    gaussian_integers,
    off_origin_points,
    xy_polynomials,
)
from mechmodel import complexfields as cf
from mechmodel.algebra import I_UNIT, Gaussian, Laurent

pytestmark = pytest.mark.properties
XyTerms = dict[tuple[int, int], tuple[int, int]]  # {(i, j): (re, im)}: (re + i im) x^i y^j
ONES = {(i, j): (1, 1) for i in range(3) for j in range(3)}  # every term (1 + i) x^i y^j
ANGLES = st.floats(min_value=-3.1, max_value=3.1)


def gaussian(parts: tuple[int, int]) -> Gaussian:
    return Gaussian(Fraction(parts[0]), Fraction(parts[1]))


def xy_poly(terms: dict[tuple[int, int], tuple[int, int]]) -> Laurent:
    return Laurent.from_powers(("x", "y"), {k: gaussian(c) for k, c in terms.items()})


def z_poly(terms: dict[int, tuple[int, int]]) -> Laurent:
    """An analytic polynomial sum c_k z^k written in x, y."""
    zs: dict[tuple[int, ...], Gaussian] = {(k, 0): gaussian(c) for k, c in terms.items()}
    return cf.zpoly_to_xy(Laurent.from_powers(("z", cf.ZSTAR), zs))


# --- exact polynomials and their printed form -------------------------------------------------


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


# --- (10.31)-(10.32): the z- and z*-derivatives -----------------------------------------------


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


# --- formulas at a point (the models of the formula claims) -----------------------------------


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
