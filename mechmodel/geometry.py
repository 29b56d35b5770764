"""Slope geometry and trigonometry of the unit circle (chapter 1).

Slopes of velocity lines on scaled graphs and their rescaling between units (Fig. 1.2), angles
as turns, degrees and radians (Fig. 1.3), the six trigonometric functions drawn as line
segments of a circle of radius r (Figs. 1.4 and 1.6), whirling-rectangle sequences and the
golden ratio (Figs. 1.5 and 1.10), arc functions with both of their solutions (Fig. 1.7), the
arc-secant and Thales' means (Figs. 1.8 and 1.9), clock angles (exercise 3) and counts of
degrees of freedom (Landscape 1.2).

Angles are in radians (a claim printed in degrees names the unit ``deg`` and the evaluator
converts); speeds and lengths in SI or any consistent units. Formulas use plain operators:
slopes, scale ratios, means other than the geometric one, turns and counts stay exact for
``int`` and ``fractions.Fraction`` inputs; anything with a trigonometric function or a square
root gives a float, or an mpmath number when an input is one (then pi is mpmath's too).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction
from types import ModuleType

import mpmath

from mechmodel import inputs
from mechmodel.numeric import clock_angle as clock_angle  # the catalog's geometry.*
from mechmodel.numeric import line_angle
from mechmodel.planar import hypotenuse as hypotenuse
from mechmodel.typing import Real

ARC_FUNCTIONS = ("sin", "cos", "tan")


# -- numeric helpers ------------------------------------------------------------------------
def _uses_mpmath(*values: object) -> bool:
    return any(isinstance(v, mpmath.mpf | mpmath.mpc) for v in values)


def _lib(*values: object) -> ModuleType:
    """The module whose sin, cos, atan, sqrt ... suit ``values``: mpmath for mpmath numbers."""
    return mpmath if _uses_mpmath(*values) else math


def _pi(*values: object) -> float:
    """Pi in the precision of ``values``: mpmath's pi for mpmath numbers, else the float."""
    return +mpmath.pi if _uses_mpmath(*values) else math.pi


def _sqrt(x: Real) -> Real:
    return _lib(x).sqrt(x)


def _atan2(y: Real, x: Real) -> Real:
    return _lib(y, x).atan2(y, x)


# -- slopes and their rescaling (Fig. 1.2) --------------------------------------------------
def slope(altitude: Real, base: Real) -> Real:
    """Slope-to-horizon of a triangle: altitude a over base b, a/b (Fig. 1.2, "=a/b").

    Exact for ``int`` and ``Fraction`` sides.
    """
    inputs.real(altitude, "altitude")
    inputs.real(base, "base")
    if base == 0:
        raise ValueError("base must be non-zero: a vertical line has no finite slope")
    return altitude / base


def grid_speed(distance_per_square: Real, time_per_square: Real) -> Real:
    """Speed of the 1:1 (45 degree) line on a graph whose unit square is ``distance_per_square``
    (s_x, a length) by ``time_per_square`` (s_y, a time): s_x / s_y (Fig. 1.2, line 1084).

    SI in, SI out: 0.1 mile per 6 s is 1 mile/min, 60 mph.
    """
    inputs.positive(distance_per_square, "distance_per_square")
    inputs.positive(time_per_square, "time_per_square")
    return distance_per_square / time_per_square


def newton_slope(speed: Real, distance_per_square: Real, time_per_square: Real) -> Real:
    """Slope-to-horizon, in graph squares, of a constant-velocity line on Newton's space vs.
    time plot (Fig. 1.2b): v s_y / s_x, the speed in units of the 1:1 line's speed.
    """
    inputs.real(speed, "speed")
    return speed / grid_speed(distance_per_square, time_per_square)


def minkowski_slope(speed: Real, distance_per_square: Real, time_per_square: Real) -> Real:
    """Slope-to-horizon, in graph squares, of a constant-velocity line on Minkowski's time vs.
    space plot (Fig. 1.2a): s_x / (v s_y), the inverse of the Newton slope (line 1080).
    """
    inputs.real(speed, "speed")
    if speed == 0:
        raise ValueError("speed must be non-zero: a body at rest is a vertical line here")
    return grid_speed(distance_per_square, time_per_square) / speed


