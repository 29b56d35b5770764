"""Laws of slope geometry and trigonometry (mechmodel.geometry): chapter 1.

Floats are compared within 1e-12 of the sum of the magnitudes involved; Fraction inputs must
give exact equality; mpmath inputs are held to their own precision.
"""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from checks.properties.strategies import (
    acute_angles,
    angles,
    fraction_lengths,
    fraction_slopes,
    lengths,
    molecule_sizes,
    oblique_angles,
    secants,
    slopes,
    unit_interval_values,
)
from mechmodel.geometry import (
    arc_chord_excess,
    arc_length,
    arc_solutions,
    arcsec_construction,
    arctan_solutions,
    chord,
    clock_angle,
    complement,
    degrees_of_freedom,
    golden_ratio,
    hypotenuse,
    minkowski_slope,
    newton_slope,
    percent_grade,
    rescaled_slope,
    slope_angle,
    thales_angle,
    thales_means,
    total_sector_area,
    turn_angle,
    unit_circle_segments,
    vibration_formula,
    whirling_rectangles,
)

pytestmark = pytest.mark.properties
REL = 1e-12


def close(x: float, y: float, *magnitudes: float) -> bool:
    """|x - y| within REL of the magnitudes involved (x and y themselves, and any others)."""
    return abs(x - y) <= REL * (abs(x) + abs(y) + sum(abs(m) for m in magnitudes))


# -- the six segments of Fig. 1.4 -------------------------------------------------------------
@given(angles(), lengths())
@example(1.0, 1.0)  # Fig. 1.4b
def test_base_and_altitude_lie_on_the_circle(sigma: float, r: float) -> None:
    """(r cos σ)^2 + (r sin σ)^2 = r^2: the base and altitude are the legs of the right
    triangle with hypotenuse r (Fig. 1.4a; Pythagoras, line 1387)."""
    s = unit_circle_segments(sigma, r)
    assert close(s.base**2 + s.altitude**2, r**2)


@given(oblique_angles(), lengths())
def test_secant_is_hypotenuse_of_radius_and_tangent(sigma: float, r: float) -> None:
    """sec^2 σ = 1 + tan^2 σ: the secant runs from the centre to the end of the tangent, which
    is normal to the radius (Fig. 1.4b)."""
    s = unit_circle_segments(sigma, r)
    assert close(s.secant**2, r**2 + s.tangent**2)


@given(oblique_angles(), lengths())
def test_cosecant_is_hypotenuse_of_radius_and_cotangent(sigma: float, r: float) -> None:
    """csc^2 σ = 1 + cot^2 σ: the same law on the y-axis side (Fig. 1.4b)."""
    s = unit_circle_segments(sigma, r)
    assert close(s.cosecant**2, r**2 + s.cotangent**2)


@given(oblique_angles())
def test_tangent_and_cotangent_are_inverse(sigma: float) -> None:
    """tan σ cot σ = 1: a slope in Fig. 1.2a is the inverse slope in Fig. 1.2b (line 1168)."""
    s = unit_circle_segments(sigma)
    assert close(s.tangent * s.cotangent, 1.0)


@given(angles())
@example(1.0)
def test_sine_is_cosine_of_the_complement(sigma: float) -> None:
    """sin σ = cos σc with σc = π/2 - σ: each ratio switches place with its co-ratio
    (line 1175)."""
    s = unit_circle_segments(sigma)
    c = unit_circle_segments(complement(sigma))
    assert close(s.altitude, c.base, sigma, math.pi)


@given(oblique_angles())
def test_tangent_is_cotangent_of_the_complement(sigma: float) -> None:
    """tan σ = cot σc = 1 / tan σc (line 1175)."""
    s = unit_circle_segments(sigma)
    c = unit_circle_segments(complement(sigma))
    assert close(s.tangent, c.cotangent)


@given(angles())
def test_complement_of_the_complement_is_the_angle(sigma: float) -> None:
    """(σc)c = σ: complementing twice swaps the plots of Fig. 1.2 back (line 1174)."""
    assert close(complement(complement(sigma)), sigma, math.pi)


