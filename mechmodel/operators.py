"""Bangs as matrices: collision, ceiling and floor operators, reflections and rotations (ch. 5).

A state of two balls is the column (v1, v2). An elastic bang between them is the matrix M of
(5.1b), a ceiling bounce of ball 2 is C and a floor bounce of ball 1 is F (5.3)-(5.4); each is
built here by applying the bang itself (``mechmodel.collisions.collide`` and the bounces of
``mechmodel.bangs``) to the unit vectors, not copied from the book. In mass-scaled velocities
V = (sqrt(m1) v1, sqrt(m2) v2) (5.6) the energy ellipse is a circle, M is a reflection and the
double bang C M a rotation by the bang angle theta (5.10)-(5.13). Sections (5.15)-(5.18) name
the reflections sigma_A, sigma_B, sigma_phi and their products.

A matrix is a tuple of rows ``((a, b), (c, d))``; a list of lists is accepted too. Their algebra
(products, powers, determinants, rotations) is ``mechmodel.planar``. Rational inputs (int,
Fraction) keep matrices built from bangs exact; square roots and angles are floats.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TypeAlias

from mechmodel import inputs
from mechmodel.bangs import ceiling_bounce, floor_bounce
from mechmodel.collisions import collide
from mechmodel.exact import exact_sqrt, magnitude
from mechmodel.planar import (
    Matrix,
    as_matrix,
    determinant,
    from_columns,
    matrix_power,
    matrix_product,
    rotation,
)
from mechmodel.planar import hypotenuse as hypotenuse  # the catalog's operators.hypotenuse
from mechmodel.typing import Matrix as RealRows
from mechmodel.typing import Real, Scalar, Symbolic, not_monotonic

# A matrix given as rows (tuples or lists): complex entries for sigma_y and the quaternion units
# (5.15); a real one is ``RealRows``.
Rows: TypeAlias = Sequence[Sequence[Scalar]]


# -- multiples of the unit matrix (p. 5.15) ---------------------------------------------------
def scalar_of_identity(a: Rows) -> Scalar:
    """The number s where A = s times the unit matrix; ``ValueError`` if A is not one."""
    m = as_matrix(a)
    s = m[0][0]
    scale = max(magnitude(x) for row in m for x in row) or 1
    tol = 1e-12 * scale if isinstance(s, float | complex) else 0
    if magnitude(m[0][1]) > tol or magnitude(m[1][0]) > tol or magnitude(m[1][1] - s) > tol:
        raise ValueError("the matrix is not a multiple of the unit matrix")
    if isinstance(s, complex) and abs(s.imag) <= tol:
        return s.real
    return s


def square_scalar(a: Rows) -> Scalar:
    """The number s with A A = s (a unit that squares to +1 or -1, p. 5.15)."""
    return scalar_of_identity(matrix_product(a, a))


# -- the bang operators (5.1)-(5.4) ----------------------------------------------------------
def collision_matrix(m1: Symbolic, m2: Symbolic) -> Matrix:
    """The elastic bang M of (5.1b): (1/M)((m1 - m2, 2 m2), (2 m1, m2 - m1)), M = m1 + m2.

    Its columns are the bangs of the unit states (1, 0) and (0, 1) (collisions.collide is
    linear in the velocities). Exact for rational masses.
    """
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    return from_columns(collide(m1, m2, 1, 0).after, collide(m1, m2, 0, 1).after)


def ceiling_matrix() -> Matrix:
    """The ceiling bounce C of (5.3): (v1, v2) -> (v1, -v2), from the bounce itself."""
    return from_columns((1, ceiling_bounce(0)), (0, ceiling_bounce(1)))


def floor_matrix() -> Matrix:
    """The floor bounce F of (5.4): (v1, v2) -> (-v1, v2), from the bounce itself."""
    return from_columns((floor_bounce(1), 0), (floor_bounce(0), 1))


def double_bang_matrix(m1: Real, m2: Real, n: int = 1) -> Matrix:
    """(C M)^n: n double bangs, a ball bang then a ceiling bang each (5.3), in velocities v."""
    return matrix_power(matrix_product(ceiling_matrix(), collision_matrix(m1, m2)), n)


# -- mass-scaled velocities (5.6)-(5.13) -------------------------------------------------------
def mass_scaling(m1: Real, m2: Real) -> Matrix:
    """S = diag(sqrt(m1), sqrt(m2)): V = S v turns the energy ellipse into a circle (5.6)."""
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    return ((math.sqrt(m1), 0), (0, math.sqrt(m2)))


def mass_scaled(a: RealRows, m1: Real, m2: Real) -> Matrix:
    """The operator A in mass-scaled velocities: S A S^-1 (5.7)-(5.9)."""
    s = mass_scaling(m1, m2)
    inverse = ((1 / s[0][0], 0), (0, 1 / s[1][1]))
    return matrix_product(s, matrix_product(a, inverse))


def scaled_collision_matrix(m1: Real, m2: Real) -> Matrix:
    """The bang in V space (5.9): rows ((m1 - m2)/M, 2 sqrt(m1 m2)/M) and
    (2 sqrt(m1 m2)/M, (m2 - m1)/M): a reflection."""
    return mass_scaled(collision_matrix(m1, m2), m1, m2)


def scaled_double_bang_matrix(m1: Real, m2: Real, n: int = 1) -> Matrix:
    """(C M)^n in V space: the rotation by -n theta of (5.12)-(5.13a)."""
    return mass_scaled(double_bang_matrix(m1, m2, n), m1, m2)


@dataclass(frozen=True)
class BangAngle:
    """The bang angle theta: cos = (m1 - m2)/M, sin = 2 sqrt(m1 m2)/M (5.10)-(5.11)."""

    cos: Real
    sin: Real
    angle: float

    @property
    def pythagorean_sum(self) -> Real:
        """cos^2 + sin^2, which is 1 (5.10a)."""
        return self.cos**2 + self.sin**2


def bang_angle(m1: Real, m2: Real) -> BangAngle:
    """The bang angle (radians, in (0, pi)) read off the V-space bang matrix (5.9)-(5.11)."""
    m = scaled_collision_matrix(m1, m2)
    return BangAngle(m[0][0], m[0][1], math.atan2(m[0][1], m[0][0]))


def multiple_bang_angle(m1: Real, m2: Real, n: int) -> float:
    """N theta: the angle n double bangs turn the V-space clock hand through (5.13)."""
    return inputs.count(n, "n") * bang_angle(m1, m2).angle


@dataclass(frozen=True)
class MassScaledForm:
    """(C M)^n in velocities v written as (cos, a sin; b sin, cos) of the angle n theta (5.13b)."""

    cos: Real
    sin: Real
    upper: Real
    lower: Real


def mass_scaled_form(m1: Real, m2: Real, n: int = 1) -> MassScaledForm:
    """The factors a = sqrt(m2/m1) and b = -sqrt(m1/m2) of (5.13b), from the matrix power itself."""
    v = double_bang_matrix(m1, m2, n)
    big = scaled_double_bang_matrix(m1, m2, n)
    s = big[0][1]
    if s == 0:
        raise ValueError("sin(n theta) is zero: the form has no sine entries")
    return MassScaledForm(big[0][0], s, v[0][1] / s, v[1][0] / s)


@not_monotonic
def rotation_picture_bang_count(m1: Real, m2: Real) -> int:
    """Bangs after the floor bounce (v0, -v0) until none can occur, from the rotation picture.

    In V space the state starts at angle -beta (beta = theta/2, the collision line's angle).
    A ball bang reflects it across the collision line, a ceiling bang across the V1 axis: each
    double bang turns it by -theta (5.12). After n bangs no bang is possible once
    (n + 2) beta >= pi, so the count is the least such n (49:1 of Fig. 5.1: 21).
    """
    beta = bang_angle(m1, m2).angle / 2
    n = max(0, math.ceil(math.pi / beta) - 2)
    while (n + 2) * beta < math.pi:  # guard against rounding in the ceiling
        n += 1
    while n > 0 and (n + 1) * beta >= math.pi:
        n -= 1
    return n


# -- reflections, rotations and mirrors (5.15)-(5.18) -----------------------------------------
def sigma_a() -> Matrix:
    """sigma_A = ((1, 0), (0, -1)) = sigma_Z (5.15a): the mirror along the x axis."""
    return ((1, 0), (0, -1))


def sigma_b() -> Matrix:
    """sigma_B = ((0, 1), (1, 0)) = sigma_X (5.15b): the mirror along the line y = x."""
    return ((0, 1), (1, 0))


def reflection(phi: Real) -> Matrix:
    """sigma_phi = sigma_A cos(phi) + sigma_B sin(phi) (5.15c): a mirror at angle phi/2."""
    inputs.real(phi, "phi")
    c, s = math.cos(phi), math.sin(phi)
    a, b = sigma_a(), sigma_b()
    return tuple(tuple(a[i][j] * c + b[i][j] * s for j in range(2)) for i in range(2))  # type: ignore[return-value]


def rotation_angle(a: RealRows) -> float:
    """The angle (radians, in (-pi, pi]) of a rotation matrix; ``ValueError`` if det is not +1."""
    a = as_matrix(a)
    if magnitude(determinant(a) - 1) > 1e-9:
        raise ValueError("not a rotation: its determinant is not +1")
    return math.atan2(a[1][0], a[0][0])


def mirror_angle(a: RealRows) -> float:
    """The angle (radians) of the mirror line of a reflection matrix: phi/2 for sigma_phi.

    ``ValueError`` if the determinant is not -1.
    """
    a = as_matrix(a)
    if magnitude(determinant(a) + 1) > 1e-9:
        raise ValueError("not a reflection: its determinant is not -1")
    return math.atan2(a[0][1], a[0][0]) / 2


def negated(a: Rows) -> Matrix:
    """-A (the floor F = -sigma_A = -C of (5.15b))."""
    a = as_matrix(a)
    return ((-a[0][0], -a[0][1]), (-a[1][0], -a[1][1]))


def product_rotation_angle(second: RealRows, first: RealRows) -> float:
    """The rotation angle of ``second`` times ``first`` (first acts first): sigma_2 sigma_1."""
    return rotation_angle(matrix_product(second, first))


def angle_between_mirrors(first: RealRows, second: RealRows) -> float:
    """The angle (radians) from the mirror of ``first`` to that of ``second``, in (-pi/2, pi/2]."""
    d = mirror_angle(second) - mirror_angle(first)
    while d > math.pi / 2:
        d -= math.pi
    while d <= -math.pi / 2:
        d += math.pi
    return d


def mirror_pair_rotation(first_mirror: Real, second_mirror: Real) -> float:
    """The turn (radians) of two mirrors at angles ``first_mirror`` then ``second_mirror``.

    sigma_2 sigma_1 is a rotation by twice the angle from the first mirror to the second
    (Fig. 5.3d-e, the clothing-store mirrors of Fig. 5.4).
    """
    return product_rotation_angle(reflection(2 * second_mirror), reflection(2 * first_mirror))


def reflection_mirror_angle(phi: Real) -> float:
    """Tilt (radians) of the mirror line of sigma_phi = sigma_A cos(phi) + sigma_B sin(phi)
    (5.15c): the line the matrix leaves fixed, read off the matrix itself (Fig. 5.3c)."""
    return mirror_angle(reflection(phi))


def mirror_separation(turn: Real) -> float:
    """Angle (radians) between the mirrors of sigma_A and sigma_turn, whose product
    sigma_turn sigma_A is the rotation by ``turn`` (5.17a, Fig. 5.3d): measured from mirror to
    mirror, in (-pi/2, pi/2]."""
    return angle_between_mirrors(sigma_a(), reflection(turn))


def translation_mirror_separation(translation: Real) -> Real:
    """Distance between two parallel 1D mirrors whose product moves every point by
    ``translation`` (p. 5.17): the product of reflections is linear in their separation, so the
    separation is ``translation`` times separation per translation of any one pair."""
    inputs.real(translation, "translation")
    pair = mirror_pair_translation(0, 1)
    return translation * pair.separation / pair.translation


@dataclass(frozen=True)
class MirrorTranslation:
    """Two 1D mirrors at x = p1 then x = p2: the product is a translation (p. 5.17)."""

    translation: Real
    separation: Real

    @property
    def ratio(self) -> Real:
        """Translation over mirror separation: 2."""
        return self.translation / self.separation


def mirror_pair_translation(first_mirror: Real, second_mirror: Real) -> MirrorTranslation:
    """Reflect x -> 2 p1 - x, then x -> 2 p2 - x; the result moves every x by the same amount."""
    p1, p2 = inputs.real(first_mirror, "first_mirror"), inputs.real(second_mirror, "second_mirror")
    if p1 == p2:
        raise ValueError("the mirrors must be apart")
    x = 0
    moved = 2 * p2 - (2 * p1 - x)
    return MirrorTranslation(moved - x, p2 - p1)


def double_bang_rotation_angle(m1: Real, m2: Real, n: int = 1) -> float:
    """The turn (radians) of n double bangs in V space: -n theta, wrapped into (-pi, pi] (5.11)."""
    return rotation_angle(scaled_double_bang_matrix(m1, m2, n))


def rotation_determinant(angle: Real) -> Real:
    """det R(angle): +1 for every rotation (p. 5.18)."""
    return determinant(rotation(angle))


def reflection_determinant(phi: Real) -> Real:
    """det sigma_phi: -1 for every reflection (p. 5.18)."""
    return determinant(reflection(phi))


def reflection_square(phi: Real) -> Scalar:
    """sigma_phi squared, as a number: 1 (a reflection undoes itself, p. 5.16)."""
    return square_scalar(reflection(phi))


def mirror_pair_determinant(first_phi: Real, second_phi: Real) -> Real:
    """det(sigma_2 sigma_1) = (-1)(-1) = +1: two reflections make a rotation (p. 5.18)."""
    return determinant(matrix_product(reflection(second_phi), reflection(first_phi)))


# -- Pauli matrices and quaternion units (5.15) ------------------------------------------------
def pauli(axis: str) -> Matrix:
    """The Pauli matrix sigma_X (= sigma_B), sigma_Y or sigma_Z (= sigma_A) of (5.15)."""
    table = {
        "x": sigma_b(),
        "y": ((0, -1j), (1j, 0)),
        "z": sigma_a(),
    }
    try:
        return table[axis.lower()]
    except KeyError as err:
        raise ValueError(f"axis must be x, y or z, got {axis!r}") from err


def sigma(name: str) -> Matrix:
    """sigma_A, sigma_B, sigma_C (= sigma_Y) or sigma_0 (the unit matrix) of (5.15); a leading
    '-' negates it ('-A' is the floor bounce F of (5.15b))."""
    sign, key = (-1, name[1:]) if name.startswith("-") else (1, name)
    table = {"A": sigma_a(), "B": sigma_b(), "C": pauli("y"), "0": ((1, 0), (0, 1))}
    if key not in table:
        raise ValueError(f"sigma name must be A, B, C or 0 (with an optional '-'), got {name!r}")
    m = table[key]
    return m if sign == 1 else negated(m)


def sigma_product(left: str, right: str) -> Matrix:
    """The product sigma_left sigma_right (right acts first), as in (5.15c)-(5.15d)."""
    return matrix_product(sigma(left), sigma(right))


def sigma_rotation_angle(left: str, right: str) -> float:
    """The turn (radians) of sigma_left sigma_right: sigma_B sigma_A is +90 degrees (p. 5.17)."""
    return rotation_angle(sigma_product(left, right))


def sigma_mirror_angle(name: str) -> float:
    """The angle (radians) of the mirror line of sigma_A, sigma_B or their negatives (Fig. 5.3)."""
    return mirror_angle(sigma(name))


def sigma_mirror_separation(first: str, second: str) -> float:
    """The angle (radians) between the mirrors of two sigmas: 90 degrees for sigma_A, -sigma_A."""
    return angle_between_mirrors(sigma(first), sigma(second))


def quaternion_unit(unit: str) -> Matrix:
    """Hamilton's unit i, j or k as the 2 x 2 matrix -i sigma (sigma_Z = i k, sigma_X = i i)."""
    axes = {"i": "x", "j": "y", "k": "z"}
    if unit not in axes:
        raise ValueError(f"unit must be i, j or k, got {unit!r}")
    p = pauli(axes[unit])
    return tuple(tuple(-1j * x for x in row) for row in p)  # type: ignore[return-value]


def quaternion_square(unit: str) -> Scalar:
    """The square of Hamilton's unit i, j or k: -1 (p. 5.15)."""
    return square_scalar(quaternion_unit(unit))


def pauli_square(axis: str) -> Scalar:
    """The square of a Pauli matrix: +1 (p. 5.15)."""
    return square_scalar(pauli(axis))


def quaternion_common_square() -> Scalar:
    """The one square of Hamilton's i, j and k: i^2 = j^2 = k^2 = -1 (p. 5.15)."""
    squares = {quaternion_square(u) for u in "ijk"}
    if len(squares) != 1:
        raise ValueError(f"the units square to different numbers: {squares}")
    return squares.pop()


def pauli_common_square() -> Scalar:
    """The one square of the Pauli matrices: sigma_X^2 = sigma_Y^2 = sigma_Z^2 = +1 (p. 5.15)."""
    squares = {pauli_square(a) for a in "xyz"}
    if len(squares) != 1:
        raise ValueError(f"the Pauli matrices square to different numbers: {squares}")
    return squares.pop()


def imaginary_unit_square() -> Real:
    """The square of the imaginary unit i = sqrt(-1): -1."""
    i = complex(0, 1)
    return (i * i).real


# -- line geometry of the V-V and space-space plots (Fig. 4.2, 4.11, 4.12, 5.2) ----------------
def bang_line_slope(m1: Real, m2: Real) -> Real:
    """Slope of the line from IN to FIN of a ball bang in the (v1, v2) plane: -m1/m2.

    It is the momentum line of Fig. 3.1 and 4.4b and the line that bisects the incident and
    reflected paths off the 45-degree collision line (Fig. 4.12): computed from one bang.
    """
    hit = collide(m1, m2, 1, -1)
    return (hit.v2 - -1) / (hit.v1 - 1)


def bang_facet_slope(m1: Real, m2: Real) -> Real:
    """Slope of the mirror facet perpendicular to the bang line: m2/m1 (p. 4.12)."""
    return -1 / bang_line_slope(m1, m2)


def bang_line_angle(m1: Real, m2: Real) -> float:
    """Inclination (radians) of the bang line: -45 degrees for equal masses (p. 4.12)."""
    return math.atan(bang_line_slope(m1, m2))


def collision_line_angle() -> float:
    """Inclination (radians) of the collision line y2 = y1 (or v2 = v1) in its plane: 45 deg.

    Taken from two points where the balls are level, (0, 0) and (1, 1).
    """
    return math.atan2(1 - 0, 1 - 0)


def energy_line_inclination(energy: Real) -> float:
    """The acute angle (radians) of the line (V1)^2 + (V2)^2 = 2 KE with the axes of the
    (V1^2, V2^2) plot: the '45 degree line' of Fig. 5.2(e)."""
    inputs.positive(energy, "energy")
    ends = ((2 * energy, 0), (0, 2 * energy))
    slope = (ends[1][1] - ends[0][1]) / (ends[1][0] - ends[0][0])
    return math.atan(abs(slope))


# -- the clock's statistics (5.14) -------------------------------------------------------------
def rms_speed_ratio(m1: Real, m2: Real) -> Real:
    """v2_rms / v1_rms = sqrt(KE/m2) / sqrt(KE/m1) = sqrt(m1/m2) (5.14)."""
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    energy = 1
    return math.sqrt(energy / m2) / math.sqrt(energy / m1)


def clock_energy_share(ticks: int) -> float:
    """Average share (V1)^2 / (2 KE) of ball 1 over ``ticks`` equally spaced clock hands.

    Arrows spread uniformly round the energy circle of Fig. 5.2(b) give each ball half the
    energy (equipartition, (5.14)).
    """
    n = inputs.count(ticks, "ticks", minimum=3)
    return sum(math.cos(2 * math.pi * k / n) ** 2 for k in range(n)) / n


# -- integral right triangles (Fig. 5.2(f)) ---------------------------------------------------
@dataclass(frozen=True)
class BangTriangle:
    """The bang triangle: altitude 2 sqrt(m1 m2), base m1 - m2, hypotenuse m1 + m2 (5.10a)."""

    altitude: Real
    base: Real
    hypotenuse: Real
    altitude_coefficient: Real


def integral_right_triangle(m1: Real, m2: Real) -> BangTriangle:
    """The right triangle of the bang angle, scaled by M = m1 + m2 (Fig. 5.2(c), (f)).

    For perfect-square masses all three sides are integers; ``altitude_coefficient`` is the 4
    of a = sqrt(4 m1 m2).
    """
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    altitude = 2 * exact_sqrt(m1 * m2)
    return BangTriangle(altitude, m1 - m2, m1 + m2, altitude**2 / (m1 * m2))


def perfect_square(root: int) -> int:
    """The perfect square root^2 (the masses 1, 4, 9, ... of Fig. 5.2(f))."""
    n = inputs.count(root, "root", minimum=1)
    return n * n
