"""Laws of the vector-product models (mechmodel.vectors): Appendix 1.A.

Exact (Fraction and int) inputs must give exact equalities; float forms are compared within
1e-12 of the sum of the magnitudes involved.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import assume, example, given
from hypothesis import strategies as st

from checks.properties.strategies import (
    exact_plane_vectors,
    exact_square_matrices,
    exact_vectors3,
    levi_civita_index_quads,
)
from mechmodel import planar, vectors

pytestmark = pytest.mark.properties
F = Fraction
# generic exact vectors: every component distinct and nonzero, so a wrong product shows at once
V3 = tuple[Fraction, Fraction, Fraction]
A3, B3, C3 = (F(1), F(2), F(3)), (F(-2), F(1, 2), F(4)), (F(3), F(-1), F(1, 3))


@given(levi_civita_index_quads())
@example((1, 2, 1, 2))
@example((1, 2, 2, 1))
@example((2, 3, 2, 3))  # the sum needs its k = 1 term
def test_levi_civita_identity(quad: tuple[int, int, int, int]) -> None:
    """sum_k eps_ijk eps_mnk = delta_im delta_jn - delta_in delta_jm (1.A.7)."""
    assert vectors.epsilon_contraction(*quad) == vectors.delta_expansion(*quad)


@given(st.permutations([1, 2, 3]), st.integers(0, 2), st.integers(0, 2))
def test_levi_civita_changes_sign_under_a_swap(perm: list[int], a: int, b: int) -> None:
    """Swapping two indices of eps_ijk changes its sign; eps_123 = +1, and a repeated index
    or one outside 1..3 gives 0 (1.A.3a)."""
    assert vectors.levi_civita(1, 2, 3) == 1
    outside = list(perm)
    outside[a] = 4
    assert vectors.levi_civita(*outside) == 0
    swapped = list(perm)
    swapped[a], swapped[b] = swapped[b], swapped[a]
    expected = vectors.levi_civita(*perm) * (1 if a == b else -1)
    assert vectors.levi_civita(*swapped) == expected
    assert vectors.levi_civita(perm[0], perm[0], perm[1]) == 0


@given(exact_vectors3(), exact_vectors3(), exact_vectors3())
@example(A3, B3, C3)
def test_triple_product_is_the_determinant_and_cyclic(a: V3, b: V3, c: V3) -> None:
    """A . (B x C) = det [A; B; C] = eps_ijk A_i B_j C_k (1.A.6), unchanged by a cyclic
    shift and reversed by a swap."""
    t = vectors.triple_product(a, b, c)
    assert t == vectors.kronecker_dot(a, vectors.levi_civita_cross(b, c))
    assert (
        t == vectors.levi_civita_determinant([a, b, c]) == vectors.determinant_by_minors([a, b, c])
    )
    assert t == vectors.triple_product(b, c, a) == -vectors.triple_product(b, a, c)


@given(exact_vectors3(), exact_vectors3(), exact_vectors3())
@example(A3, B3, C3)
def test_double_cross_expansion(a: V3, b: V3, c: V3) -> None:
    """A x (B x C) = (A . C) B - (A . B) C, the first application of (1.A.7)."""
    assert vectors.double_cross(a, b, c) == vectors.bac_cab(a, b, c)


@given(exact_vectors3(), exact_vectors3())
@example(A3, B3)
def test_cross_product_is_antisymmetric_and_normal(a: V3, b: V3) -> None:
    """A x B = -B x A (anti-reflexive), it is perpendicular to both A and B, and
    |A x B|^2 + (A . B)^2 = |A|^2 |B|^2 (sine and cosine of one angle, (1.A.1))."""
    dot, ab = vectors.kronecker_dot, vectors.levi_civita_cross(a, b)
    assert ab == [-x for x in vectors.levi_civita_cross(b, a)]
    assert dot(a, ab) == 0 == dot(b, ab)
    assert dot(ab, ab) + dot(a, b) ** 2 == dot(a, a) * dot(b, b)


@given(exact_square_matrices())
def test_levi_civita_determinant_equals_minor_expansion(matrix: list[list[int]]) -> None:
    """det U as a Levi-Civita sum equals its expansion by minors (1.A.5) and numpy's value."""
    det = vectors.levi_civita_determinant(matrix)
    assert det == vectors.determinant_by_minors(matrix)
    assert abs(det - float(np.linalg.det(np.array(matrix, float)))) <= 1e-9 * (1 + abs(float(det)))


@given(
    st.floats(min_value=0.01, max_value=100),
    st.floats(min_value=-7, max_value=7),
    st.floats(min_value=0.01, max_value=100),
    st.floats(min_value=-7, max_value=7),
)
def test_polar_products_equal_component_products(
    la: float, ta: float, lb: float, tb: float
) -> None:
    """A . B = AB cos(theta_B - theta_A) = Ax Bx + Ay By and
    A x B = AB sin(theta_B - theta_A) = Ax By - Ay Bx (1.A.1a-b)."""
    a = (la * math.cos(ta), la * math.sin(ta))
    b = (lb * math.cos(tb), lb * math.sin(tb))
    p = vectors.polar_products(la, ta, lb, tb)
    scale = 1e-12 * (1 + la * lb) * 10
    assert abs(p.dot - vectors.kronecker_dot(a, b)) <= scale
    assert abs(p.cross - planar.cross(a, b)) <= scale


