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

from checks.properties.closeness import assert_close, magnitude
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
    complement_segments,
    degrees_of_freedom,
    doubled_clock_points,
    function_range,
    golden_ratio,
    grid_speed,
    hypotenuse,
    minkowski_slope,
    newton_slope,
    precision_parts,
    principal_range,
    quadrant_fraction,
    regular_polygon_interior_angle,
    rescaled_slope,
    right_triangle_sides,
    slope,
    slope_angle,
    thales_angle,
    thales_means,
    total_sector_area,
    turn_angle,
    unit_circle_segments,
    vibration_formula,
    vibrational_modes,
    whirling_rectangles,
)

pytestmark = pytest.mark.properties
REL = 1e-12


# -- the six segments of Fig. 1.4 -------------------------------------------------------------
@given(angles(), lengths())
@example(1.0, 1.0)  # Fig. 1.4b
def test_base_and_altitude_lie_on_the_circle(sigma: float, r: float) -> None:
    """(r cos σ)^2 + (r sin σ)^2 = r^2: the base and altitude are the legs of the right
    triangle with hypotenuse r (Fig. 1.4a; Pythagoras, line 1387)."""
    s = unit_circle_segments(sigma, r)
    assert_close(s.base**2 + s.altitude**2, r**2)


@given(oblique_angles(), lengths())
def test_secant_is_hypotenuse_of_radius_and_tangent(sigma: float, r: float) -> None:
    """sec^2 σ = 1 + tan^2 σ: the secant runs from the centre to the end of the tangent, which
    is normal to the radius (Fig. 1.4b)."""
    s = unit_circle_segments(sigma, r)
    assert_close(s.secant**2, r**2 + s.tangent**2)


@given(oblique_angles(), lengths())
def test_cosecant_is_hypotenuse_of_radius_and_cotangent(sigma: float, r: float) -> None:
    """csc^2 σ = 1 + cot^2 σ: the same law on the y-axis side (Fig. 1.4b)."""
    s = unit_circle_segments(sigma, r)
    assert_close(s.cosecant**2, r**2 + s.cotangent**2)


@given(oblique_angles())
def test_tangent_and_cotangent_are_inverse(sigma: float) -> None:
    """tan σ cot σ = 1: a slope in Fig. 1.2a is the inverse slope in Fig. 1.2b (line 1168)."""
    s = unit_circle_segments(sigma)
    assert_close(s.tangent * s.cotangent, 1.0)


@given(lengths())
def test_on_the_x_axis_the_tangent_vanishes_and_the_cotangent_is_infinite(r: float) -> None:
    """At σ = 0 the radius lies along the x-axis (Fig. 1.4b turned down to the axis): the
    tangent segment shrinks to 0 and the secant point is the circle's own point, sec = r,
    while the cotangent and cosecant lines run parallel to the y-axis and never meet it."""
    s = unit_circle_segments(0.0, r)
    assert (s.base, s.altitude, s.tangent, s.secant) == (r, 0, 0, r)
    for name in ("cotangent", "cosecant"):
        with pytest.raises(ValueError, match="infinite"):
            getattr(s, name)


@given(angles())
@example(1.0)
def test_sine_is_cosine_of_the_complement(sigma: float) -> None:
    """sin σ = cos σc with σc = π/2 - σ: each ratio switches place with its co-ratio
    (line 1175)."""
    s = unit_circle_segments(sigma)
    c = unit_circle_segments(complement(sigma))
    assert_close(s.altitude, c.base, scale=magnitude(s.altitude, c.base, sigma, math.pi))


@given(oblique_angles())
def test_tangent_is_cotangent_of_the_complement(sigma: float) -> None:
    """tan σ = cot σc = 1 / tan σc (line 1175)."""
    s = unit_circle_segments(sigma)
    c = unit_circle_segments(complement(sigma))
    assert_close(s.tangent, c.cotangent)


