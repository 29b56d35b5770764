"""Plane vectors and 2 x 2 matrices: the linear algebra of the velocity plane.

The book works in planes throughout: the (V1, V2) plane of two colliding bodies and its bang
matrices (chapter 5, (5.1)-(5.18)), the orbit plane of the 2-D oscillator and its quadratic
forms (chapter 11, (11.7)-(11.20)), the plane products of Appendix 1.A ((1.A.1)). This module
holds their shared algebra once; the topic modules import it.

A vector is a pair (x, y); a matrix is a tuple of rows ``((a, b), (c, d))`` (a list of lists is
accepted). Both are generic in their entries: ``Vector[Fraction]``, ``Matrix[Symbolic]``; a
bare ``Vector`` leaves the entries open. Formulas use plain operators, so ``int`` and
``Fraction`` entries stay exact and sympy symbols give expressions; only ``rotation`` (a
cosine) and the square root of ``hypotenuse`` leave exact arithmetic.
Units are those of the entries.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from fractions import Fraction
from typing import TypeAlias, TypeVar, overload

from mechmodel import inputs
from mechmodel.exact import exact_sqrt
from mechmodel.typing import Real, Scalar, Symbolic

T = TypeVar("T")  # an entry: a number, a sympy symbol, anything the caller computes with
Vector: TypeAlias = tuple[T, T]
Matrix: TypeAlias = tuple[tuple[T, T], tuple[T, T]]
UNIT: Matrix[int] = ((1, 0), (0, 1))


def as_matrix(a: Sequence[Sequence[T]]) -> Matrix[T]:
    """A 2 x 2 matrix as a tuple of rows; ``ValueError`` for any other shape."""
    if len(a) != 2 or any(len(row) != 2 for row in a):
        raise ValueError("a matrix here is 2 x 2: two rows of two entries")
    return ((a[0][0], a[0][1]), (a[1][0], a[1][1]))


def from_columns(first: Sequence[T], second: Sequence[T]) -> Matrix[T]:
    """The matrix whose columns are the images of the unit vectors (1, 0) and (0, 1)."""
    return ((first[0], second[0]), (first[1], second[1]))


# -- vectors ----------------------------------------------------------------------------------
# Products are written with plain operators: real entries give a real number, sympy symbols an
# expression (``Symbolic``).
@overload
def dot(u: Sequence[float], v: Sequence[float]) -> float: ...
@overload
def dot(u: Sequence[Real], v: Sequence[Real]) -> Real: ...
@overload
def dot(u: Sequence[Symbolic], v: Sequence[Symbolic]) -> Symbolic: ...
def dot(u: Sequence[Symbolic], v: Sequence[Symbolic]) -> Symbolic:
    """The dot product u.v = u_x v_x + u_y v_y of two plane vectors ((1.A.1a), (11.8b))."""
    return u[0] * v[0] + u[1] * v[1]


@overload
def cross(u: Sequence[float], v: Sequence[float]) -> float: ...
@overload
def cross(u: Sequence[Real], v: Sequence[Real]) -> Real: ...
@overload
def cross(u: Sequence[Symbolic], v: Sequence[Symbolic]) -> Symbolic: ...
def cross(u: Sequence[Symbolic], v: Sequence[Symbolic]) -> Symbolic:
    """The scalar cross product u_x v_y - u_y v_x of two plane vectors: the z component of
    u x v ((1.A.1b); r x v = a b w of the oscillator orbit, (11.21))."""
    return u[0] * v[1] - u[1] * v[0]


def hypotenuse(altitude: Real, base: Real) -> Real:
    """Hypotenuse r = sqrt(a^2 + b^2) of the right triangle with legs a and b: the length of
    the plane vector (b, a) (Pythagoras, line 1387; the 3-4-5 triangles of lines 1585-1587
    and of Fig. 5.2(f)). An ``int`` or ``Fraction`` where the sum of squares is a rational
    square, an mpmath number for mpmath legs, else a float."""
    inputs.real(altitude, "altitude")
    inputs.real(base, "base")
    square = altitude**2 + base**2
    if type(square).__module__.startswith("mpmath"):
        import mpmath

        return mpmath.sqrt(square)
    return exact_sqrt(square)


# -- matrices ---------------------------------------------------------------------------------
@overload
def apply(a: Sequence[Sequence[float]], v: Sequence[float]) -> Vector[float]: ...
@overload
def apply(a: Sequence[Sequence[Real]], v: Sequence[Real]) -> Vector[Real]: ...
@overload
def apply(a: Sequence[Sequence[Symbolic]], v: Sequence[Symbolic]) -> Vector[Symbolic]: ...
def apply(a: Sequence[Sequence[Symbolic]], v: Sequence[Symbolic]) -> Vector[Symbolic]:
    """The vector A v: the matrix acting on the column vector v (5.2a)."""
    m = as_matrix(a)
    return (m[0][0] * v[0] + m[0][1] * v[1], m[1][0] * v[0] + m[1][1] * v[1])


@overload
def matrix_product(a: Sequence[Sequence[float]], b: Sequence[Sequence[float]]) -> Matrix[float]: ...
@overload
def matrix_product(a: Sequence[Sequence[Real]], b: Sequence[Sequence[Real]]) -> Matrix[Real]: ...
# complex entries (the Pauli and quaternion units of p. 5.15); real ones match the overload above,
# so the overlap mypy reports with the symbolic one below is never reached
@overload
def matrix_product(  # type: ignore[overload-overlap]
    a: Sequence[Sequence[Scalar]], b: Sequence[Sequence[Scalar]]
) -> Matrix[Scalar]: ...
@overload
def matrix_product(
    a: Sequence[Sequence[Symbolic]], b: Sequence[Sequence[Symbolic]]
) -> Matrix[Symbolic]: ...
def matrix_product(
    a: Sequence[Sequence[Scalar | Symbolic]], b: Sequence[Sequence[Scalar | Symbolic]]
) -> Matrix[Scalar | Symbolic]:
    """The product A B: B acts first, then A (5.2b): row-by-column sums."""
    p, q = as_matrix(a), as_matrix(b)
    return (
        (p[0][0] * q[0][0] + p[0][1] * q[1][0], p[0][0] * q[0][1] + p[0][1] * q[1][1]),
        (p[1][0] * q[0][0] + p[1][1] * q[1][0], p[1][0] * q[0][1] + p[1][1] * q[1][1]),
    )


@overload
def determinant(a: Sequence[Sequence[float]]) -> float: ...
@overload
def determinant(a: Sequence[Sequence[Real]]) -> Real: ...
@overload
def determinant(a: Sequence[Sequence[Symbolic]]) -> Symbolic: ...
def determinant(a: Sequence[Sequence[Symbolic]]) -> Symbolic:
    """det A = a d - b c: +1 for a rotation, -1 for a reflection (p. 5.18)."""
    m = as_matrix(a)
    return m[0][0] * m[1][1] - m[0][1] * m[1][0]


@overload
def matrix_inverse(a: Sequence[Sequence[Real]]) -> Matrix[Real]: ...
@overload
def matrix_inverse(a: Sequence[Sequence[Symbolic]]) -> Matrix[Symbolic]: ...
def matrix_inverse(a: Sequence[Sequence[Symbolic]]) -> Matrix[Symbolic]:
    """A^-1 = ((d, -b), (-c, a)) / det A; exact for exact entries (an ``int`` determinant is
    made a ``Fraction``). ``ValueError`` for a singular matrix."""
    a = as_matrix(a)
    det = determinant(a)
    if det == 0:
        raise ValueError("a singular matrix has no inverse")
    if isinstance(det, int):
        det = Fraction(det)
    return ((a[1][1] / det, -a[0][1] / det), (-a[1][0] / det, a[0][0] / det))


@overload
def matrix_power(a: Sequence[Sequence[Real]], n: int) -> Matrix[Real]: ...
@overload
def matrix_power(a: Sequence[Sequence[Symbolic]], n: int) -> Matrix[Symbolic]: ...
def matrix_power(a: Sequence[Sequence[Symbolic]], n: int) -> Matrix[Symbolic]:
    """A^n for any integer n: n bangs of the same kind in a row (5.4), the powers R^n of the
    slope operator (11.12)-(11.13); A^0 is the unit matrix, a negative power that of A^-1."""
    n = inputs.integer(n, "n")
    base = matrix_inverse(a) if n < 0 else as_matrix(a)
    out: Matrix[Symbolic] = UNIT
    for _ in range(abs(n)):
        out = matrix_product(base, out)
    return out


def rotation(angle: Real) -> Matrix[float]:
    """R(phi) = ((cos, -sin), (sin, cos)): the right-handed (counterclockwise) turn by
    ``angle`` radians ((5.17a); the rotated forms of exercise 1.11.1(a); (10.27c))."""
    inputs.real(angle, "angle")
    c, s = math.cos(angle), math.sin(angle)
    return ((c, -s), (s, c))
