"""Laws of the bang operators, reflections and rotations (mechmodel.operators): chapter 5.

Matrices of rational masses are compared exactly; anything with a square root or an angle
within 1e-12 of the magnitudes involved.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from fractions import Fraction

import pytest
from hypothesis import assume, example, given, target
from hypothesis import strategies as st

from checks.properties.closeness import assert_close, largest, reals
from checks.properties.strategies import (
    fraction_lengths,
    fraction_masses,
    fraction_velocities,
    masses,
    mirror_angles,
    moderate_fraction_masses,
    rational_half_angle_tans,
    small_fractions,
    square_roots,
    velocities,
)
from mechmodel.bangs import ceiling_sequence
from mechmodel.collisions import collide, momentum_line_slope
from mechmodel.operators import (
    angle_between_mirrors,
    bang_angle,
    bang_facet_slope,
    bang_line_angle,
    bang_line_slope,
    ceiling_matrix,
    clock_energy_share,
    collision_line_angle,
    collision_matrix,
    double_bang_matrix,
    double_bang_rotation_angle,
    energy_line_inclination,
    floor_matrix,
    hypotenuse,
    imaginary_unit_square,
    integral_right_triangle,
    mass_scaled,
    mass_scaled_form,
    mirror_angle,
    mirror_pair_rotation,
    mirror_pair_translation,
    mirror_separation,
    multiple_bang_angle,
    negated,
    pauli_common_square,
    pauli_square,
    perfect_square,
    quaternion_common_square,
    quaternion_square,
    quaternion_unit,
    reflection,
    reflection_mirror_angle,
    rms_speed_ratio,
    rotation_angle,
    rotation_picture_bang_count,
    scalar_of_identity,
    scaled_collision_matrix,
    scaled_double_bang_matrix,
    sigma,
    sigma_a,
    sigma_b,
    sigma_mirror_angle,
    sigma_mirror_separation,
    sigma_product,
    sigma_rotation_angle,
    square_scalar,
    translation_mirror_separation,
)
from mechmodel.planar import apply, determinant, matrix_power, matrix_product, rotation

pytestmark = pytest.mark.properties
REL = 1e-12
UNIT = ((1, 0), (0, 1))


def worst(a: Sequence[Sequence[float]], b: Sequence[Sequence[float]]) -> float:
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
    assert matrix_power(m, 2) == matrix_power(m, 0) == UNIT
    assert determinant(m) == -1


@given(fraction_masses(), fraction_masses())
@example(Fraction(49), Fraction(1))  # Fig. 5.1
def test_the_bang_matrix_times_the_total_mass_is_linear_in_the_masses(
    m1: Fraction, m2: Fraction
) -> None:
    """(m1 + m2) M = ((m1 - m2, 2 m2), (2 m1, m2 - m1)) (5.1a)-(5.1b), exactly, at any
    masses."""
    m = collision_matrix(m1, m2)
    scaled = [[(m1 + m2) * x for x in row] for row in m]
    assert scaled == [[m1 - m2, 2 * m2], [2 * m1, m2 - m1]]


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
    once = matrix_product(ceiling_matrix(), collision_matrix(m1, m2))
    assert double_bang_matrix(m1, m2) == double_bang_matrix(m1, m2, 1) == once
    assert double_bang_matrix(m1, m2, 2) == matrix_product(once, once)
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
    assert abs(float(angle.pythagorean_sum) - 1) <= 4 * REL
    c, s = angle.cos, angle.sin
    bang, mirror = scaled_collision_matrix(m1, m2), ((c, s), (s, -c))
    assert_close(bang, mirror, scale=1.0 + largest(bang, mirror))
    double, turn_back = scaled_double_bang_matrix(m1, m2), rotation(-angle.angle)
    target(worst(double, turn_back), label="rotation error")
    assert_close(double, turn_back, scale=1.0 + largest(double, turn_back))
    assert abs(determinant(double) - 1) <= 4 * REL
    assert abs(c - (m1 - m2) / (m1 + m2)) <= 4 * REL
    expected_sin = 2 * math.sqrt(m1 * m2) / (m1 + m2)
    assert math.isclose(s, expected_sin, rel_tol=8 * REL)
    turn = double_bang_rotation_angle(m1, m2)
    assert turn == double_bang_rotation_angle(m1, m2, 1)
    assert abs(turn + angle.angle) <= 4 * REL


@given(masses(), masses(), st.integers(min_value=0, max_value=12))
@example(49.0, 1.0, 5)  # (5.13a): N theta = 81.30 degrees
def test_n_double_bangs_rotate_by_n_bang_angles(m1: float, m2: float, n: int) -> None:
    """(C M)^N in V space is the rotation by -N theta (5.13a): the bang clock ticks equal
    angles."""
    theta = bang_angle(m1, m2).angle
    power, turn_back = scaled_double_bang_matrix(m1, m2, n), rotation(-n * theta)
    assert_close(power, turn_back, scale=n + largest(power, turn_back))
    assert multiple_bang_angle(m1, m2, n) == n * theta
    turn = double_bang_rotation_angle(m1, m2, n)
    assert -math.pi <= turn <= math.pi
    assert abs(math.remainder(turn + n * theta, 2 * math.pi)) <= 1e-11 * (n + 1)


@given(fraction_masses(), fraction_masses(), st.integers(min_value=1, max_value=12))
@example(Fraction(49), Fraction(1), 5)  # (5.13b) at N = 5
@example(Fraction(1), Fraction(1), 2)  # theta = 90 degrees: sin(2 theta) = 0
def test_n_double_bangs_in_velocities_have_the_mass_scaled_form(
    m1: Fraction, m2: Fraction, n: int
) -> None:
    """In velocities v, (C M)^N = ((cos, a sin), (b sin, cos)) of the angle N theta with
    a = sqrt(m2/m1) and b = -sqrt(m1/m2), so a b = -1 (5.13b): the rotation of (5.13a) seen
    through the mass scaling S (5.7). Where sin(N theta) = 0 there is no such form."""
    v = double_bang_matrix(m1, m2, n)
    assert v[0][0] == v[1][1]
    if v[0][1] == 0:
        with pytest.raises(ValueError, match="sin"):
            mass_scaled_form(m1, m2, n)
        return
    form = mass_scaled_form(m1, m2, n)
    theta = bang_angle(m1, m2).angle
    assert math.isclose(form.upper, math.sqrt(m2 / m1), rel_tol=8 * REL)
    assert math.isclose(form.lower, -math.sqrt(m1 / m2), rel_tol=8 * REL)
    assert abs(form.cos - math.cos(n * theta)) <= 1e-11 * n
    assert abs(form.sin - math.sin(n * theta)) <= 1e-11 * n
    assert mass_scaled_form(m1, m2) == mass_scaled_form(m1, m2, 1)


@given(moderate_fraction_masses(), moderate_fraction_masses())
@example(Fraction(49), Fraction(1))  # Fig. 5.1: 21 bangs after the floor bounce
def test_the_rotation_picture_counts_the_bangs_of_the_sequence(m1: Fraction, m2: Fraction) -> None:
    """From the floor bounce (v0, -v0), at angle -theta/2 in V space, each double bang turns
    the state by -theta (5.12); the bangs stop at the least n with (n + 2) theta/2 >= pi: the
    count of the exact bang sequence of (5.4) (21 for the 49:1 pair of Fig. 5.1)."""
    ratio = 2 * math.pi / bang_angle(m1, m2).angle
    assume(abs(ratio - round(ratio)) > 1e-9)  # exact ties (1:1, 3:1) are decided by rounding
    assert rotation_picture_bang_count(m1, m2) == ceiling_sequence(m1, m2, 1, -1).count


@given(masses(), masses())
@example(376.3496345680438, 1.0)  # pi/beta rounds up past a whole number: the count steps back
@example(569.2651083271583, 1.0)  # pi/beta rounds down to a whole number: the count steps on
def test_the_rotation_picture_count_is_the_least_that_ends_the_bangs(m1: float, m2: float) -> None:
    """The bang clock's count is the least n with (n + 2) beta >= pi, beta = theta/2 (5.12):
    after n bangs none is possible and after n - 1 one still is, also where pi/beta lies
    within rounding of a whole number (Fig. 5.1, Exercise 1.5.1's game-over point)."""
    beta = bang_angle(m1, m2).angle / 2
    n = rotation_picture_bang_count(m1, m2)
    assert (n + 2) * beta >= math.pi
    assert n == 0 or (n + 1) * beta < math.pi


@given(masses(), masses(), velocities(), velocities())
def test_a_bang_keeps_the_length_of_the_mass_scaled_velocity(
    m1: float, m2: float, v1: float, v2: float
) -> None:
    """The energy ellipse m1 v1^2 + m2 v2^2 = 2E is the circle V1^2 + V2^2 = 2E in mass-scaled
    velocities (5.6), and every bang keeps V on it: the bang clock's hand has fixed length."""
    s = ((math.sqrt(m1), 0), (0, math.sqrt(m2)))
    before = apply(s, (v1, v2))
    after = apply(s, [float(v) for v in reals(collide(m1, m2, v1, v2).after)])
    energy = m1 * v1 * v1 + m2 * v2 * v2
    assert abs(before[0] ** 2 + before[1] ** 2 - energy) <= REL * (energy + 1e-300)
    assert abs(after[0] ** 2 + after[1] ** 2 - energy) <= 1e-11 * (energy + 1e-300)


@given(fraction_masses(), fraction_masses())
def test_mass_scaling_keeps_the_ceiling_and_floor(m1: Fraction, m2: Fraction) -> None:
    """The scaling S = diag(sqrt(m1), sqrt(m2)) commutes with C and F: a wall bounce is the same
    reflection in v and in V (5.7)."""
    for wall in (ceiling_matrix(), floor_matrix()):
        scaled = mass_scaled(wall, m1, m2)
        assert_close(scaled, wall, scale=1.0 + largest(scaled, wall))


@given(mirror_angles())
def test_a_reflection_squares_to_one_and_has_determinant_minus_one(phi: float) -> None:
    """sigma_phi = sigma_A cos(phi) + sigma_B sin(phi) (5.15c) squares to 1 and has det -1;
    its mirror is at phi/2 (Fig. 5.3c)."""
    s = reflection(phi)
    square = matrix_product(s, s)
    assert_close(square, UNIT, scale=1.0 + largest(square, UNIT))
    assert abs(determinant(s) + 1) <= REL
    assert abs(mirror_angle(s) - phi / 2) <= REL


@given(mirror_angles(), mirror_angles())
def test_two_reflections_make_a_rotation_by_twice_the_mirror_angle(a: float, b: float) -> None:
    """sigma_2 sigma_1 is the rotation R by twice the angle from the first mirror to the second
    (5.17a, Fig. 5.3d-e), with det = (-1)(-1) = +1 (p. 5.18)."""
    product = matrix_product(reflection(2 * b), reflection(2 * a))
    assert abs(determinant(product) - 1) <= 4 * REL
    turn_twice = rotation(2 * (b - a))
    assert_close(product, turn_twice, scale=1.0 + largest(product, turn_twice))
    turn = mirror_pair_rotation(a, b)
    assert abs(math.remainder(turn - 2 * (b - a), 2 * math.pi)) <= 1e-11
    between = angle_between_mirrors(reflection(2 * a), reflection(2 * b))
    assert -math.pi / 2 < between <= math.pi / 2
    assert abs(math.remainder(between - (b - a), math.pi)) <= 1e-11


@given(fraction_velocities(), fraction_velocities(), fraction_velocities())
@example(Fraction(0), Fraction(1), Fraction(5))
def test_two_parallel_mirrors_translate_by_twice_their_separation(
    p1: Fraction, d: Fraction, x: Fraction
) -> None:
    """Reflecting x -> 2 p1 - x and then x -> 2 p2 - x moves every x by 2 (p2 - p1): two
    parallel mirrors make a translation by twice their separation (line 5091), as two crossed
    mirrors make a rotation by twice their angle (Fig. 5.4)."""
    p2 = p1 + (d if d != 0 else Fraction(1))
    t = mirror_pair_translation(p1, p2)
    assert t.separation == p2 - p1
    assert 2 * p2 - (2 * p1 - x) == x + t.translation
    assert t.ratio == 2


@given(mirror_angles())
def test_the_mirror_of_sigma_phi_is_tilted_at_half_phi(phi: float) -> None:
    """sigma_phi leaves fixed the line at phi/2 (5.15c, Fig. 5.3c): the unit vector along it is
    its own image."""
    tilt = reflection_mirror_angle(phi)
    assert abs(tilt - phi / 2) <= REL
    along = (math.cos(tilt), math.sin(tilt))
    image = apply(reflection(phi), along)
    assert all(abs(a - b) <= 4 * REL for a, b in zip(image, along, strict=True))


@given(mirror_angles())
def test_the_mirrors_of_a_rotation_are_half_its_angle_apart(turn: float) -> None:
    """sigma_turn sigma_A is the rotation by turn (5.17a), and the two mirrors are turn/2 apart:
    a rotation angle is twice the angle between the mirrors (p. 5.16)."""
    assert (
        abs(math.remainder(mirror_pair_rotation(0, mirror_separation(turn)) - turn, 2 * math.pi))
        <= 1e-11
    )
    assert abs(mirror_separation(turn) - turn / 2) <= REL


@given(fraction_velocities(), fraction_velocities())
def test_parallel_mirrors_half_a_translation_apart_make_it(p1: Fraction, a: Fraction) -> None:
    """Two 1D mirrors a/2 apart translate by a (p. 5.17), exactly."""
    assume(a != 0)
    d = translation_mirror_separation(a)
    assert d == a / 2
    assert mirror_pair_translation(p1, p1 + d).translation == a


@given(mirror_angles(), mirror_angles())
def test_rotations_compose_and_have_determinant_one(a: float, b: float) -> None:
    """R(a) R(b) = R(a + b): rotations never make a reflection, det R = +1 (p. 5.17-5.18)."""
    composed, sum_turn = matrix_product(rotation(a), rotation(b)), rotation(a + b)
    assert_close(composed, sum_turn, scale=1.0 + largest(composed, sum_turn))
    assert abs(determinant(rotation(a)) - 1) <= REL
    assert abs(math.remainder(rotation_angle(rotation(a)) - a, 2 * math.pi)) <= 1e-12


def test_pauli_and_quaternion_algebra() -> None:
    """sigma_A^2 = sigma_B^2 = sigma_C^2 = 1 (5.15d), sigma_A sigma_B = -sigma_B sigma_A, the
    Pauli matrices square to +1 and Hamilton's i, j, k to -1 (p. 5.15); sigma_B sigma_A turns
    by +90 degrees and sigma_A sigma_B by -90 (p. 5.17)."""
    for name in ("A", "B", "C"):
        square = sigma_product(name, name)
        assert_close(square, UNIT, scale=1.0 + largest(square, UNIT))
    assert sigma_product("A", "B") == negated(sigma_product("B", "A"))
    assert sigma_product("A", "B") == ((0, 1), (-1, 0))
    assert [pauli_square(a) for a in "xyz"] == [1, 1, 1]
    assert [quaternion_square(u) for u in "ijk"] == [-1, -1, -1]
    assert rotation_angle(matrix_product(sigma_b(), sigma_a())) == pytest.approx(math.pi / 2)
    assert rotation_angle(matrix_product(sigma_a(), sigma_b())) == pytest.approx(-math.pi / 2)
    assert sigma_rotation_angle("B", "A") == pytest.approx(math.pi / 2)
    assert quaternion_common_square() == imaginary_unit_square() == -1
    assert pauli_common_square() == 1
    i, j, k = (quaternion_unit(u) for u in "ijk")  # Hamilton: i j = k, j k = i, k i = j
    assert (matrix_product(i, j), matrix_product(j, k), matrix_product(k, i)) == (k, i, j)
    assert matrix_product(j, i) == negated(k)
    assert sigma("0") == UNIT
    for name in ("A", "B", "C", "0"):
        assert sigma("-" + name) == negated(sigma(name))
        assert sigma_product("0", name) == sigma(name) == sigma_product(name, "0")
    assert sigma_mirror_angle("A") == 0
    assert sigma_mirror_angle("B") == pytest.approx(math.pi / 4)
    assert sigma_mirror_angle("-A") == pytest.approx(math.pi / 2)
    for first, second in (("A", "-A"), ("-A", "A")):  # mirrors at 0 and 90 degrees
        assert sigma_mirror_separation(first, second) == pytest.approx(math.pi / 2)


@given(small_fractions(), small_fractions(), small_fractions(), masses())
@example(Fraction(1), Fraction(1, 4), Fraction(-1), 1e6)
def test_a_traceless_matrix_squares_to_minus_its_determinant(
    a: Fraction, b: Fraction, c: Fraction, r: float
) -> None:
    """Cayley-Hamilton: A^2 = (tr A) A - det A, so a matrix of trace zero squares to the number
    -det A (sigma_A and sigma_B to +1, Hamilton's units to -1 (5.15)), r R(90 degrees)
    to -r^2 up to rounding (1e-12 of the size), while a shear ((1, b), (0, 1)), b != 0,
    squares to no number."""
    m = ((a, b), (c, -a))
    assert square_scalar(m) == scalar_of_identity(matrix_product(m, m)) == -determinant(m)
    quarter = tuple(tuple(r * x for x in row) for row in rotation(math.pi / 2))
    square = square_scalar(quarter)
    assert not isinstance(square, complex)  # a real matrix squares to a real number
    assert math.isclose(square, -r * r, rel_tol=4 * REL)
    assert scalar_of_identity(((r, 0.99e-12 * r), (0.0, r))) == r  # rounding: 1e-12 of the size
    with pytest.raises(ValueError, match="unit matrix"):
        scalar_of_identity(((r, 1.005e-12 * r), (0.0, r)))
    if b != 0:
        with pytest.raises(ValueError, match="unit matrix"):
            square_scalar(((1, b), (0, 1)))


ROUNDING = Fraction(1e-9)  # how far a determinant may be off +1 or -1 by rounding


@given(rational_half_angle_tans(), st.integers(min_value=-600, max_value=600))
@example(Fraction(1, 2), 200)  # a determinant exactly 1e-9 off: rounding
@example(Fraction(1, 2), -200)
@example(Fraction(1, 2), 201)  # 1.005e-9 off: no longer
@example(Fraction(1, 2), -201)
def test_a_determinant_off_by_more_than_rounding_is_no_rotation_or_reflection(
    t: Fraction, k: int
) -> None:
    """det R = +1 for a rotation (5.17a) and -1 for a reflection (5.15c), p. 5.18:
    stretching one row by 1 + delta makes the determinant 1 + delta, still a rotation (or
    reflection) within rounding, |delta| <= 1e-9, and neither beyond it."""
    cos, sin = (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)  # a rational point of the circle
    stretch = 1 + ROUNDING * k / 200
    turned = ((stretch * cos, -stretch * sin), (sin, cos))
    mirrored = ((stretch * cos, stretch * sin), (sin, -cos))
    assert determinant(turned) == stretch == -determinant(mirrored)
    if abs(k) <= 200:
        assert abs(rotation_angle(turned) - math.atan2(sin, cos)) <= 1e-8
        assert abs(mirror_angle(mirrored) - math.atan2(sin, cos) / 2) <= 1e-8
    else:
        with pytest.raises(ValueError, match="rotation"):
            rotation_angle(turned)
        with pytest.raises(ValueError, match="reflection"):
            mirror_angle(mirrored)


@given(square_roots(), square_roots())
@example(7, 1)  # (a, b, c) = (14, 48, 50)
@example(3, 2)  # (12, 5, 13)
@example(1, 2)  # the masses 1 and 4: (4, 3, 5)
def test_perfect_square_masses_give_integral_right_triangles(k1: int, k2: int) -> None:
    """For perfect-square masses m1 = k1^2, m2 = k2^2 the bang triangle has integer sides
    altitude 2 sqrt(m1 m2) = 2 k1 k2 = sqrt(4 m1 m2), base m1 - m2 and hypotenuse m1 + m2,
    with a^2 + b^2 = c^2 (Fig. 5.2(f))."""
    m1, m2 = perfect_square(k1), perfect_square(k2)
    assert (m1, m2) == (k1 * k1, k2 * k2)
    t = integral_right_triangle(m1, m2)
    assert isinstance(t.altitude, int)
    assert isinstance(t.base, int)
    assert isinstance(t.hypotenuse, int)
    assert t.altitude == 2 * k1 * k2
    assert t.altitude**2 + t.base**2 == t.hypotenuse**2
    assert t.altitude_coefficient == 4
    if k1 != k2:
        c = hypotenuse(t.altitude, abs(t.base))
        assert c == t.hypotenuse
        assert isinstance(c, int)
        assert hypotenuse(float(t.altitude), abs(float(t.base))) == pytest.approx(c, rel=REL)


# -- lines of the velocity plots and the clock's statistics -----------------------------------


@given(fraction_masses(), fraction_masses(), fraction_lengths())
@example(Fraction(1), Fraction(1), Fraction(1, 2))  # equal masses: the -45 degree bang line
def test_the_bang_line_is_the_momentum_line(m1: Fraction, m2: Fraction, energy: Fraction) -> None:
    """A bang moves (v1, v2) along the momentum line of slope -m1/m2 (Figs. 3.1, 4.4b, 4.12),
    normal to a mirror facet of slope m2/m1; the collision line v2 = v1 is at 45 degrees, and
    so is the energy line V1^2 + V2^2 = 2 KE of Fig. 5.2(e), whatever the energy."""
    slope = bang_line_slope(m1, m2)
    assert slope == momentum_line_slope(m1, m2) == -m1 / m2
    assert bang_facet_slope(m1, m2) * slope == -1
    assert bang_line_angle(m1, m2) == pytest.approx(math.atan(-m1 / m2), rel=REL)
    assert collision_line_angle() == pytest.approx(math.pi / 4, rel=REL)
    assert energy_line_inclination(energy) == pytest.approx(math.pi / 4, rel=REL)


@given(masses(), masses(), st.integers(min_value=3, max_value=200))
@example(49.0, 1.0, 3)
def test_the_bang_clock_shares_the_energy_equally(m1: float, m2: float, ticks: int) -> None:
    """Clock hands spread evenly round the energy circle of Fig. 5.2(b) give each ball half
    the energy on average, for any number of ticks; so the mean squares of the velocities are
    in the inverse ratio of the masses, v2_rms / v1_rms = sqrt(m1/m2) (5.14)."""
    assert abs(clock_energy_share(ticks) - 0.5) <= 1e-12
    ratio = rms_speed_ratio(m1, m2)
    assert math.isclose(ratio * ratio, m1 / m2, rel_tol=4 * REL)
    assert math.isclose(ratio * rms_speed_ratio(m2, m1), 1, rel_tol=4 * REL)
