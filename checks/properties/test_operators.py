"""Laws of the bang operators, reflections and rotations (mechmodel.operators): chapter 5.

Matrices of rational masses are compared exactly; anything with a square root or an angle
within 1e-12 of the magnitudes involved.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import example, given, target
from hypothesis import strategies as st

from checks.properties.strategies import (
    fraction_masses,
    fraction_velocities,
    masses,
    mirror_angles,
    square_roots,
    velocities,
)
from mechmodel.collisions import collide
from mechmodel.operators import (
    apply,
    bang_angle,
    ceiling_matrix,
    collision_matrix,
    determinant,
    double_bang_matrix,
    floor_matrix,
    integral_right_triangle,
    mass_scaled,
    matrix_product,
    mirror_angle,
    mirror_pair_rotation,
    negated,
    pauli_square,
    quaternion_square,
    reflection,
    rotation,
    rotation_angle,
    scaled_collision_matrix,
    scaled_double_bang_matrix,
    sigma_a,
    sigma_b,
    sigma_product,
)

pytestmark = pytest.mark.properties
REL = 1e-12
UNIT = ((1, 0), (0, 1))


def close(a, b, scale: float = 1.0) -> bool:
    """Entry by entry within REL of the scale of the entries."""
    size = scale + max(abs(x) for row in (*a, *b) for x in row)
    return all(
        abs(x - y) <= REL * size
        for ra, rb in zip(a, b, strict=True)
        for x, y in zip(ra, rb, strict=True)
    )


def worst(a, b) -> float:
    return max(abs(x - y) for ra, rb in zip(a, b, strict=True) for x, y in zip(ra, rb, strict=True))


@given(fraction_masses(), fraction_masses())
@example(Fraction(49), Fraction(1))  # Fig. 5.1
def test_the_collision_matrix_is_an_involution_with_determinant_minus_one(
    m1: Fraction, m2: Fraction
) -> None:
    """The elastic bang M of (5.1b) undoes itself, M M = 1 (a second bang at once restores the
    velocities), and det M = -1: in any velocities it is a reflection (p. 5.18)."""
    m = collision_matrix(m1, m2)
    assert matrix_product(m, m) == UNIT
    assert determinant(m) == -1


@given(fraction_masses(), fraction_masses(), fraction_velocities(), fraction_velocities())
def test_the_collision_matrix_is_the_collision(
    m1: Fraction, m2: Fraction, v1: Fraction, v2: Fraction
) -> None:
    """v_FIN = M v_IN (5.1b)-(5.2a): the matrix gives exactly the velocities of the bang (4.1)."""
    assert apply(collision_matrix(m1, m2), (v1, v2)) == collide(m1, m2, v1, v2).after


@given(fraction_masses(), fraction_masses())
def test_ceiling_times_collision_has_determinant_plus_one(m1: Fraction, m2: Fraction) -> None:
    """The double bang C M of (5.3) has det(C M) = det C det M = (-1)(-1) = +1: a rotation,
    not a reflection (p. 5.18); C and F are sigma_A and -sigma_A (5.15a)-(5.15b)."""
    assert determinant(double_bang_matrix(m1, m2)) == 1
    assert ceiling_matrix() == sigma_a()
    assert floor_matrix() == negated(sigma_a())


@given(masses(), masses())
@example(49.0, 1.0)  # theta = 16.26 degrees (5.11)
def test_ceiling_times_collision_rotates_by_the_bang_angle(m1: float, m2: float) -> None:
    """In mass-scaled velocities V = (sqrt(m1) v1, sqrt(m2) v2) (5.6) the bang is the reflection
    ((cos, sin), (sin, -cos)) of the bang angle theta, and C M is the rotation by -theta
    (5.9)-(5.12), with cos^2 + sin^2 = 1 (5.10a)."""
    angle = bang_angle(m1, m2)
    assert 0 < angle.angle < math.pi
    assert abs(angle.pythagorean_sum - 1) <= 4 * REL
    c, s = angle.cos, angle.sin
    assert close(scaled_collision_matrix(m1, m2), ((c, s), (s, -c)))
    double = scaled_double_bang_matrix(m1, m2)
    target(worst(double, rotation(-angle.angle)), label="rotation error")
    assert close(double, rotation(-angle.angle))
    assert abs(determinant(double) - 1) <= 4 * REL


@given(masses(), masses(), st.integers(min_value=0, max_value=12))
@example(49.0, 1.0, 5)  # (5.13a): N theta = 81.30 degrees
def test_n_double_bangs_rotate_by_n_bang_angles(m1: float, m2: float, n: int) -> None:
    """(C M)^N in V space is the rotation by -N theta (5.13a): the bang clock ticks equal
    angles."""
    theta = bang_angle(m1, m2).angle
    assert close(scaled_double_bang_matrix(m1, m2, n), rotation(-n * theta), scale=n)


@given(masses(), masses(), velocities(), velocities())
def test_a_bang_keeps_the_length_of_the_mass_scaled_velocity(
    m1: float, m2: float, v1: float, v2: float
) -> None:
    """The energy ellipse m1 v1^2 + m2 v2^2 = 2E is the circle V1^2 + V2^2 = 2E in mass-scaled
    velocities (5.6), and every bang keeps V on it: the bang clock's hand has fixed length."""
    s = ((math.sqrt(m1), 0), (0, math.sqrt(m2)))
    before = apply(s, (v1, v2))
    after = apply(s, collide(m1, m2, v1, v2).after)
    energy = m1 * v1 * v1 + m2 * v2 * v2
    assert abs(before[0] ** 2 + before[1] ** 2 - energy) <= REL * (energy + 1e-300)
    assert abs(after[0] ** 2 + after[1] ** 2 - energy) <= 1e-11 * (energy + 1e-300)