@given(oblique_angles(), lengths())
@example(1.0, 1.0)
def test_the_complement_swaps_each_ratio_with_its_co_ratio(sigma: float, r: float) -> None:
    """The segments of σc = π/2 - σ are those of σ with the legs swapped: base and altitude,
    tangent and cotangent, secant and cosecant trade places, so tan σc = cot σ = 1/tan σ
    (line 1175)."""
    s = unit_circle_segments(sigma, r)
    c = complement_segments(sigma, r)
    assert_close(c.base, s.altitude, scale=magnitude(c.base, s.altitude, r * sigma, r * math.pi))
    assert_close(c.altitude, s.base, scale=magnitude(c.altitude, s.base, r * sigma, r * math.pi))
    assert_close(c.tangent, s.cotangent)
    assert_close(c.cotangent, s.tangent)
    assert_close(c.secant, s.cosecant)
    assert_close(c.tangent * s.tangent, r * r)


@given(angles())
def test_complement_of_the_complement_is_the_angle(sigma: float) -> None:
    """(σc)c = σ: complementing twice swaps the plots of Fig. 1.2 back (line 1174)."""
    twice = complement(complement(sigma))
    assert_close(twice, sigma, scale=magnitude(twice, sigma, math.pi))


@given(acute_angles())
def test_tangent_line_is_normal_to_the_radius(sigma: float) -> None:
    """The tangent segment's slope angle is σ - π/2 = -σc: normal to the radius at slope angle
    σ, so the two slopes multiply to -1 (Figs. 1.4b and 1.5)."""
    s = unit_circle_segments(sigma)
    assert_close(math.tan(s.tangent_slope_angle) * math.tan(sigma), -1.0)


@given(slopes())
def test_slope_angle_has_the_slope_for_tangent(m: float) -> None:
    """tan(arctan m) = m: the slope angle of a slope-m line (line 934: 45° for slope 1/1)."""
    assert_close(math.tan(slope_angle(m)), m)


# -- arc functions and their two solutions (Fig. 1.7) ------------------------------------------
@given(unit_interval_values())
@example(0.5)  # Fig. 1.7a
@example(-1.0)  # the ends of the range of sine
@example(1.0)
def test_both_arcsine_solutions_give_the_value(a: float) -> None:
    """sin σ1 = sin σ2 = a for σ1 = sin⁻¹(a) and its x-reflection σ2 = π - σ1 (Fig. 1.7a): the
    reflection keeps the altitude and reverses the base."""
    sol = arc_solutions("sin", a)
    sin1, sin2 = math.sin(sol.first), math.sin(sol.second)
    cos1, cos2 = math.cos(sol.first), math.cos(sol.second)
    assert_close(sin1, a, scale=magnitude(sin1, a, math.pi))
    assert_close(sin2, a, scale=magnitude(sin2, a, math.pi))
    assert_close(cos2, -cos1, scale=magnitude(cos2, cos1, math.pi))


@given(unit_interval_values())
@example(0.5)  # Fig. 1.7b
@example(-1.0)  # the ends of the range of cosine
@example(1.0)
def test_both_arccosine_solutions_give_the_value(b: float) -> None:
    """cos σ1 = cos σ2 = b for σ1 = cos⁻¹(b) and its y-reflection σ2 = -σ1 (Fig. 1.7b): the
    reflection keeps the base and reverses the altitude."""
    sol = arc_solutions("cos", b)
    sin1, sin2 = math.sin(sol.first), math.sin(sol.second)
    cos1, cos2 = math.cos(sol.first), math.cos(sol.second)
    assert_close(cos1, b, scale=magnitude(cos1, b, math.pi))
    assert_close(cos2, b, scale=magnitude(cos2, b, math.pi))
    assert_close(sin2, -sin1, scale=magnitude(sin2, sin1, math.pi))


@given(
    st.floats(min_value=1.0, max_value=2.0, exclude_min=True),
    st.sampled_from(("sin", "cos")),
    st.sampled_from((-1, 1)),
)
def test_no_arc_reaches_beyond_the_unit_circle(x: float, function: str, sign: int) -> None:
    """The altitude sin σ and the base cos σ of a point of the unit circle run from -1 to +1
    (Fig. 1.7a-b, lines 1821-1830), so sin σ = x and cos σ = x have no real solution for
    |x| > 1."""
    r = function_range(function)
    assert (r.lower, r.upper) == (-1, 1)
    with pytest.raises(ValueError, match="no real solution"):
        arc_solutions(function, sign * x)