def scale_ratio(distance_factor: Real, time_factor: Real) -> Real:
    """The factor f_x / f_y that multiplies every slope when the distance scale is multiplied
    by f_x and the time scale by f_y (lines 1085-1093). Exact for ``int`` and ``Fraction``.
    """
    inputs.positive(distance_factor, "distance_factor")
    inputs.positive(time_factor, "time_factor")
    return distance_factor / time_factor


def rescaled_slope(slope: Real, distance_factor: Real, time_factor: Real) -> Real:
    """A slope Δx/Δt after rescaling distance by f_x and time by f_y: (f_x/f_y) Δx/Δt
    (lines 1087-1094: the SUV's slope 1 in miles per minute is 88 in feet per second)."""
    inputs.real(slope, "slope")
    return slope * scale_ratio(distance_factor, time_factor)


def speed(speed: Real) -> Real:
    """A speed, unchanged (SI). Writing it in another unit (60 mph as 88 ft/s, line 1094) is
    the conversion through the claim's unit, whose factor comes from ``units.toml``."""
    return inputs.real(speed, "speed")


# The slope angle sigma = arctan(slope) of a line of slope dy/dx (line 934: the 1/1 slope is the
# 45 degree diagonal) is the angle of its line.
slope_angle = line_angle


# -- angles (Fig. 1.3, exercises 1 and 3) ---------------------------------------------------
def turn_angle(turns: Real) -> Real:
    """The angle of a fraction of a full turn, 2π turns radians (lines 1099-1101: a half turn
    is π, 180 degrees; a quarter turn π/2, Fig. 1.3b)."""
    inputs.real(turns, "turns")
    return 2 * _pi(turns) * turns


def radians(angle: Real) -> Real:
    """An angle, unchanged, in radians. A claim printed in degrees names the unit ``deg`` and
    the evaluator converts with the factor π/180 of ``units.toml`` (line 1100: 1 radian =
    180/π degrees)."""
    return inputs.real(angle, "angle")


def complement(angle: Real) -> Real:
    """The complement σc = π/2 - σ of a slope angle σ (line 1174, Fig. 1.4a)."""
    inputs.real(angle, "angle")
    return _pi(angle) / 2 - angle


def regular_polygon_interior_angle(sides: int) -> float:
    """Interior angle (n - 2) π / n of a regular polygon of n sides; π/3 for the equilateral
    triangle of the Euclid construction of a 60 degree slope (line 1431, Fig. 1.6)."""
    n = inputs.count(sides, "sides", minimum=3)
    return (n - 2) * math.pi / n


def doubled_clock_points(points: int) -> int:
    """Points of a clock whose hour arcs are all bisected: twice as many (exercise 3: the
    12-point clock repeated with diagonals gives the 24-hour clock)."""
    return 2 * inputs.count(points, "points", minimum=1)


def quadrant_fraction(quadrants: int) -> Fraction:
    """The share of all directions lying in ``quadrants`` of the four quadrants: each is a
    quarter turn of the full turn (line 1818: a calculator that never answers in the 3rd
    quadrant is wrong at least 25 % of the time)."""
    n = inputs.count(quadrants, "quadrants")
    if n > 4:
        raise ValueError(f"there are four quadrants, not {n}")
    return Fraction(n, 4)


# -- circles: arcs, sectors, chords (Figs. 1.3 and 1.6) ---------------------------------------
def arc_length(angle: Real, radius: Real) -> Real:
    """Length r σ of the arc of a circle of radius r swept by angle σ (Fig. 1.3: r σ = 1 for
    σ = 1 radian on the unit circle)."""
    inputs.real(angle, "angle")
    inputs.positive(radius, "radius")
    return radius * angle


