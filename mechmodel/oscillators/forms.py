"""Quadratic forms of the oscillator's ellipse and their matrices (chapter 11, (11.7)-(11.15),
(11.20), exercise 1.11.1).

The orbit is the quadratic form r.Q.r = 1 with Q = diag(1/a^2, 1/b^2) = R^2 ((11.7)-(11.13));
p = Q.r is perpendicular to the velocity and lies on the dual ellipse p.Q^-1.p = 1 of radii 1/a,
1/b ((11.8)-(11.10)); Q and R multiply slopes by powers of a/b and have the axes as eigenvectors
((11.12)-(11.16)); a rotated form A x^2 + 2B xy + C y^2 = 1 (11.20) and its ellipse parameters
(exercise 1.11.1).

Units: lengths a, b in any unit; matrices in its inverse powers. Matrices, slopes, dot products
of points given by a rational phase (``rational_phase``) and square roots of perfect squares
stay exact for ``int`` and ``Fraction`` inputs, so that identities such as p.r = 1 can be
checked exactly.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import overload

from mechmodel import inputs
from mechmodel.exact import exact_div, exact_sqrt, magnitude
from mechmodel.oscillators._common import check_semi_axes
from mechmodel.planar import (
    Matrix,
    Vector,
    apply,
    dot,
    matrix_inverse,
    matrix_power,
    matrix_product,
    rotation,
)
from mechmodel.typing import Real, Symbolic


def rational_phase(half_angle_tan: Real) -> Vector:
    """(cos u, sin u) of the phase u with tan(u/2) = ``half_angle_tan``: the rational
    parametrization ((1 - s^2)/(1 + s^2), 2s/(1 + s^2)) of the unit circle, exact for
    ``Fraction`` s, so that orbit points can be exact."""
    s = inputs.real(half_angle_tan, "half_angle_tan")
    if isinstance(s, int):
        s = Fraction(s)
    return ((1 - s * s) / (1 + s * s), 2 * s / (1 + s * s))


def _reciprocal(x: Real) -> Real:
    return Fraction(1, x) if isinstance(x, int) else 1 / x


def slope_operator(a: Real, b: Real) -> Matrix:
    """R = diag(1/a, 1/b): it multiplies the slope y/x of a vector by a/b (11.12a)."""
    check_semi_axes(a, b)
    return ((_reciprocal(a), 0), (0, _reciprocal(b)))


def ellipse_form(a: Real, b: Real) -> Matrix:
    """Q = R^2 = diag(1/a^2, 1/b^2), the matrix of the ellipse x^2/a^2 + y^2/b^2 = r.Q.r = 1
    ((11.7), (11.8a), (11.13))."""
    r = slope_operator(a, b)
    return matrix_product(r, r)


@overload
def form_value(matrix: Sequence[Sequence[Real]], vector: Sequence[Real]) -> Real: ...
@overload
def form_value(matrix: Sequence[Sequence[Symbolic]], vector: Sequence[Symbolic]) -> Symbolic: ...
def form_value(matrix: Sequence[Sequence[Symbolic]], vector: Sequence[Symbolic]) -> Symbolic:
    """The quadratic form r.M.r (11.7), (11.20)."""
    return dot(vector, apply(matrix, vector))


def quadratic_form(A: Symbolic, B: Symbolic, C: Symbolic, x: Symbolic, y: Symbolic) -> Symbolic:  # noqa: N803
    """The form (x y).(A B; B C).(x y) of (11.20), by the matrix products (plain operators:
    exact for rationals, an expression for sympy symbols)."""
    return form_value(((A, B), (B, C)), (x, y))


@dataclass(frozen=True)
class DualityProducts:
    """Dot products of the orbit point r, its velocity r' (w = 1), p = Q.r and p' = Q.r'
    ((11.8b), (11.10c), (11.17)), and the forms r.Q.r and p.Q^-1.p."""

    r: Vector
    p: Vector
    rdot_dot_p: Real
    pdot_dot_r: Real
    p_dot_r: Real
    pdot_dot_rdot: Real
    r_form: Real
    p_dual_form: Real


def duality_products(a: Real, b: Real, half_angle_tan: Real) -> DualityProducts:
    """The duality of the Q-ellipse and its p-ellipse at the orbit point of phase u,
    tan(u/2) = ``half_angle_tan`` (exact for rationals): r.v = ... p = Q.r is perpendicular to
    the velocity (r'.p = 0 = p'.r) and projects to 1 on r (p.r = p'.r' = 1); p lies on the
    ellipse p.Q^-1.p = 1 ((11.8)-(11.10), (11.17))."""
    check_semi_axes(a, b)
    c, s = rational_phase(half_angle_tan)
    r = (a * c, b * s)
    rdot = (-a * s, b * c)
    q = ellipse_form(a, b)
    p, pdot = apply(q, r), apply(q, rdot)
    return DualityProducts(
        r,
        p,
        dot(rdot, p),
        dot(pdot, r),
        dot(p, r),
        dot(pdot, rdot),
        form_value(q, r),
        form_value(matrix_inverse(q), p),
    )


@dataclass(frozen=True)
class EllipseParameters:
    """An ellipse of a quadratic form: ``radius`` along the direction ``angle`` (radians, in
    (-pi/2, pi/2]), ``other_radius`` across it; ``kind`` is the conic's name."""

    radius: Real
    other_radius: Real
    angle: float
    kind: str


