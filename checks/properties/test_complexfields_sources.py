"""Laws of non-analytic fields and their sources (mechmodel.complexfields.sources): chapter
10, (10.46)-(10.56).

The printed sources, potentials and fields of f = k (z*)^n are exact polynomials (Gaussian
rationals); at a point they are compared within 1e-9 of the magnitudes involved.

Shared helpers of the complexfields modules are in ``_complexfields_helpers``.
"""

from __future__ import annotations

import pytest
from hypothesis import given

from checks.properties._complexfields_helpers import NONNEGATIVE_POWERS, view_at
from checks.properties.closeness import assert_close
from checks.properties.strategies import gaussian_integers, off_origin_points
from mechmodel import complexfields as cf
from mechmodel.algebra import Laurent

pytestmark = pytest.mark.properties


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


# --- formulas at a point (the models of the formula claims) -----------------------------------


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