def sector_area(angle: Real, radius: Real) -> Real:
    """Area (1/2) r^2 σ of one circular sector of angle σ (each piece in Fig. 1.3)."""
    inputs.real(angle, "angle")
    inputs.positive(radius, "radius")
    return radius**2 * angle / 2


def total_sector_area(angle: Real, radius: Real) -> Real:
    """The book's "Total Sector Area" r^2 σ: the slope line at angle σ sweeps two sectors of
    (1/2) r^2 σ, one on each side of the x-axis (Fig. 1.3; a quarter turn sweeps half the
    disk, π/2, and a half turn the whole pie, π)."""
    return 2 * sector_area(angle, radius)


def chord(angle: Real, radius: Real) -> Real:
    """Length 2 r sin(σ/2) of the straight chord under an arc of angle σ (line 1435: the line
    RX under the π/3 arc has length r exactly)."""
    inputs.real(angle, "angle")
    inputs.positive(radius, "radius")
    return 2 * radius * _lib(angle).sin(angle / 2)


def arc_chord_excess(angle: Real) -> Real:
    """How much longer an arc is than its chord, as a fraction: r σ / (2 r sin(σ/2)) - 1, the
    same on every circle (lines 1436-1440: the π/3 arc is 4.72 % longer than the line RX)."""
    return arc_length(angle, 1) / chord(angle, 1) - 1


@dataclass(frozen=True)
class UnitCircleSegments:
    """The six trigonometric functions of angle σ as segments of a circle of radius r, as in
    Fig. 1.4b (σ = 1) and Fig. 1.6d (σ = π/3).

    base = r cos σ and altitude = r sin σ are the legs of the right triangle with hypotenuse
    r; tangent = r tan σ runs along the tangent line from the circle to the secant point on
    the x-axis, at distance secant = r sec σ from the centre; cotangent = r cot σ continues
    the tangent line to the cosecant point on the y-axis, at cosecant = r csc σ. The segments
    are computed when asked for, so that σ = π/2 (Fig. 1.4c) has a base and a zero
    cotangent while its infinite tangent and secant raise ``ValueError``.
    """

    angle: Real
    radius: Real

    def _cos(self) -> float:
        return _lib(self.angle).cos(self.angle)

    def _sin(self) -> float:
        return _lib(self.angle).sin(self.angle)

    @staticmethod
    def _over(numerator: Real, denominator: float, name: str) -> float:
        if denominator == 0:
            raise ValueError(f"the {name} segment is infinite at this angle")
        return numerator / denominator

    @property
    def base(self) -> float:
        """r cos σ: the horizontal leg (Fig. 1.4b: 0.5403 for σ = 1)."""
        return self.radius * self._cos()

    @property
    def altitude(self) -> float:
        """r sin σ: the vertical leg (Fig. 1.4a: 0.8415 for σ = 1)."""
        return self.radius * self._sin()

    @property
    def tangent(self) -> float:
        """r tan σ: the tangent segment from the circle to the x-axis."""
        return self._over(self.radius * self._sin(), self._cos(), "tangent")

    @property
    def cotangent(self) -> float:
        """r cot σ: the tangent segment from the circle to the y-axis."""
        return self._over(self.radius * self._cos(), self._sin(), "cotangent")

    @property
    def secant(self) -> float:
        """r sec σ: centre to the secant point on the x-axis."""
        return self._over(self.radius, self._cos(), "secant")

    @property
    def cosecant(self) -> float:
        """r csc σ: centre to the cosecant point on the y-axis."""
        return self._over(self.radius, self._sin(), "cosecant")

    @property
    def tangent_slope_angle(self) -> Real:
        """Slope angle of the tangent line, σ - π/2 = -σc: it is normal to the radius."""
        return -complement(self.angle)


def unit_circle_segments(angle: Real, radius: Real = 1) -> UnitCircleSegments:
    """The trigonometric segments of angle σ (radians) on a circle of radius r (Fig. 1.4)."""
    inputs.real(angle, "angle")
    inputs.positive(radius, "radius")
    return UnitCircleSegments(angle, radius)