def form_eigenvalues(A: Real, B: Real, C: Real) -> tuple[Real, Real]:  # noqa: N803
    """Eigenvalues (larger, smaller) of the symmetric matrix (A B; B C)."""
    mean = (A + C) / 2
    spread = exact_sqrt(((A - C) / 2) ** 2 + B * B)
    return mean + spread, mean - spread


def conic_type(A: Real, B: Real, C: Real) -> str:  # noqa: N803
    """Curve of r.(A B; B C).r = 1 (11.20): an ellipse for two positive eigenvalues, a
    hyperbola for eigenvalues of opposite sign (exercise 1.11.1(c)), parallel lines for one zero
    and one positive eigenvalue, else no real points."""
    hi, lo = form_eigenvalues(A, B, C)
    if lo > 0:
        return "ellipse"
    if hi > 0 > lo:
        return "hyperbola"
    if hi > 0 and lo == 0:
        return "parallel lines"
    return "empty"


def ellipse_from_form(A: Real, B: Real, C: Real) -> EllipseParameters:  # noqa: N803
    """Radii and orientation of the conic r.(A B; B C).r = 1 (exercise 1.11.1(a)): writing
    (A B; B C) = Rot(t) diag(l1, l2) Rot(-t) gives A - C = (l1 - l2) cos 2t and
    2B = (l1 - l2) sin 2t, so t = atan2(2B, A - C)/2 points along the eigenvalue l1 >= l2, and
    the radius there is 1/sqrt(l1)."""
    hi, lo = form_eigenvalues(A, B, C)
    kind = conic_type(A, B, C)
    if kind not in ("ellipse", "hyperbola"):
        raise ValueError(f"r.Q.r = 1 is {kind}, not an ellipse or hyperbola")
    angle = math.atan2(2 * B, A - C) / 2 if (B != 0 or A != C) else 0.0
    radius = _reciprocal(exact_sqrt(hi))
    other = _reciprocal(exact_sqrt(magnitude(lo)))
    return EllipseParameters(radius, other, angle, kind)


@dataclass(frozen=True)
class QuadraticForm:
    """The symmetric matrix (A B; B C) of a form A x^2 + 2B xy + C y^2 (11.20)."""

    A: Real
    B: Real
    C: Real


def rotated_form(a: Real, b: Real, angle: Real) -> QuadraticForm:
    """The ellipse of radii a, b turned by ``angle``: Q' = Rot Q Rot^-1 (exercise 1.11.1(a));
    B != 0 marks a rotated ellipse (text after Fig. 11.7)."""
    rot = rotation(angle)
    q = matrix_product(matrix_product(rot, ellipse_form(a, b)), matrix_inverse(rot))
    return QuadraticForm(q[0][0], (q[0][1] + q[1][0]) / 2, q[1][1])


@dataclass(frozen=True)
class DualEllipse:
    """The p-ellipse p.Q^-1.p = 1: radii along x and y, and those radii times a and b."""

    radius_x: Real
    radius_y: Real
    radius_x_times_a: Real
    radius_y_times_b: Real


def dual_ellipse(a: Real, b: Real) -> DualEllipse:
    """Radii of the ellipse p.Q^-1.p = 1 traced by p = Q.r: the inverse (1/a, 1/b) of the
    Q-ellipse radii (11.9). From the diagonal of Q^-1: radius = 1/sqrt(entry)."""
    qi = matrix_inverse(ellipse_form(a, b))
    rx = _reciprocal(exact_sqrt(qi[0][0]))
    ry = _reciprocal(exact_sqrt(qi[1][1]))
    return DualEllipse(rx, ry, rx * a, ry * b)