@given(acute_angles())
def test_tangent_line_is_normal_to_the_radius(sigma: float) -> None:
    """The tangent segment's slope angle is σ - π/2 = -σc: normal to the radius at slope angle
    σ, so the two slopes multiply to -1 (Figs. 1.4b and 1.5)."""
    s = unit_circle_segments(sigma)
    assert close(math.tan(s.tangent_slope_angle) * math.tan(sigma), -1.0)


@given(slopes())
def test_slope_angle_has_the_slope_for_tangent(m: float) -> None:
    """tan(arctan m) = m: the slope angle of a slope-m line (line 934: 45° for slope 1/1)."""
    assert close(math.tan(slope_angle(m)), m)


@given(slopes())
def test_grade_is_slope_over_incline(m: float) -> None:
    """Percent grade 100 sin σ of a road of slope m = tan σ is 100 m / √(1 + m^2): altitude
    gained over distance travelled (line 1150), never above 100 %."""
    grade = percent_grade(slope_angle(m))
    assert close(grade, m / math.sqrt(1 + m * m), 1.0)
    assert abs(grade) <= 1


# -- arc functions and their two solutions (Fig. 1.7) ------------------------------------------
@given(unit_interval_values())
@example(0.5)  # Fig. 1.7a
def test_both_arcsine_solutions_give_the_value(a: float) -> None:
    """sin σ1 = sin σ2 = a for σ1 = sin⁻¹(a) and its x-reflection σ2 = π - σ1 (Fig. 1.7a)."""
    sol = arc_solutions("sin", a)
    assert close(math.sin(sol.first), a, math.pi)
    assert close(math.sin(sol.second), a, math.pi)


@given(unit_interval_values())
@example(0.5)  # Fig. 1.7b
def test_both_arccosine_solutions_give_the_value(b: float) -> None:
    """cos σ1 = cos σ2 = b for σ1 = cos⁻¹(b) and its y-reflection σ2 = -σ1 (Fig. 1.7b)."""
    sol = arc_solutions("cos", b)
    assert close(math.cos(sol.first), b, math.pi)
    assert close(math.cos(sol.second), b, math.pi)


@given(slopes())
@example(0.5)  # Fig. 1.7c
def test_both_arctangent_solutions_give_the_value(t: float) -> None:
    """tan σ1 = tan σ2 = t for σ1 = tan⁻¹(t) and the antipodal σ2 = σ1 - π (Fig. 1.7c); the
    check is sin σ = t cos σ, which stays finite."""
    sol = arc_solutions("tan", t)
    for sigma in (sol.first, sol.second):
        assert close(math.sin(sigma), t * math.cos(sigma), 1.0 + abs(t))


@given(slopes(), lengths())
@example(0.5, 1.0)  # Fig. 1.7c: a = 0.5, b = 1
def test_atan2_solutions_are_antipodal(a: float, b: float) -> None:
    """atan2(a, b) and atan2(-a, -b) point to (b, a) and (-b, -a): both have slope a/b and
    they differ by half a turn, ±180° (line 1603, line 1832)."""
    sol = arctan_solutions(a, b)
    assert close(abs(sol.separation), math.pi)
    r = math.hypot(a, b)
    assert close(r * math.cos(sol.first), b, r)
    assert close(r * math.sin(sol.first), a, r)


@given(unit_interval_values())
def test_calculator_answers_lie_in_the_principal_range(a: float) -> None:
    """A calculator's sin⁻¹ gives -π/2 to +π/2 and ignores the obtuse solution, whose range is
    the rest of the turn (lines 1834-1846)."""
    sol = arc_solutions("sin", a)
    assert -math.pi / 2 <= sol.first <= math.pi / 2
    assert not -math.pi / 2 < sol.second < math.pi / 2


# -- circles, arcs and chords (Figs. 1.3 and 1.6) -----------------------------------------------
@given(lengths())
def test_half_turn_sweeps_the_whole_pie(r: float) -> None:
    """The book's total sector area r^2 σ is π r^2 for σ = π (line 1142) and half of it for a
    quarter turn (Fig. 1.3b)."""
    assert close(total_sector_area(turn_angle(Fraction(1, 2)), r), math.pi * r * r)
    assert close(total_sector_area(turn_angle(Fraction(1, 4)), r), math.pi * r * r / 2)