def complement_segments(angle: Real, radius: Real = 1) -> UnitCircleSegments:
    """The trigonometric segments of the complement σc = π/2 - σ of ``angle`` on a circle of
    radius r: the triangle of Fig. 1.4a seen with its legs swapped, so that each ratio of σc is
    a co-ratio of σ (line 1175: tan σc = cot σ, tan σ = cot σc)."""
    return unit_circle_segments(complement(angle), radius)


@dataclass(frozen=True)
class RightTriangle:
    """Sides of a right triangle: base b, altitude a, hypotenuse r."""

    base: Real
    altitude: Real
    hypotenuse: Real


def right_triangle_sides(angle: Real, base: Real) -> RightTriangle:
    """The right triangle with slope angle σ and base b: altitude b tan σ, hypotenuse b sec σ
    (line 1584: the 30-60-90 triangle has (b:a:r) = (1:√3:2))."""
    segments = unit_circle_segments(angle)
    inputs.positive(base, "base")
    return RightTriangle(base, base * segments.tangent, base * segments.secant)


# -- whirling rectangles and the golden ratio (Figs. 1.5 and 1.10) ----------------------------
@dataclass(frozen=True)
class WhirlingRectangles:
    """The whirling-rectangle sequence of slope angle σ (Fig. 1.5).

    ``lengths`` are the diagonals (Fig. 1.5a) or sides (Fig. 1.5b) tan σ, 1, cot σ, cot^2 σ,
    ...: the powers (tan σ)^(1-k), k = 0, 1, ...; each is the one before rotated a quarter
    turn clockwise and shrunk by ``scale_factor`` = cot σ. ``rotation`` is the size of that
    quarter turn. ``first_angle`` is the slope angle of the first segment, tan σ: it lies on
    the tangent line of Fig. 1.4b, normal to the radius, at σ - π/2 = -σc.
    """

    angle: Real
    lengths: tuple[float, ...]
    scale_factor: float
    rotation: Real
    first_angle: Real


def whirling_rectangles(angle: Real, terms: int = 5) -> WhirlingRectangles:
    """The first ``terms`` segments of the whirling-rectangle sequence of slope angle σ
    (Fig. 1.5: {tan σ, 1, cot σ, cot^2 σ, cot^3 σ, ...}, line 1390)."""
    n = inputs.count(terms, "terms", minimum=2)
    segments = unit_circle_segments(angle)
    tan = segments.tangent
    cot = segments.cotangent
    lengths = (tan, *(cot**k for k in range(n - 1)))
    return WhirlingRectangles(angle, lengths, cot, turn_angle(1) / 4, segments.tangent_slope_angle)


@dataclass(frozen=True)
class GoldenRatio:
    """The two roots G± = (1 ± √5)/2 of G^2 = G + 1: G+ = 1.618... and G- = -0.618... = -1/G+
    (Figs. 1.9b and 1.10: the tangent and the negative cotangent of the golden slope)."""

    plus: Real
    minus: Real


def golden_ratio(unit: Real = 1) -> GoldenRatio:
    """The golden means of a square of side ``unit``: the roots of G^2 = G u + u^2 by the
    quadratic formula, u (1 ± √5)/2 (Fig. 1.9b; Fig. 1.10a cuts the unit square from the
    golden rectangle). An mpmath ``unit`` gives mpmath roots."""
    inputs.positive(unit, "unit")
    root = _sqrt(5 * unit**2)
    return GoldenRatio((unit + root) / 2, (unit - root) / 2)


# -- arc functions and their two solutions (Figs. 1.7 and 1.8) -----------------------------------
@dataclass(frozen=True)
class ArcSolutions:
    """Both arcs σ1, σ2 that give the same value of a trigonometric function (Fig. 1.7).

    ``first`` is the calculator's answer (the principal value); ``second`` the one it ignores:
    for sine the x-reflection π - σ1, for cosine the y-reflection -σ1, for tangent the
    antipodal σ1 - π. ``separation`` = σ2 - σ1.
    """

    function: str
    first: Real
    second: Real

    @property
    def separation(self) -> Real:
        """σ2 - σ1: π - 2σ1 for sine, -2σ1 for cosine, -π for tangent (the antipodal ±180°)."""
        return self.second - self.first