@given(fraction_masses(), fraction_masses())
def test_mass_scaling_keeps_the_ceiling_and_floor(m1: Fraction, m2: Fraction) -> None:
    """The scaling S = diag(sqrt(m1), sqrt(m2)) commutes with C and F: a wall bounce is the same
    reflection in v and in V (5.7)."""
    assert close(mass_scaled(ceiling_matrix(), m1, m2), ceiling_matrix())
    assert close(mass_scaled(floor_matrix(), m1, m2), floor_matrix())


@given(mirror_angles())
def test_a_reflection_squares_to_one_and_has_determinant_minus_one(phi: float) -> None:
    """sigma_phi = sigma_A cos(phi) + sigma_B sin(phi) (5.15c) squares to 1 and has det -1;
    its mirror is at phi/2 (Fig. 5.3c)."""
    s = reflection(phi)
    assert close(matrix_product(s, s), UNIT)
    assert abs(determinant(s) + 1) <= REL
    assert abs(mirror_angle(s) - phi / 2) <= REL


@given(mirror_angles(), mirror_angles())
def test_two_reflections_make_a_rotation_by_twice_the_mirror_angle(a: float, b: float) -> None:
    """sigma_2 sigma_1 is the rotation R by twice the angle from the first mirror to the second
    (5.17a, Fig. 5.3d-e), with det = (-1)(-1) = +1 (p. 5.18)."""
    product = matrix_product(reflection(2 * b), reflection(2 * a))
    assert abs(determinant(product) - 1) <= 4 * REL
    assert close(product, rotation(2 * (b - a)))
    turn = mirror_pair_rotation(a, b)
    assert abs(math.remainder(turn - 2 * (b - a), 2 * math.pi)) <= 1e-11


@given(mirror_angles(), mirror_angles())
def test_rotations_compose_and_have_determinant_one(a: float, b: float) -> None:
    """R(a) R(b) = R(a + b): rotations never make a reflection, det R = +1 (p. 5.17-5.18)."""
    assert close(matrix_product(rotation(a), rotation(b)), rotation(a + b))
    assert abs(determinant(rotation(a)) - 1) <= REL
    assert abs(math.remainder(rotation_angle(rotation(a)) - a, 2 * math.pi)) <= 1e-12


def test_pauli_and_quaternion_algebra() -> None:
    """sigma_A^2 = sigma_B^2 = sigma_C^2 = 1 (5.15d), sigma_A sigma_B = -sigma_B sigma_A, the
    Pauli matrices square to +1 and Hamilton's i, j, k to -1 (p. 5.15); sigma_B sigma_A turns
    by +90 degrees and sigma_A sigma_B by -90 (p. 5.17)."""
    for name in ("A", "B", "C"):
        assert close(sigma_product(name, name), UNIT)
    assert sigma_product("A", "B") == negated(sigma_product("B", "A"))
    assert sigma_product("A", "B") == ((0, 1), (-1, 0))
    assert [pauli_square(a) for a in "xyz"] == [1, 1, 1]
    assert [quaternion_square(u) for u in "ijk"] == [-1, -1, -1]
    assert rotation_angle(matrix_product(sigma_b(), sigma_a())) == pytest.approx(math.pi / 2)
    assert rotation_angle(matrix_product(sigma_a(), sigma_b())) == pytest.approx(-math.pi / 2)


@given(square_roots(), square_roots())
@example(7, 1)  # (a, b, c) = (14, 48, 50)
@example(3, 2)  # (12, 5, 13)
def test_perfect_square_masses_give_integral_right_triangles(k1: int, k2: int) -> None:
    """For perfect-square masses m1 = k1^2, m2 = k2^2 the bang triangle has integer sides
    altitude 2 sqrt(m1 m2), base m1 - m2 and hypotenuse m1 + m2, with a^2 + b^2 = c^2
    (Fig. 5.2(f))."""
    t = integral_right_triangle(k1 * k1, k2 * k2)
    assert all(isinstance(x, int) for x in (t.altitude, t.base, t.hypotenuse))
    assert t.altitude**2 + t.base**2 == t.hypotenuse**2