@given(slopes())
@example(0.5)  # Fig. 1.7c
def test_both_arctangent_solutions_give_the_value(t: float) -> None:
    """tan σ1 = tan σ2 = t for σ1 = tan⁻¹(t) and the antipodal σ2 = σ1 - π (Fig. 1.7c); the
    check is sin σ = t cos σ, which stays finite."""
    sol = arc_solutions("tan", t)
    for sigma in (sol.first, sol.second):
        sine, t_cosine = math.sin(sigma), t * math.cos(sigma)
        assert_close(sine, t_cosine, scale=magnitude(sine, t_cosine, 1.0 + abs(t)))
    assert_close(sol.separation, -math.pi)  # the antipode, half a turn back


@given(slopes(), lengths())
@example(0.5, 1.0)  # Fig. 1.7c: a = 0.5, b = 1
def test_atan2_solutions_are_antipodal(a: float, b: float) -> None:
    """atan2(a, b) and atan2(-a, -b) point to (b, a) and (-b, -a): both have slope a/b and
    they differ by half a turn, ±180° (line 1603, line 1832)."""
    sol = arctan_solutions(a, b)
    assert_close(abs(sol.separation), math.pi)
    r = math.hypot(a, b)
    assert_close(r * math.cos(sol.first), b, scale=magnitude(r * math.cos(sol.first), b, r))
    assert_close(r * math.sin(sol.first), a, scale=magnitude(r * math.sin(sol.first), a, r))
    on_axes = [(s.first, s.second) for s in (arctan_solutions(1, 0), arctan_solutions(0, 1))]
    assert on_axes == [(math.pi / 2, -math.pi / 2), (0, math.pi)]
    with pytest.raises(ValueError, match="no direction"):
        arctan_solutions(0, 0)


@given(unit_interval_values(), slopes())
@example(-1.0, 0.0)
def test_the_principal_ranges_are_spanned_by_the_calculator_answers(a: float, t: float) -> None:
    """sin⁻¹ and tan⁻¹ answer from -π/2 to +π/2, cos⁻¹ from 0 to π and atan2 over the whole
    turn, -π to +π (Fig. 1.7c, lines 1834-1846): the ends are the answers at the extreme
    arguments, and every answer lies in between. The calculator ignores the other solution of
    sin σ = a, whose range is the rest of the turn."""
    ranges = {f: principal_range(f) for f in ("sin", "cos", "tan", "atan2")}
    ends = {f: (r.lower, r.upper) for f, r in ranges.items()}
    assert ends["sin"] == (math.asin(-1), math.asin(1))
    assert ends["cos"] == (math.acos(1), math.acos(-1))
    assert ends["tan"] == (math.atan(-math.inf), math.atan(math.inf))
    assert ends["atan2"] == (math.atan2(-0.0, -1), math.atan2(0.0, -1))
    for f, value in (("sin", a), ("cos", a), ("tan", t)):
        assert ranges[f].lower <= arc_solutions(f, value).first <= ranges[f].upper
    assert not -math.pi / 2 < arc_solutions("sin", a).second < math.pi / 2


# -- circles, arcs and chords (Figs. 1.3 and 1.6) -----------------------------------------------
@given(lengths())
def test_half_turn_sweeps_the_whole_pie(r: float) -> None:
    """The book's total sector area r^2 σ is π r^2 for σ = π (line 1142) and half of it for a
    quarter turn (Fig. 1.3b)."""
    assert_close(total_sector_area(turn_angle(Fraction(1, 2)), r), math.pi * r * r)
    assert_close(total_sector_area(turn_angle(Fraction(1, 4)), r), math.pi * r * r / 2)