@given(exact_plane_vectors(), exact_plane_vectors())
@example((Fraction(1), Fraction(0)), (Fraction(0), Fraction(1)))  # unit square, A_y = 0
@example((Fraction(3), Fraction(1)), (Fraction(1), Fraction(2)))  # the catalogue's sample pair
def test_triangles_are_half_the_cross_product(
    a: tuple[Fraction, Fraction], b: tuple[Fraction, Fraction]
) -> None:
    """By Heron's formula the parallelogram of A and B has area |A x B| and the A+B and A-B
    triangles half of it (Fig. 1.A.2), exactly (rational ratios stay Fractions); parallel
    vectors span no figure."""
    assume(planar.cross(a, b) != 0)
    r = vectors.area_ratios(a, b)
    assert r.parallelogram == 1
    assert r.sum_triangle == Fraction(1, 2) == r.difference_triangle
    assert all(type(x) is Fraction for x in (r.parallelogram, r.sum_triangle))
    assert type(r.difference_triangle) is Fraction
    with pytest.raises(ValueError, match="parallel"):
        vectors.area_ratios(a, [2 * a[0], 2 * a[1]])


@given(exact_plane_vectors(), exact_plane_vectors(), exact_plane_vectors(), exact_plane_vectors())
def test_heron_area_is_half_the_cross_product_anywhere(
    a: tuple[Fraction, Fraction],
    b: tuple[Fraction, Fraction],
    c: tuple[Fraction, Fraction],
    shift: tuple[Fraction, Fraction],
) -> None:
    """Heron's formula in the squared sides gives the area of any triangle P, Q, R as
    1/2 |(Q - P) x (R - P)| (Fig. 1.A.2): unchanged when the triangle is moved, exact for
    rational vertices and within rounding for float ones."""
    cross = planar.cross([b[0] - a[0], b[1] - a[1]], [c[0] - a[0], c[1] - a[1]])
    area_sq = vectors.heron_area_squared(a, b, c)
    assert area_sq == cross**2 / 4
    moved = [[p[0] + shift[0], p[1] + shift[1]] for p in (a, b, c)]
    assert vectors.heron_area_squared(*moved) == area_sq
    as_float = vectors.heron_area_squared(*([float(x) for x in p] for p in (a, b, c)))
    sides = max(abs(float(x)) for p in (a, b, c) for x in p) ** 4
    assert abs(as_float - float(area_sq)) <= 1e-12 * (1 + sides)


@given(
    st.floats(min_value=0.01, max_value=100),
    st.floats(min_value=-7, max_value=7),
    st.floats(min_value=0.01, max_value=100),
    st.floats(min_value=-7, max_value=7),
)
@example(1.0, 0.0, 1.0, math.pi / 2)  # B a quarter turn ahead of A: B_A↵ = B, A_B↵ = -A
def test_relative_components_give_the_products(la: float, ta: float, lb: float, tb: float) -> None:
    """On axes made of the other vector (Fig. 1.A.1b-c) each vector keeps its length, the
    longitudinal components give A . B = A B_A = B A_B, and the transverse ones give
    A x B = A B_A↵ = -B A_B↵: cross products are anti-reflexive (A x B = -B x A)."""
    a = (la * math.cos(ta), la * math.sin(ta))
    b = (lb * math.cos(tb), lb * math.sin(tb))
    c = vectors.relative_components(la, ta, lb, tb)
    scale = 1e-12 * (1 + la * lb) * 10
    assert abs(c.b_along_a**2 + c.b_across_a**2 - lb**2) <= scale * (1 + lb / la)
    assert abs(c.a_along_b**2 + c.a_across_b**2 - la**2) <= scale * (1 + la / lb)
    assert abs(la * c.b_along_a - vectors.kronecker_dot(a, b)) <= scale
    assert abs(lb * c.a_along_b - vectors.kronecker_dot(a, b)) <= scale
    assert abs(la * c.b_across_a - planar.cross(a, b)) <= scale
    assert abs(lb * c.a_across_b + planar.cross(a, b)) <= scale


@given(
    st.floats(min_value=0.01, max_value=100),
    st.floats(min_value=0.01, max_value=100),
    st.floats(min_value=0, max_value=math.pi),
)
@example(1.0, 1.0, math.pi / 2)
@example(1.0, 1.0, 0.0)  # along the axis: no Coriolis acceleration
def test_coriolis_acceleration_is_twice_omega_cross_v(w: float, v: float, theta: float) -> None:
    """The apparent acceleration of a free body crossing the rotation axis is the Coriolis
    acceleration -2 omega x v (no centrifugal part on the axis): its magnitude is
    |2 omega x v| for omega along z and v at angle theta to it (line 16508)."""
    omega = [0.0, 0.0, w]
    vel = [v * math.sin(theta), 0.0, v * math.cos(theta)]
    expected = 2 * math.sqrt(sum(x * x for x in vectors.levi_civita_cross(omega, vel)))
    got = vectors.coriolis_acceleration(w, v, theta)
    assert abs(got - expected) <= 1e-12 * (1 + 2 * w * v)


@given(
    st.floats(min_value=0.1, max_value=10),
    st.floats(min_value=0.1, max_value=10),
    st.floats(min_value=0.1, max_value=3.0),
    st.floats(min_value=-5, max_value=5),
)
def test_triangle_areas_by_heron(la: float, lb: float, theta: float, shear: float) -> None:
    """Heron's formula from the vertices gives the sum triangle (0, A, A+B) of Fig. 1.A.2 half
    the cross product |A x B|, and any triangle half its base times its altitude, wherever
    its apex lies along the line parallel to the base."""
    a = (la, 0.0)
    b = (lb * math.cos(theta), lb * math.sin(theta))
    half_cross = abs(planar.cross(a, b)) / 2
    assert abs(vectors.sum_triangle_area(la, lb, theta) - half_cross) <= 1e-9 * (la + lb) ** 2
    base, height = la, lb * math.sin(theta)
    area = vectors.triangle_area([0.0, 0.0], [base, 0.0], [shear, height])
    assert abs(area - base * height / 2) <= 1e-9 * (base + height + abs(shear)) ** 2