@given(st.floats(min_value=1e-3, max_value=2 * math.pi - 1e-3), lengths())
def test_arc_is_longer_than_its_chord(sigma: float, r: float) -> None:
    """r σ > 2 r sin(σ/2) for 0 < σ < 2π: the straight line is the shortest path (line 1436:
    the π/3 arc is 4.72 % longer than its chord)."""
    assert arc_length(sigma, r) > chord(sigma, r)
    assert arc_chord_excess(sigma) > 0


@given(lengths())
def test_chord_of_sixty_degrees_is_the_radius(r: float) -> None:
    """The chord under a π/3 arc equals the radius: the equilateral triangle of Euclid's
    construction (lines 1433-1435, Fig. 1.6b)."""
    assert close(chord(math.pi / 3, r), r)


@given(st.integers(min_value=0, max_value=48), st.integers(min_value=1, max_value=48))
@example(3, 12)  # exercise 3: 3 hours of the 12-point clock is 90°
def test_clock_angle_is_the_fraction_of_a_turn(hours: int, per_turn: int) -> None:
    """h hours of an N-hour clock sweep h/N of a turn (exercise 3)."""
    assert close(clock_angle(hours, per_turn), turn_angle(Fraction(hours, per_turn)))


# -- slopes of velocity lines (Fig. 1.2) --------------------------------------------------------
@given(fraction_slopes(), fraction_lengths(), fraction_lengths())
@example(Fraction(10), Fraction(1, 10), Fraction(1, 10))  # the VW: 10 mph, 0.1 mile per 6 s
def test_minkowski_and_newton_slopes_are_inverse(v: Fraction, sx: Fraction, sy: Fraction) -> None:
    """A velocity line's slope on the time vs. space plot is the inverse of its slope on the
    space vs. time plot (line 1080; 6/1 against 1/6 for the VW), exactly."""
    assert minkowski_slope(v, sx, sy) * newton_slope(v, sx, sy) == 1


@given(
    fraction_slopes(),
    fraction_lengths(),
    fraction_lengths(),
    fraction_lengths(),
    fraction_lengths(),
)
def test_rescalings_compose(
    m: Fraction, fx1: Fraction, fy1: Fraction, fx2: Fraction, fy2: Fraction
) -> None:
    """Rescaling by (f_x1, f_y1) and then (f_x2, f_y2) is rescaling by (f_x1 f_x2, f_y1 f_y2):
    miles to feet and minutes to seconds in steps or at once (lines 1087-1094), exactly."""
    twice = rescaled_slope(rescaled_slope(m, fx1, fy1), fx2, fy2)
    assert twice == rescaled_slope(m, fx1 * fx2, fy1 * fy2)


# -- whirling rectangles and the golden ratio (Figs. 1.5 and 1.10) -------------------------------
@given(acute_angles(), st.integers(min_value=2, max_value=12))
@example(1.0, 5)  # Fig. 1.5
def test_whirling_sequence_is_geometric(sigma: float, terms: int) -> None:
    """Each segment of the whirling sequence {tan σ, 1, cot σ, cot^2 σ, ...} is the one before
    shrunk by cot σ: a geometric (power) sequence (lines 1390-1391)."""
    w = whirling_rectangles(sigma, terms)
    for before, after in zip(w.lengths, w.lengths[1:], strict=False):
        assert close(after, before * w.scale_factor)


@given(st.integers(min_value=3, max_value=20))
def test_golden_whirling_rectangles_are_whirling_squares(terms: int) -> None:
    """At the golden slope, tan σ = G+, the scale factor cot σ is 1/G+ = -G- and each
    rectangle is a square plus the next rectangle: L_k = L_(k+1) + L_(k+2) (Fig. 1.10c)."""
    g = golden_ratio()
    w = whirling_rectangles(math.atan(g.plus), terms)
    assert close(w.scale_factor, -g.minus)
    for k in range(terms - 2):
        assert close(w.lengths[k], w.lengths[k + 1] + w.lengths[k + 2])


