"""Vector products, Levi-Civita symbols, determinants and triple products (Appendix 1.A).

The dot product A.B = AB cos(theta_B - theta_A) and the cross product
A x B = AB sin(theta_B - theta_A) of plane vectors (1.A.1), the Kronecker delta and the totally
antisymmetric Levi-Civita symbol epsilon_ijk (1.A.3), the products written with them (1.A.4),
determinants as Levi-Civita sums and by minors (1.A.5), the triple product (1.A.6), the
epsilon-delta identity (1.A.7) and the double cross product A x (B x C) = (A.C) B - (A.B) C.
Areas of parallelograms and triangles (Fig. 1.A.2) are computed independently of the cross
product, by Heron's formula, so that the book's |A x B| and 1/2 |A x B| can be checked.

The index-notation products are named for the symbols they are written with
(``kronecker_dot``, ``levi_civita_cross``, ``levi_civita_determinant``); the plain plane
products are ``mechmodel.planar.dot`` and ``cross``.

Plain operators throughout: ``int`` and ``Fraction`` components give exact results (Heron's
formula works with the squares of the sides, so areas of rational triangles stay exact where
they are rational); floats give floats. Indices are 1-based as in the book.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

import mpmath

from mechmodel import inputs
from mechmodel.exact import exact_sqrt
from mechmodel.planar import cross
from mechmodel.typing import Real

DIMENSIONS = 3


def _vector(v: Sequence[Real], name: str, size: int | None = None) -> list[Real]:
    out = [inputs.real(c, f"{name} component") for c in v]
    if size is not None and len(out) != size:
        raise ValueError(f"{name} must have {size} components, got {len(out)}")
    return out


def kronecker(i: int, j: int) -> int:
    """delta_ij = 1 if i = j else 0 (1.A.3a)."""
    return 1 if inputs.count(i, "i", 1) == inputs.count(j, "j", 1) else 0


def permutation_sign(indices: Sequence[int]) -> int:
    """Sign of a sequence of distinct indices as a permutation of its sorted order: +1 for an
    even number of inversions, -1 for an odd number, 0 if an index repeats."""
    idx = [inputs.count(i, "index", 1) for i in indices]
    if len(set(idx)) != len(idx):
        return 0
    inversions = sum(1 for a, b in itertools.combinations(idx, 2) if a > b)
    return -1 if inversions % 2 else 1


def levi_civita(*indices: int) -> int:
    """epsilon_{i j k ...} of N = len(indices) indices from 1..N (1.A.3a): +1 for an even
    permutation of (1 2 ... N), -1 for an odd one, 0 otherwise."""
    n = len(indices)
    if any(not 1 <= inputs.count(i, "index", 1) <= n for i in indices):
        return 0
    return permutation_sign(indices)


def kronecker_dot(a: Sequence[Real], b: Sequence[Real]) -> Real:
    """The dot product written with the Kronecker delta, A.B = delta_ij A_i B_j = sum_i A_i B_i
    (1.A.4a), in any dimension."""
    a, b = _vector(a, "A"), _vector(b, "B", len(a))
    return sum(kronecker(i + 1, j + 1) * a[i] * b[j] for i in range(len(a)) for j in range(len(b)))


def levi_civita_cross(a: Sequence[Real], b: Sequence[Real]) -> list[Real]:
    """The cross product written with the Levi-Civita symbol, (A x B)_k = epsilon_ijk A_i B_j
    (1.A.4b), three dimensions."""
    a, b = _vector(a, "A", DIMENSIONS), _vector(b, "B", DIMENSIONS)
    return [
        sum(
            levi_civita(i + 1, j + 1, k + 1) * a[i] * b[j]
            for i in range(DIMENSIONS)
            for j in range(DIMENSIONS)
        )
        for k in range(DIMENSIONS)
    ]


@dataclass(frozen=True)
class PolarProducts:
    """Dot and cross products of plane vectors given by lengths and angles (1.A.1)."""

    dot: float
    cross: float


def polar_products(length_a: Real, angle_a: Real, length_b: Real, angle_b: Real) -> PolarProducts:
    """A.B = AB cos(theta_B - theta_A) and A x B = AB sin(theta_B - theta_A) (1.A.1), the
    longitudinal and transverse projections of Fig. 1.A.1."""
    for x, name in ((length_a, "A"), (angle_a, "theta_A"), (length_b, "B"), (angle_b, "theta_B")):
        inputs.real(x, name)
    d = angle_b - angle_a
    return PolarProducts(
        dot=length_a * length_b * math.cos(d), cross=length_a * length_b * math.sin(d)
    )


@dataclass(frozen=True)
class RelativeComponents:
    """Components of each of two plane vectors on axes made of the other (Fig. 1.A.1b-c): on
    the unit vector along A and on its perpendicular copy A↵ (A turned a quarter turn
    counterclockwise), and likewise on B and B↵."""

    b_along_a: Real  # B_A, the A-longitudinal component of B
    b_across_a: Real  # B_A↵, the A-transverse component of B
    a_along_b: Real  # A_B, the B-longitudinal component of A
    a_across_b: Real  # A_B↵, the B-transverse component of A


def relative_components(
    length_a: Real, angle_a: Real, length_b: Real, angle_b: Real
) -> RelativeComponents:
    """The relative components of plane vectors A and B given by lengths and lab angles
    (Fig. 1.A.1): each vector's Cartesian components dotted with the unit vector of the other
    and with that unit vector turned counterclockwise by a quarter turn, (u_x, u_y) ->
    (-u_y, u_x). No angle differences are taken: the projections come from the components."""
    for x, name in ((length_a, "A"), (angle_a, "theta_A"), (length_b, "B"), (angle_b, "theta_B")):
        inputs.real(x, name)
    unit_a = [math.cos(angle_a), math.sin(angle_a)]
    unit_b = [math.cos(angle_b), math.sin(angle_b)]
    a = [length_a * c for c in unit_a]
    b = [length_b * c for c in unit_b]

    def turned(u: list[float]) -> list[float]:
        return [-u[1], u[0]]

    return RelativeComponents(
        b_along_a=kronecker_dot(b, unit_a),
        b_across_a=kronecker_dot(b, turned(unit_a)),
        a_along_b=kronecker_dot(a, unit_b),
        a_across_b=kronecker_dot(a, turned(unit_b)),
    )


def coriolis_acceleration(angular_speed: Real, speed: Real, angle: Real) -> float:
    """Magnitude of the Coriolis acceleration of a body moving at ``speed`` v, at ``angle``
    theta to the rotation axis, in a frame turning at ``angular_speed`` omega (line 16508).

    Computed from the motion, not from a formula: a free body crossing the axis moves on the
    straight line X(t) = v t of an inertial frame; its position in the rotating frame is that
    line turned back by the angle omega t about the axis, and its apparent acceleration is the
    second time derivative of that position at t = 0 (mpmath.diff). On the axis the
    centrifugal acceleration vanishes, so what remains is the Coriolis acceleration alone.
    """
    inputs.real(angular_speed, "angular_speed")
    inputs.real(speed, "speed")
    inputs.real(angle, "angle")
    w, v, th = (mpmath.mpf(x) for x in (angular_speed, speed, angle))
    across, along = v * mpmath.sin(th), v * mpmath.cos(th)

    def seen(t: mpmath.mpf, k: int) -> mpmath.mpf:
        x, y, z = across * t, 0 * t, along * t  # the inertial path through the axis
        c, s = mpmath.cos(w * t), mpmath.sin(w * t)
        return (c * x + s * y, -s * x + c * y, z)[k]

    acceleration = [mpmath.diff(lambda t, k=k: seen(t, k), 0, 2) for k in range(DIMENSIONS)]
    return float(mpmath.sqrt(sum(a * a for a in acceleration)))


def levi_civita_determinant(matrix: Sequence[Sequence[Real]]) -> Real:
    """det U = sum epsilon_{i j k ...} U_1i U_2j U_3k ... over all index tuples (1.A.5)."""
    rows = [list(r) for r in matrix]
    n = len(rows)
    if any(len(r) != n for r in rows):
        raise ValueError("a determinant needs a square matrix")
    total: Real = 0
    for perm in itertools.permutations(range(1, n + 1)):
        term: Real = levi_civita(*perm)
        for row, col in enumerate(perm):
            term = term * inputs.real(rows[row][col - 1], "matrix entry")
        total = total + term
    return total


def determinant_by_minors(matrix: Sequence[Sequence[Real]]) -> Real:
    """det U expanded by minors of the first row, U11 M11 - U12 M12 + U13 M13 ... (1.A.5)."""
    rows = [list(r) for r in matrix]
    n = len(rows)
    if any(len(r) != n for r in rows):
        raise ValueError("a determinant needs a square matrix")
    if n == 1:
        return inputs.real(rows[0][0], "matrix entry")
    total: Real = 0
    for col in range(n):
        minor = [r[:col] + r[col + 1 :] for r in rows[1:]]
        total = total + (-1) ** col * rows[0][col] * determinant_by_minors(minor)
    return total


def triple_product(a: Sequence[Real], b: Sequence[Real], c: Sequence[Real]) -> Real:
    """A . (B x C) = epsilon_ijk A_i B_j C_k (1.A.6a), the signed volume of the parallelepiped
    of A, B and C."""
    a, b, c = (_vector(v, n, DIMENSIONS) for v, n in ((a, "A"), (b, "B"), (c, "C")))
    return sum(
        levi_civita(i + 1, j + 1, k + 1) * a[i] * b[j] * c[k]
        for i in range(DIMENSIONS)
        for j in range(DIMENSIONS)
        for k in range(DIMENSIONS)
    )


def double_cross(a: Sequence[Real], b: Sequence[Real], c: Sequence[Real]) -> list[Real]:
    """A x (B x C) computed as two cross products (the left side of the identity after
    (1.A.7))."""
    return levi_civita_cross(a, levi_civita_cross(b, c))


def bac_cab(a: Sequence[Real], b: Sequence[Real], c: Sequence[Real]) -> list[Real]:
    """(A.C) B - (A.B) C, the right side of the double-cross identity after (1.A.7)."""
    ac, ab = kronecker_dot(a, c), kronecker_dot(a, b)
    return [ac * bi - ab * ci for bi, ci in zip(b, c, strict=True)]


def epsilon_contraction(i: int, j: int, m: int, n: int) -> int:
    """sum_k epsilon_ijk epsilon_mnk over k = 1..3 (the left side of (1.A.7))."""
    return sum(levi_civita(i, j, k) * levi_civita(m, n, k) for k in range(1, DIMENSIONS + 1))


def delta_expansion(i: int, j: int, m: int, n: int) -> int:
    """delta_im delta_jn - delta_in delta_jm (the right side of (1.A.7))."""
    return kronecker(i, m) * kronecker(j, n) - kronecker(i, n) * kronecker(j, m)


def heron_area_squared(a: Sequence[Real], b: Sequence[Real], c: Sequence[Real]) -> Real:
    """Squared area of the triangle with vertices a, b, c by Heron's formula in the squared
    side lengths: 16 Area^2 = 4 x y - (x + y - z)^2 for squared sides x, y, z. Exact for
    rational coordinates."""
    pa, pb, pc = (_vector(v, "vertex") for v in (a, b, c))

    def sq(u: list[Real], w: list[Real]) -> Real:
        return sum((ui - wi) ** 2 for ui, wi in zip(u, w, strict=True))

    x, y, z = sq(pa, pb), sq(pb, pc), sq(pc, pa)
    numerator = 4 * x * y - (x + y - z) ** 2
    if isinstance(numerator, int | Fraction):
        return Fraction(numerator) / 16
    return numerator / 16


def triangle_area(p: Sequence[Real], q: Sequence[Real], r: Sequence[Real]) -> float:
    """Area of the plane triangle with vertices p, q, r, by Heron's formula (the square root
    of ``heron_area_squared``); it knows nothing of bases, altitudes or cross products."""
    return math.sqrt(max(0.0, float(heron_area_squared(p, q, r))))


def sum_triangle_area(length_a: Real, length_b: Real, angle: Real) -> float:
    """Area of the sum triangle (0, A, A + B) of Fig. 1.A.2c for vectors of lengths A and B at
    ``angle`` theta from A to B, by Heron's formula from its vertices (A along the x-axis)."""
    for x, name in ((length_a, "A"), (length_b, "B"), (angle, "theta")):
        inputs.real(x, name)
    tip = [length_a + length_b * math.cos(angle), length_b * math.sin(angle)]
    return triangle_area([0.0, 0.0], [length_a, 0.0], tip)