def dual_vector(a: Real, b: Real, phi: Real) -> Vector:
    """The vector p = Q.r of the orbit point r = (a cos phi, b sin phi), phi the time-phase
    angle (11.8): the matrix Q = diag(1/a^2, 1/b^2) applied to r."""
    inputs.real(phi, "phi")
    return apply(ellipse_form(a, b), (a * math.cos(phi), b * math.sin(phi)))


def operator_image(a: Real, b: Real, power: int, x: Real, y: Real) -> Vector:
    """R^power applied to the vector (x, y), R = diag(1/a, 1/b) ((11.12)-(11.13): power 2 is
    Q.r, power -2 is Q^-1.r)."""
    return apply(matrix_power(slope_operator(a, b), power), (x, y))


def image_slope(a: Real, b: Real, power: int, angle: Real) -> float:
    """Slope tan of the polar angle of R^power applied to a vector of polar angle ``angle``
    ((11.16): p(phi_k+1) = Q.r(phi_k-1) for power 2)."""
    inputs.real(angle, "angle")
    x, y = operator_image(a, b, power, math.cos(angle), math.sin(angle))
    return y / x


@dataclass(frozen=True)
class ScaledRadii:
    """Radii scaled by the geometric mean S = sqrt(ab): a_S = a/S, b_S = b/S, and a_S b_S."""

    scale: Real
    a_scaled: Real
    b_scaled: Real
    product: Real


def scaled_radii(a: Real, b: Real) -> ScaledRadii:
    """Scale the ellipse by S = sqrt(ab) (11.11): a_S = sqrt(a/b) = 1/b_S."""
    check_semi_axes(a, b)
    s = exact_sqrt(a * b)
    a_s, b_s = exact_div(a, s), exact_div(b, s)
    return ScaledRadii(s, a_s, b_s, a_s * b_s)


def unit_scale(area_product: Real) -> Real:
    """The geometric-mean scale S = sqrt(ab) of (11.11) from the product ab of the radii (the
    triads' ab = 1 gives the unit scale S = 1, before (11.18)); exact for rational squares."""
    inputs.positive(area_product, "area_product")
    return exact_sqrt(area_product)


def major_axis_angle(matrix: Sequence[Sequence[Real]]) -> float:
    """Direction, radians in [0, pi), of the major (longest) axis of r.M.r = 1: the eigenvector
    of the smaller eigenvalue."""
    A, B, C = matrix[0][0], (matrix[0][1] + matrix[1][0]) / 2, matrix[1][1]  # noqa: N806
    return (ellipse_from_form(A, B, C).angle + math.pi / 2) % math.pi


def inverse_ellipse_rotation(a: Real, b: Real) -> float:
    """Angle, radians in [0, pi), that turns the S-scaled Q-ellipse (form S^2 Q) onto the
    S-scaled p-ellipse (form Q^-1/S^2): the axis switch after (11.11)."""
    if a == b:
        raise ValueError("a circle has no axes to switch: a != b")
    s2 = a * b
    q = ellipse_form(a, b)
    qi = matrix_inverse(q)
    scaled_q = tuple(tuple(s2 * e for e in row) for row in q)
    scaled_qi = tuple(tuple(e / s2 for e in row) for row in qi)
    return (major_axis_angle(scaled_qi) - major_axis_angle(scaled_q)) % math.pi


def slope_gain(a: Real, b: Real, power: int) -> Real:
    """Factor by which R^power multiplies the slope y/x of a vector (R = diag(1/a, 1/b);
    power 2 is Q, -1 is R^-1): (11.12)-(11.13), (11.16). Exact for rational a, b."""
    operator = matrix_power(slope_operator(a, b), power)
    x, y = apply(operator, (1, 1))
    return exact_div(y, x)


@dataclass(frozen=True)
class AxisEigenvalues:
    """Eigenvalues of R^power on the axis vectors a^ = (1, 0) and b^ = (0, 1), and those
    eigenvalues times a^power and b^power (11.14)-(11.15)."""

    a_axis: Real
    b_axis: Real
    a_axis_scaled: Real
    b_axis_scaled: Real


def axis_eigenvalues(a: Real, b: Real, power: int) -> AxisEigenvalues:
    """R^power maps a^ to a multiple of itself (no slope change, (11.14)): the eigenvalue is
    the ratio of image to vector; R^2 = Q gives 1/a^2 and 1/b^2 (11.15c,d)."""
    operator = matrix_power(slope_operator(a, b), power)
    ea = apply(operator, (1, 0))
    eb = apply(operator, (0, 1))
    if ea[1] != 0 or eb[0] != 0:
        raise ValueError("the axes are not eigenvectors")  # pragma: no cover
    n = int(power)
    return AxisEigenvalues(ea[0], eb[1], ea[0] * a**n, eb[1] * b**n)