@given(lengths())
def test_golden_means_are_the_roots_of_g_squared_is_g_plus_one(u: float) -> None:
    """G± = u (1 ± √5)/2 solve G^2 = u G + u^2: their sum is u and product -u^2, so G- is
    -1/G+ for the unit square (Figs. 1.9b and 1.10)."""
    g = golden_ratio(u)
    assert close(g.plus + g.minus, u, g.plus, g.minus)
    assert close(g.plus * g.minus, -u * u)
    assert close(g.plus**2, u * g.plus + u * u)


def test_golden_means_in_mpmath_precision() -> None:
    """With mpmath the golden means hold G+^2 = G+ + 1 to the working precision."""
    with mpmath.workdps(50):
        g = golden_ratio(mpmath.mpf(1))
        assert abs(g.plus**2 - g.plus - 1) < mpmath.mpf(10) ** -45


# -- means (Thales, Fig. 1.9) and the arc-secant (Fig. 1.8) -------------------------------------
@given(lengths(), lengths())
@example(1.0, 5.0)  # Fig. 1.9
def test_means_are_ordered(a: float, b: float) -> None:
    """Arithmetic >= geometric >= harmonic mean: the radius of Thales' circle is never shorter
    than the half-chord √(ab) (Fig. 1.9a)."""
    m = thales_means(a, b)
    assert m.arithmetic >= m.geometric * (1 - REL)
    assert m.geometric >= m.harmonic * (1 - REL)


@given(fraction_lengths(), fraction_lengths())
def test_thales_right_triangle_exactly(a: Fraction, b: Fraction) -> None:
    """AM^2 - DM^2 = ab = GM^2 and AM HM = ab: the half-chord √(ab), the centre offset
    (a - b)/2 and the radius (a + b)/2 form a right triangle (Fig. 1.9a), exactly."""
    m = thales_means(a, b)
    assert m.arithmetic**2 - m.difference**2 == a * b
    assert m.arithmetic * m.harmonic == a * b


@given(lengths(), lengths())
def test_angle_in_a_semicircle_is_right(a: float, b: float) -> None:
    """Thales' theorem: the apex over the diameter a + b sees it at π/2, whatever a and b
    (Fig. 1.9a, the 90° label)."""
    assert close(thales_angle(a, b), math.pi / 2)


@given(secants())
@example(3.0)  # exercise 2: sec⁻¹ 3, tangent √8
def test_arcsecant_construction(s: float) -> None:
    """The tangent from x = s to the unit circle is √(ab) with a = s - 1, b = s + 1, so its
    square is s^2 - 1, and the angle it makes has secant s (Fig. 1.8)."""
    c = arcsec_construction(s)
    assert close(c.tangent**2, s * s - 1, 1.0)
    assert close(1 / math.cos(c.angle), s)


# -- right triangles and degrees of freedom ------------------------------------------------------
@given(st.integers(min_value=1, max_value=10**5), st.integers(min_value=1, max_value=10**5))
@example(2, 1)  # the 3-4-5 triangle
def test_pythagorean_triples_are_exact(m: int, n: int) -> None:
    """Euclid's triples (m^2 - n^2, 2mn, m^2 + n^2) have integer hypotenuse: the 3-4-5
    triangle of line 1585 is m = 2, n = 1."""
    m, n = max(m, n) + 1, min(m, n)
    assert hypotenuse(m * m - n * n, 2 * m * n) == m * m + n * n


@given(molecule_sizes())
def test_degrees_of_freedom_add_up(atoms: int) -> None:
    """An N-atom molecule has 3N degrees of freedom: 3 translational, 3 rotational and
    3N - 6 vibrational (Landscape 1.2)."""
    formula = vibration_formula(3, 3)
    assert degrees_of_freedom([3, 3, formula.modes(atoms)]) == 3 * atoms


@given(angles())
def test_unit_circle_in_mpmath_precision(sigma: float) -> None:
    """With an mpmath angle the segments keep mpmath's precision: cos^2 + sin^2 = 1 to 45
    digits (Fig. 1.4)."""
    with mpmath.workdps(50):
        s = unit_circle_segments(mpmath.mpf(sigma))
        assert abs(s.base**2 + s.altitude**2 - 1) < mpmath.mpf(10) ** -45