def arc_solutions(function: str, value: Real) -> ArcSolutions:
    """The two solutions σ of sin σ = value, cos σ = value or tan σ = value (Fig. 1.7, line
    1602: sin⁻¹(0.5) is π/6 and 5π/6; cos⁻¹(0.5) is ±π/3)."""
    inputs.real(value, "value")
    lib, pi = _lib(value), _pi(value)
    if function == "sin":
        if not -1 <= value <= 1:
            raise ValueError(f"sin σ = {value!r} has no real solution")
        first = lib.asin(value)
        return ArcSolutions(function, first, pi - first)
    if function == "cos":
        if not -1 <= value <= 1:
            raise ValueError(f"cos σ = {value!r} has no real solution")
        first = lib.acos(value)
        return ArcSolutions(function, first, -first)
    if function == "tan":
        first = lib.atan(value)
        return ArcSolutions(function, first, first - pi)
    raise ValueError(f"function must be one of {ARC_FUNCTIONS}, got {function!r}")


def arctan_solutions(altitude: Real, base: Real) -> ArcSolutions:
    """The two arcs of slope a/b (Fig. 1.7c): atan2(a, b), the direction of the point (b, a),
    and the antipodal atan2(-a, -b); a calculator's tan⁻¹(a/b) cannot tell them apart
    (line 1832)."""
    inputs.real(altitude, "altitude")
    inputs.real(base, "base")
    if altitude == 0 and base == 0:
        raise ValueError("the point (0, 0) has no direction")
    return ArcSolutions("tan", _atan2(altitude, base), _atan2(-altitude, -base))


@dataclass(frozen=True)
class Interval:
    """A closed range of values, lower to upper."""

    lower: Real
    upper: Real


def principal_range(function: str) -> Interval:
    """The range of a calculator's arc function (lines 1834-1846): sin⁻¹ and tan⁻¹ give
    -π/2 to +π/2, cos⁻¹ 0 to π, and atan2(y, x) the whole turn -π to +π."""
    pi = math.pi
    ranges = {
        "sin": (-pi / 2, pi / 2),
        "tan": (-pi / 2, pi / 2),
        "cos": (0, pi),
        "atan2": (-pi, pi),
    }
    if function not in ranges:
        raise ValueError(f"function must be one of {sorted(ranges)}, got {function!r}")
    return Interval(*ranges[function])


def function_range(function: str) -> Interval:
    """Least and greatest values of sin or cos over a turn, at their extreme angles (lines
    1821-1830: the altitude a = y and the base b = x run from +1 to -1 on the unit circle)."""
    pi = math.pi
    if function == "sin":
        return Interval(math.sin(-pi / 2), math.sin(pi / 2))
    if function == "cos":
        return Interval(math.cos(pi), math.cos(0))
    raise ValueError(f"function must be 'sin' or 'cos', got {function!r}")


@dataclass(frozen=True)
class ArcSecantConstruction:
    """The arc-secant of s by Thales' geometric mean (Fig. 1.8): the tangent from x = s to the
    unit circle has length √(s^2 - 1) = √(a b) with a = s - 1 and b = s + 1."""

    secant: Real
    a: Real
    b: Real
    tangent: Real
    angle: Real


def arcsec_construction(secant: Real) -> ArcSecantConstruction:
    """Construct σ = sec⁻¹(s) for s >= 1 (exercise 2, Fig. 1.8)."""
    inputs.real(secant, "secant")
    if secant < 1:
        raise ValueError(f"the secant point must lie outside the unit circle, got {secant!r}")
    a, b = secant - 1, secant + 1
    tangent = thales_means(a, b).geometric if a > 0 else 0
    return ArcSecantConstruction(secant, a, b, tangent, _atan2(tangent, 1))


