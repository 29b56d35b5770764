"""Laws of the plane vectors and 2 x 2 matrices (mechmodel.planar): chapters 5 and 11, App. 1.A.

Rational entries are compared exactly; rotations within 1e-12 of the magnitudes involved.
"""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import pytest
from hypothesis import assume, example, given
from hypothesis import strategies as st

from checks.properties.closeness import assert_close, largest
from checks.properties.strategies import (
    exact_plane_vectors,
    matrix_powers,
    mirror_angles,
    plane_points,
    small_fractions,
)
from mechmodel import planar
from mechmodel.planar import Matrix, Vector

pytestmark = pytest.mark.properties


def exact_matrices() -> st.SearchStrategy[tuple[tuple[Fraction, Fraction], ...]]:
    row = st.tuples(small_fractions(), small_fractions())
    return st.tuples(row, row)


@given(exact_matrices(), exact_matrices(), exact_matrices(), exact_plane_vectors())
def test_products_associate_and_act_as_composition(
    a: Matrix[Fraction], b: Matrix[Fraction], c: Matrix[Fraction], v: Vector[Fraction]
) -> None:
    """(A B) C = A (B C), (A B) v = A (B v): B acts first, then A (5.2b); the unit matrix
    changes nothing; det(A B) = det A det B (p. 5.18), exactly."""
    ab = planar.matrix_product(a, b)
    assert planar.matrix_product(ab, c) == planar.matrix_product(a, planar.matrix_product(b, c))
    assert planar.apply(ab, v) == planar.apply(a, planar.apply(b, v))
    assert planar.matrix_product(planar.UNIT, a) == planar.as_matrix(a)
    assert planar.determinant(ab) == planar.determinant(a) * planar.determinant(b)
    columns = planar.from_columns(planar.apply(a, (1, 0)), planar.apply(a, (0, 1)))
    assert columns == planar.as_matrix(a)


@given(exact_matrices(), matrix_powers(), matrix_powers())
def test_powers_add_their_exponents(a: Matrix[Fraction], m: int, n: int) -> None:
    """A^m A^n = A^(m+n) for any integers, negative powers through A^-1 (5.4), (11.13);
    A^-1 A = 1. A singular matrix has no inverse."""
    if planar.determinant(a) == 0:
        with pytest.raises(ValueError, match="singular"):
            planar.matrix_inverse(a)
        assume(m >= 0 and n >= 0)
    else:
        assert planar.matrix_product(planar.matrix_inverse(a), a) == planar.UNIT
    product = planar.matrix_product(planar.matrix_power(a, m), planar.matrix_power(a, n))
    assert product == planar.matrix_power(a, m + n)
    assert planar.matrix_power(a, 0) == planar.UNIT


@given(mirror_angles(), mirror_angles(), plane_points(), plane_points())
@example(math.pi / 2, 0.0, (1.0, 0.0), (0.0, 1.0))
def test_rotations_compose_and_keep_dot_and_cross(
    a: float, b: float, u: Vector[float], v: Vector[float]
) -> None:
    """R(a) R(b) = R(a + b) with det R = +1 (5.17a): a rotation keeps the dot and the cross
    product of two vectors, their lengths and the angle between them ((1.A.1), (10.27))."""
    composed = planar.matrix_product(planar.rotation(a), planar.rotation(b))
    turned = planar.rotation(a + b)
    assert_close(composed, turned, scale=1.0 + largest(composed, turned))
    assert_close(planar.determinant(planar.rotation(a)), 1.0, scale=1.0)
    ru, rv = planar.apply(planar.rotation(a), u), planar.apply(planar.rotation(a), v)
    size = math.hypot(*u) * math.hypot(*v)
    assert_close(planar.dot(ru, rv), planar.dot(u, v), scale=4 * size)
    assert_close(planar.cross(ru, rv), planar.cross(u, v), scale=4 * size)


@given(exact_plane_vectors(), exact_plane_vectors())
def test_dot_and_cross_are_the_cosine_and_sine_parts(
    u: Vector[Fraction], v: Vector[Fraction]
) -> None:
    """u x v = -v x u, u x u = 0, and (u.v)^2 + (u x v)^2 = |u|^2 |v|^2: the AB cos and AB sin
    of one angle (1.A.1), exactly."""
    assert planar.cross(u, v) == -planar.cross(v, u)
    assert planar.cross(u, u) == 0
    lengths = planar.dot(u, u) * planar.dot(v, v)
    assert planar.dot(u, v) ** 2 + planar.cross(u, v) ** 2 == lengths


@given(st.integers(min_value=1, max_value=10**5), st.integers(min_value=1, max_value=10**5))
@example(2, 1)  # the 3-4-5 triangle
def test_the_hypotenuse_is_exact_for_pythagorean_triples(m: int, n: int) -> None:
    """Euclid's triples (m^2 - n^2, 2mn, m^2 + n^2) have an integer hypotenuse, returned as an
    int (line 1585, Fig. 5.2(f)); scaled by a rational it stays exact; otherwise it is the
    length hypot(a, b), in mpmath's precision for mpmath legs."""
    m, n = max(m, n) + 1, min(m, n)
    a, b = m * m - n * n, 2 * m * n
    assert planar.hypotenuse(a, b) == m * m + n * n
    assert planar.hypotenuse(Fraction(a, 7), Fraction(b, 7)) == Fraction(m * m + n * n, 7)
    assert_close(planar.hypotenuse(float(a), 1.5), math.hypot(a, 1.5))
    with mpmath.workdps(40):
        exact = planar.hypotenuse(mpmath.mpf(a), mpmath.mpf(1) / 3)
        assert abs(exact - mpmath.hypot(a, mpmath.mpf(1) / 3)) < mpmath.mpf(10) ** -30 * exact


def test_a_matrix_is_two_by_two() -> None:
    with pytest.raises(ValueError, match="2 x 2"):
        planar.as_matrix(((1, 2, 3), (4, 5, 6)))
    with pytest.raises(ValueError, match="integer"):
        planar.matrix_power(planar.UNIT, 1.5)  # type: ignore[call-overload]  # on purpose