@dataclass(frozen=True)
class AreaRatios:
    """Areas of the figures of Fig. 1.A.2 in units of |A x B|."""

    parallelogram: Real
    sum_triangle: Real
    difference_triangle: Real


def area_ratios(a: Sequence[Real], b: Sequence[Real]) -> AreaRatios:
    """The parallelogram of A and B and the triangles (0, A, A+B) and (0, A, A-B) of
    Fig. 1.A.2, their areas by Heron's formula divided by the plane cross product |A x B|:
    1, 1/2 and 1/2. Exact for rational components (the squared ratio is a rational square)."""
    a, b = _vector(a, "A", 2), _vector(b, "B", 2)
    cross_ab = cross(a, b)
    if isinstance(cross_ab, int):
        cross_ab = Fraction(cross_ab)
    if cross_ab == 0:
        raise ValueError("A and B are parallel: the figures have no area")
    origin = [0 * a[0], 0 * a[1]]
    tip_sum = [a[0] + b[0], a[1] + b[1]]
    tip_diff = [a[0] - b[0], a[1] - b[1]]
    parallelogram_sq = 4 * heron_area_squared(origin, a, tip_sum)  # two congruent triangles
    return AreaRatios(
        parallelogram=exact_sqrt(parallelogram_sq / cross_ab**2),
        sum_triangle=exact_sqrt(heron_area_squared(origin, a, tip_sum) / cross_ab**2),
        difference_triangle=exact_sqrt(heron_area_squared(origin, a, tip_diff) / cross_ab**2),
    )