# -- means (Thales, Fig. 1.9) -------------------------------------------------------------------
@dataclass(frozen=True)
class Means:
    """Means of two lengths a and b (Fig. 1.9a).

    ``arithmetic`` (a + b)/2 is the radius of Thales' circle on the diameter a + b;
    ``geometric`` √(a b) the half-chord normal to the diameter where a meets b; ``difference``
    (a - b)/2 the signed distance from the centre to that point, and ``difference_length`` its
    length |a - b|/2 (the segment DM of the figure); ``harmonic`` 2ab/(a + b).
    """

    a: Real
    b: Real
    arithmetic: Real
    geometric: Real
    difference: Real
    harmonic: Real

    @property
    def difference_length(self) -> Real:
        """|a - b|/2: the distance from the centre of Thales' circle to the split point."""
        d = self.difference  # not abs(d): mypy joins abs over float | int | Fraction to object
        return -d if d < 0 else d


def thales_means(a: Real, b: Real) -> Means:
    """Arithmetic, geometric, difference and harmonic means of lengths a, b > 0 (Fig. 1.9)."""
    inputs.positive(a, "a")
    inputs.positive(b, "b")
    return Means(a, b, (a + b) / 2, _sqrt(a * b), (a - b) / 2, 2 * a * b / (a + b))


def thales_angle(a: Real, b: Real) -> Real:
    """Angle at the apex of Thales' triangle on the diameter a + b (Fig. 1.9a), computed from
    the apex (0, √(ab)) and the ends (-a, 0), (b, 0): always π/2 (angle in a semicircle)."""
    h = thales_means(a, b).geometric
    to_a = _atan2(-h, -a)
    to_b = _atan2(-h, b)
    return to_b - to_a


# -- degrees of freedom and precision (Landscape 1.2, exercise 1) ------------------------------
def degrees_of_freedom(counts: Sequence[int]) -> int:
    """Total degrees of freedom of a system: the sum of its parts' counts (Landscape 1.2:
    3 + 3 translational for the SUV and VW, 12 rigid-body in all)."""
    return sum(inputs.count(c, "count") for c in counts)


@dataclass(frozen=True)
class VibrationFormula:
    """The formula per_atom N - subtracted for the vibrational degrees of freedom of an
    N-atom molecule: each atom moves in ``per_atom`` dimensions; the molecule's own
    translations and rotations are not vibrations (Landscape 1.2: 3N - 6)."""

    per_atom: int
    subtracted: int

    def modes(self, atoms: int) -> int:
        """Vibrational degrees of freedom of a molecule of ``atoms`` atoms (at least three)."""
        n = inputs.count(atoms, "atoms", minimum=3)
        return self.per_atom * n - self.subtracted


def vibration_formula(translational: int, rotational: int) -> VibrationFormula:
    """Coefficients of the vibrational count 3N - 6 from the translational and rotational
    degrees of freedom of a rigid body (Landscape 1.2)."""
    return VibrationFormula(
        vibration_coefficient(translational), vibration_offset(translational, rotational)
    )


def vibration_coefficient(translational: int) -> int:
    """The coefficient of N in the vibrational count: each of the N atoms moves in as many
    dimensions as a body has translational degrees of freedom (the 3 of 3N - 6)."""
    return inputs.count(translational, "translational")


def vibration_offset(translational: int, rotational: int) -> int:
    """The count subtracted from N times the coefficient: the molecule's own translations and
    rotations, which are not vibrations (the 6 = 3 + 3 of 3N - 6)."""
    return inputs.count(translational, "translational") + inputs.count(rotational, "rotational")


def vibrational_modes(atoms: int, translational: int, rotational: int) -> int:
    """Vibrational degrees of freedom of a molecule of ``atoms`` atoms, not all on one line:
    the N atoms move in N times as many dimensions as a body has translational degrees of
    freedom, less the molecule's own rigid translations and rotations (Landscape 1.2: an N-atom
    molecule has 3N - 6)."""
    return vibration_formula(translational, rotational).modes(atoms)


def precision_parts(order: int) -> int:
    """Parts resolved at absolute precision of order k: 10^k (line 1438: order 3 is 1 part
    in 1,000)."""
    return 10 ** inputs.count(order, "order")