@given(st.floats(min_value=1e-3, max_value=2 * math.pi - 1e-3), lengths())
def test_arc_is_longer_than_its_chord(sigma: float, r: float) -> None:
    """r σ > 2 r sin(σ/2) for 0 < σ < 2π: the straight line is the shortest path (line 1436:
    the π/3 arc is 4.72 % longer than its chord)."""
    assert arc_length(sigma, r) > chord(sigma, r)
    excess = arc_chord_excess(sigma)
    assert excess > 0
    assert_close(excess + 1, arc_length(sigma, r) / chord(sigma, r))  # the same on every circle
    assert_close(total_sector_area(sigma, r), arc_length(sigma, r) * r)
    assert_close(arc_length(turn_angle(1), r), 2 * math.pi * r)  # the circumference


def test_the_sixty_degree_arc_is_four_point_seven_percent_longer() -> None:
    """The π/3 arc over the chord RX, of length r, is π/3 - 1 = 4.72 % longer (Fig. 1.6b,
    lines 1436-1440)."""
    excess = arc_chord_excess(math.pi / 3)
    assert_close(excess, math.pi / 3 - 1, scale=magnitude(excess, math.pi / 3 - 1, 1.0))


@given(lengths())
def test_chord_of_sixty_degrees_is_the_radius(r: float) -> None:
    """The chord under a π/3 arc equals the radius: the equilateral triangle of Euclid's
    construction (lines 1433-1435, Fig. 1.6b)."""
    assert_close(chord(math.pi / 3, r), r)


@given(st.integers(min_value=0, max_value=48), st.integers(min_value=1, max_value=48))
@example(3, 12)  # exercise 3: 3 hours of the 12-point clock is 90°
@example(1, 1)  # a one-hour clock: an hour is the whole turn
def test_clock_angle_is_the_fraction_of_a_turn(hours: int, per_turn: int) -> None:
    """h hours of an N-hour clock sweep h/N of a turn (exercise 3); bisecting every hour arc
    doubles the points (the 24-hour clock from the 12-point one), and 2h of the new hours
    sweep the same angle."""
    angle = clock_angle(hours, per_turn)
    assert_close(angle, turn_angle(Fraction(hours, per_turn)))
    doubled = doubled_clock_points(per_turn)
    assert doubled == 2 * per_turn
    assert_close(clock_angle(2 * hours, doubled), angle)


@given(st.integers(min_value=3, max_value=1000))
@example(3)  # the equilateral triangle of Euclid's construction: 60 degrees (Fig. 1.6)
def test_the_outer_angles_of_a_regular_polygon_make_one_turn(n: int) -> None:
    """Walking round a regular n-gon turns by π minus the interior angle at each corner, and
    by one whole turn in all: the interior angle is (n - 2) π / n, π/3 for the triangle of the
    60 degree slope (line 1431, Fig. 1.6)."""
    interior = regular_polygon_interior_angle(n)
    exterior = n * (math.pi - interior)
    assert_close(exterior, turn_angle(1), scale=magnitude(exterior, turn_angle(1), n * math.pi))


@given(st.integers(min_value=0, max_value=4))
@example(4)
def test_each_quadrant_is_a_quarter_turn(q: int) -> None:
    """The four quadrants are quarter turns (Fig. 1.3b): q of them hold q/4 of all directions
    (line 1818: never answering in the 3rd quadrant is wrong 25 % of the time), all four the
    whole turn, and there is no fifth."""
    assert_close(turn_angle(quadrant_fraction(q)), q * complement(0))
    assert quadrant_fraction(4) == 1
    with pytest.raises(ValueError, match="four quadrants"):
        quadrant_fraction(5)


