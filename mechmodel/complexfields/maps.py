"""The stereographic map of Fig. 10.15: a sphere of diameter D touching the z-plane at its North
Pole N and standing on the w-plane at its South Pole S; a point P at the central angle theta
projects from S to z (|z| = D tan(theta/2)) and from N to w (|w| = D cot(theta/2)), so that
|w| = D^2/|z|: the map w = 1/z (D = 1) that carries the point at infinity to w = 0. Lengths in
units of D, angles in radians.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

from mechmodel import inputs
from mechmodel.typing import Real


@dataclass(frozen=True)
class StereographicPoint:
    """A point P of a sphere of diameter D standing on the w-plane at its South Pole S and
    touching the z-plane at its North Pole N (Fig. 10.15); theta = angle NOP at the centre O.
    The z-point is where the line from S through P meets the z-plane, the w-point where the
    line from N through P meets the w-plane.

    The ``*_angle_divisor`` fields are theta over the angle read off each printed relation
    (|z| = D tan(theta/2), |w| = D cot(theta/2), SP = D cos(theta/2), NP = D sin(theta/2),
    depth of P below N = D sin^2(theta/2), height above S = D cos^2(theta/2)); the
    ``*_exponent`` fields are the powers in |w| = |z|^p, |z| = |w|^p (true for D = 1),
    depth = NP^p and height = SP^p (in units of D)."""

    z_radius: float
    w_radius: float
    radius: Real  # exact for an exact diameter
    tan_angle_divisor: float
    cot_angle_divisor: float
    w_exponent: float
    z_exponent: float
    south_chord_angle_divisor: float
    north_chord_angle_divisor: float
    north_depth_exponent: float
    south_height_exponent: float
    north_depth_angle_divisor: float
    south_height_angle_divisor: float


def stereographic_projection(theta: Real, diameter: Real) -> StereographicPoint:
    """Coordinates of the construction of Fig. 10.15 for a point at angle theta (radians)."""
    inputs.positive(diameter, "diameter")
    inputs.real(theta, "theta")
    t, d = float(theta), float(diameter)
    if not 0 < t < math.pi or math.isclose(t, math.pi / 2):
        raise ValueError("theta must be in (0, pi) and not pi/2 (where |z| = |w|)")
    # S at height 0, N at height D, the centre half-way: the radius, exact for exact D
    centre_height = Fraction(diameter) / 2 if isinstance(diameter, int | Fraction) else d / 2
    r = d / 2
    px, py = r * math.sin(t), r + r * math.cos(t)
    z_radius = px * d / py  # line S -> P continued to height D
    w_radius = px * d / (d - py)  # line N -> P continued to height 0
    sp, np_ = math.hypot(px, py), math.hypot(px, d - py)
    depth, height = d - py, py
    return StereographicPoint(
        z_radius=z_radius,
        w_radius=w_radius,
        radius=centre_height,
        tan_angle_divisor=t / math.atan(z_radius / d),
        cot_angle_divisor=t / math.atan(d / w_radius),
        w_exponent=math.log(w_radius) / math.log(z_radius),
        z_exponent=math.log(z_radius) / math.log(w_radius),
        south_chord_angle_divisor=t / math.acos(sp / d),
        north_chord_angle_divisor=t / math.asin(np_ / d),
        north_depth_exponent=math.log(depth / d) / math.log(np_ / d),
        south_height_exponent=math.log(height / d) / math.log(sp / d),
        north_depth_angle_divisor=t / math.asin(math.sqrt(depth / d)),
        south_height_angle_divisor=t / math.acos(math.sqrt(height / d)),
    )


def stereographic_image_radius(z_radius: Real, diameter: Real) -> float:
    """|w| of the image of a z-point at distance |z| from N: project it onto the sphere along
    the line to S, then from N onto the w-plane (Fig. 10.15); equals D^2/|z|."""
    inputs.positive(z_radius, "z_radius")
    inputs.positive(diameter, "diameter")
    d, rho = float(diameter), float(z_radius)
    # the line from S = (0, 0) to (rho, d): points s (rho, d); it meets the sphere
    # x^2 + (y - d/2)^2 = (d/2)^2 where s^2 (rho^2 + d^2) = s d^2
    s = d * d / (rho * rho + d * d)
    px, py = s * rho, s * d
    return px * d / (d - py)


@dataclass(frozen=True)
class StereographicLengths:
    """The lengths of Fig. 10.15 for the point P at the central angle theta on a sphere of
    diameter D (N on the z-plane, S on the w-plane): ``z_radius`` |z| and ``w_radius`` |w| of
    its two images, the chords ``south_chord`` SP and ``north_chord`` NP, P's depth below N
    (``north_depth``), its height above S (``south_height``) and the angle NSP at S between the
    axis and the chord SP (``south_angle``, radians), the angle the figure marks theta/2."""

    z_radius: float
    w_radius: float
    south_chord: float
    north_chord: float
    north_depth: float
    south_height: float
    south_angle: float


def stereographic_lengths(theta: Real, diameter: Real) -> StereographicLengths:
    """The construction of Fig. 10.15 in coordinates: S at the origin, N at height D, P on the
    circle of radius D/2 about the centre at angle theta from N; the line S -> P continued to
    height D gives |z|, the line N -> P continued to height 0 gives |w|."""
    inputs.positive(diameter, "diameter")
    inputs.real(theta, "theta")
    t, d = float(theta), float(diameter)
    if not 0 < t < math.pi:
        raise ValueError("theta must be in (0, pi): P between N and S")
    r = d / 2
    px, py = r * math.sin(t), r + r * math.cos(t)
    return StereographicLengths(
        z_radius=px * d / py,
        w_radius=px * d / (d - py),
        south_chord=math.hypot(px, py),
        north_chord=math.hypot(px, d - py),
        north_depth=d - py,
        south_height=py,
        south_angle=math.atan2(px, py),
    )


def stereographic_preimage_radius(w_radius: Real, diameter: Real) -> float:
    """|z| of the point whose image is at distance |w| from S: project the w-point onto the
    sphere along the line to N, then from S onto the z-plane (Fig. 10.15)."""
    inputs.positive(w_radius, "w_radius")
    inputs.positive(diameter, "diameter")
    d, rho = float(diameter), float(w_radius)
    # the line from N = (0, d) to (rho, 0): points (t rho, d - t d); on the sphere
    # x^2 + (y - d/2)^2 = (d/2)^2 where t^2 (rho^2 + d^2) = t d^2
    t = d * d / (rho * rho + d * d)
    px, py = t * rho, d - t * d
    return px * d / py