# -- slopes of velocity lines (Fig. 1.2) --------------------------------------------------------
@given(fraction_slopes(), fraction_lengths(), fraction_lengths())
@example(Fraction(10), Fraction(1, 10), Fraction(1, 10))  # the VW: 10 mph, 0.1 mile per 6 s
def test_minkowski_and_newton_slopes_are_inverse(v: Fraction, sx: Fraction, sy: Fraction) -> None:
    """A velocity line's slope on the time vs. space plot is the inverse of its slope on the
    space vs. time plot (line 1080; 6/1 against 1/6 for the VW), exactly. The 1:1 line covers
    one square s_x per square s_y (line 1084), so speed v climbs v s_y / s_x squares."""
    assert minkowski_slope(v, sx, sy) * newton_slope(v, sx, sy) == 1
    assert grid_speed(sx, sy) * sy == sx
    assert newton_slope(v, sx, sy) * sx == v * sy


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


@given(fraction_slopes(), fraction_lengths(), fraction_lengths())
@example(Fraction(1), Fraction(5280), Fraction(60))  # 1 mile per minute is 88 feet per second
def test_a_slope_is_altitude_over_base_and_grows_with_the_distance_scale(
    m: Fraction, fx: Fraction, fy: Fraction
) -> None:
    """A triangle of base b and slope m has altitude m b (Fig. 1.2, "= a/b"); rescaling the
    distance unit by f_x and the time unit by f_y multiplies every slope by f_x / f_y, so equal
    factors change nothing (lines 1087-1094: slope 1 in miles per minute is 88 in ft/s)."""
    assert slope(m * fx, fx) == m
    assert rescaled_slope(m, fx, fy) * fy == m * fx
    assert rescaled_slope(m, fx, fx) == m


# -- whirling rectangles and the golden ratio (Figs. 1.5 and 1.10) -------------------------------
@given(acute_angles(), st.integers(min_value=2, max_value=12))
@example(1.0, 5)  # Fig. 1.5
@example(1.0, 2)  # the shortest sequence: tan σ and 1
def test_whirling_sequence_is_geometric(sigma: float, terms: int) -> None:
    """Each segment of the whirling sequence {tan σ, 1, cot σ, cot^2 σ, ...} is the one before
    shrunk by cot σ: a geometric (power) sequence (lines 1390-1391)."""
    w = whirling_rectangles(sigma, terms)
    for before, after in zip(w.lengths, w.lengths[1:], strict=False):
        assert_close(after, before * w.scale_factor)
    assert len(w.lengths) == terms
    assert_close(w.lengths[0], math.tan(sigma))
    assert w.lengths[1] == 1
    assert_close(w.rotation, math.pi / 2)  # each is the one before turned a quarter turn
    tangent_line = sigma - math.pi / 2  # the first segment lies along the tangent line
    assert_close(w.first_angle, tangent_line, scale=magnitude(w.first_angle, tangent_line, math.pi))
    assert len(whirling_rectangles(sigma).lengths) == 5  # Fig. 1.5


@given(st.integers(min_value=3, max_value=20))
def test_golden_whirling_rectangles_are_whirling_squares(terms: int) -> None:
    """At the golden slope, tan σ = G+, the scale factor cot σ is 1/G+ = -G- and each
    rectangle is a square plus the next rectangle: L_k = L_(k+1) + L_(k+2) (Fig. 1.10c)."""
    g = golden_ratio()
    w = whirling_rectangles(math.atan(g.plus), terms)
    assert_close(w.scale_factor, -g.minus)
    for k in range(terms - 2):
        assert_close(w.lengths[k], w.lengths[k + 1] + w.lengths[k + 2])


@given(lengths())
def test_golden_means_are_the_roots_of_g_squared_is_g_plus_one(u: float) -> None:
    """G± = u (1 ± √5)/2 solve G^2 = u G + u^2: their sum is u and product -u^2, so G- is
    -1/G+ for the unit square (Figs. 1.9b and 1.10)."""
    g = golden_ratio(u)
    assert_close(g.plus + g.minus, u, scale=magnitude(g.plus + g.minus, u, g.plus, g.minus))
    assert_close(g.plus * g.minus, -u * u)
    assert_close(g.plus**2, u * g.plus + u * u)


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
    assert_close(m.geometric**2, a * b)


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
    assert_close(thales_angle(a, b), math.pi / 2)


@given(secants())
@example(3.0)  # exercise 2: sec⁻¹ 3, tangent √8
@example(1.0)  # on the circle: no tangent, angle 0
def test_arcsecant_construction(s: float) -> None:
    """The tangent from x = s to the unit circle is √(ab) with a = s - 1, b = s + 1, so its
    square is s^2 - 1, and the angle it makes has secant s (Fig. 1.8)."""
    c = arcsec_construction(s)
    assert_close(c.tangent**2, s * s - 1, scale=magnitude(c.tangent**2, s * s - 1, 1.0))
    assert_close(1 / math.cos(c.angle), s)


# -- right triangles and degrees of freedom ------------------------------------------------------
@given(st.integers(min_value=1, max_value=10**5), st.integers(min_value=1, max_value=10**5))
@example(2, 1)  # the 3-4-5 triangle
def test_pythagorean_triples_are_exact(m: int, n: int) -> None:
    """Euclid's triples (m^2 - n^2, 2mn, m^2 + n^2) have integer hypotenuse: the 3-4-5
    triangle of line 1585 is m = 2, n = 1."""
    m, n = max(m, n) + 1, min(m, n)
    assert hypotenuse(m * m - n * n, 2 * m * n) == m * m + n * n


@given(acute_angles(), lengths())
@example(math.pi / 3, 1.0)  # the 30-60-90 triangle, (b : a : r) = (1 : √3 : 2) (line 1584)
def test_the_right_triangle_of_a_slope_angle(sigma: float, b: float) -> None:
    """The right triangle of slope angle σ on base b has altitude b tan σ, so its slope is
    tan σ, and hypotenuse b sec σ, with a^2 + b^2 = r^2 (Fig. 1.4b; Pythagoras, line 1387)."""
    t = right_triangle_sides(sigma, b)
    assert t.base == b
    assert_close(slope(t.altitude, t.base), math.tan(sigma))
    assert_close(hypotenuse(t.altitude, t.base), t.hypotenuse)


@given(molecule_sizes())
@example(3)  # water: 3 vibrations
def test_degrees_of_freedom_add_up(atoms: int) -> None:
    """An N-atom molecule has 3N degrees of freedom: 3 translational, 3 rotational and
    3N - 6 vibrational (Landscape 1.2)."""
    formula = vibration_formula(3, 3)
    assert degrees_of_freedom([3, 3, formula.modes(atoms)]) == 3 * atoms


@given(
    molecule_sizes(), st.integers(min_value=1, max_value=4), st.integers(min_value=0, max_value=6)
)
@example(3, 3, 3)  # water: 3 vibrations
def test_vibrations_are_what_the_rigid_motions_leave(
    atoms: int, translational: int, rotational: int
) -> None:
    """N atoms moving in t dimensions have t N coordinates; the rigid molecule's t translations
    and r rotations take away t + r of them and the rest vibrate: each added atom brings t more
    vibrations (Landscape 1.2: 3N - 6 for t = r = 3)."""
    modes = vibrational_modes(atoms, translational, rotational)
    assert modes + degrees_of_freedom([translational, rotational]) == translational * atoms
    assert vibrational_modes(atoms + 1, translational, rotational) - modes == translational


@given(angles())
def test_unit_circle_in_mpmath_precision(sigma: float) -> None:
    """With an mpmath angle the segments keep mpmath's precision: cos^2 + sin^2 = 1 to 45
    digits (Fig. 1.4)."""
    with mpmath.workdps(50):
        s = unit_circle_segments(mpmath.mpf(sigma))
        assert abs(s.base**2 + s.altitude**2 - 1) < mpmath.mpf(10) ** -45


@given(st.integers(min_value=0, max_value=30))
@example(3)  # 1 part in 1,000 (line 1438)
def test_each_order_of_precision_resolves_ten_times_more_parts(k: int) -> None:
    """Absolute precision of order k resolves 10^k parts, one more digit ten times as many
    (line 1438, the estimates of Fig. 1.6b: order 3 is 1 part in 1,000); order 0 resolves the
    whole."""
    assert precision_parts(k + 1) == 10 * precision_parts(k)
    assert precision_parts(0) == 1
