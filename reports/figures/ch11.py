"""Figures of chapter 11, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from mechmodel.oscillators import (
    apsis_speeds,
    ellipse_form,
    matrix_inverse,
    orbit_derivative,
    orbit_period,
    orbit_position,
    triad_angle,
)
from mechmodel.rotation import (
    cycloid_kind,
    radius_of_gyration,
    rod_impulse,
    rod_point_position,
)
from reports.figures import ellipse_points, figure, value_of

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim

_NAMES = ("r", "v/ω", "a/ω²", "j/ω³")


@figure(
    "oscillator-orbit",
    "Figs. 11.1, 11.5 and 11.8",
    "Left: the orbit r = (a cos ωt, b sin ωt) of Fig. 11.1 (a = 2.2, b = 1) at twelve equal "
    "time steps, with the velocity, acceleration and jerk arrows at one of them; the mass is "
    "a/b = 2.2 times faster crossing the minor axis than at the ends of the major axis, and "
    "the shaded sectors swept in equal times have equal areas (Fig. 11.8). Right: r, v/ω, "
    "a/ω² and j/ω³ all lie on the same ellipse, a quarter turn of phase apart (Fig. 11.5(a)).",
    (
        "ch11.apsis-speed-ratio",
        "ch11.fig11-5.phase-step",
        "ch11.derivative-phase.step",
        "ch11.derivative-phase.jerk",
        "ch11.acceleration.omega-power",
        "ch11.jerk.omega-power",
        "ch11.area-law.half",
    ),
)
def _orbit(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    a = value_of(claims, "ch11.fig11-1.a")
    b = value_of(claims, "ch11.fig11-1.b")
    w = 1.0
    period = orbit_period(w)
    left, right = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    xs, ys = ellipse_points(a, b)
    for ax in (left, right):
        ax.plot(xs, ys, color="0.6")
        ax.set_aspect("equal")
        ax.set_xlim(-a * 1.3, a * 1.3)
        ax.set_ylim(-1.3 * max(b, 0.7 * a), 1.3 * max(b, 0.7 * a))
    steps = 12
    for k in range(steps):
        x, y = orbit_position(a, b, w, period * k / steps)
        left.plot([x], [y], "o", color="C0", markersize=3)
    for k0 in (0, 3):  # two sectors of one step each: at apogee and at perigee
        t0, t1 = period * k0 / steps, period * (k0 + 1) / steps
        pts = [orbit_position(a, b, w, t0 + (t1 - t0) * j / 20) for j in range(21)]
        left.fill([0, *(p[0] for p in pts)], [0, *(p[1] for p in pts)], color="C0", alpha=0.2)
    t = period / 10
    x, y = orbit_position(a, b, w, t)
    for order, colour in ((1, "C1"), (2, "C2"), (3, "C3")):
        dx, dy = orbit_derivative(a, b, w, t, order)
        left.annotate(
            "",
            (x + dx / 2, y + dy / 2),
            (x, y),
            arrowprops={"arrowstyle": "->", "color": colour},
        )
    speeds = apsis_speeds(a, b, w)
    left.set_title(
        f"perigee/apogee speed = {speeds.ratio:.2f}; arrows v, a, j (half length)",
        fontsize="x-small",
    )
    for order, colour in zip(range(4), ("C0", "C1", "C2", "C3"), strict=True):
        dx, dy = orbit_derivative(a, b, w, t, order)
        scale = w**order
        right.annotate(
            "",
            (dx / scale, dy / scale),
            (0, 0),
            arrowprops={"arrowstyle": "->", "color": colour},
        )
        right.annotate(_NAMES[order], (dx / scale, dy / scale), fontsize="small", color=colour)
    right.set_title("derivatives a quarter turn apart", fontsize="x-small")


@figure(
    "triads",
    "Fig. 11.7 and (11.18)",
    "The Q-ellipse r·Q·r = 1 (solid, a = 2, b = 1/2, ab = 1) and its dual p·Q⁻¹·p = 1 "
    "(dashed, radii 1/a and 1/b) with the triad sequence started at φ0 = π/4: the radius "
    "r(φk-1) = (a cos φk, b sin φk) and the perpendicular p(φk+1) = Q·r(φk-1) of each triad, "
    "on lines of slope (a/b)^k.",
    (
        "ch11.triad.phi0-slope",
        "ch11.triad.p1.x-divisor",
        "ch11.triad.r-1.x-divisor",
        "ch11.slope-gain.q-power",
        "ch11.dual.p-dot-r",
        "ch11.dual.radius-x",
    ),
)
def _triads(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    phi0 = value_of(claims, "ch11.triad.phi0")
    ab = value_of(claims, "ch11.triad.ab")
    a = 2.0
    b = ab / a
    q = ellipse_form(a, b)
    qi = matrix_inverse(q)
    ax = fig.add_subplot()
    xs, ys = ellipse_points(a, b)
    ax.plot(xs, ys, color="C0", label="Q-ellipse r·Q·r = 1")
    xs, ys = ellipse_points(1 / math.sqrt(qi[0][0]), 1 / math.sqrt(qi[1][1]))
    ax.plot(xs, ys, "--", color="C1", label="p-ellipse p·Q⁻¹·p = 1")
    for k in range(-2, 3):
        phi = triad_angle(a, b, phi0, k)
        r = (a * math.cos(phi), b * math.sin(phi))
        p = (q[0][0] * r[0], q[1][1] * r[1])
        ax.plot([0, r[0]], [0, r[1]], color="C0", linewidth=1)
        ax.plot([0, p[0]], [0, p[1]], color="C1", linewidth=1)
        reach = 2.2
        ax.plot(
            [0, reach * math.cos(phi)], [0, reach * math.sin(phi)], ":", color="0.6", linewidth=1
        )
        ax.annotate(f"φ{k}", (reach * math.cos(phi), reach * math.sin(phi)), fontsize="x-small")
    ax.set_aspect("equal")
    ax.set_xlim(-0.2, 2.4)
    ax.set_ylim(-0.2, 2.4)
    ax.legend(loc="upper right", fontsize="x-small")


@figure(
    "rod-cycloids",
    "Figs. 11.9 and 11.10",
    "A free rod of length L = 2 struck at height h = l/2 above its centre rolls on a 'tire' "
    "of percussion radius p = l²/(3h) = 2l/3: the point at distance p on the far side traces "
    "a normal cycloid (cusps at rest), points inside it prolate and the rod's ends curlate "
    "cycloids; the centre moves straight. The crosses mark the radius of gyration "
    "l/√3 = 0.577 l on the upright rod, where h = p (the book prints 0.866).",
    (
        "ch11.percussion.hp-coefficient",
        "ch11.percussion.half-hit.radius",
        "ch11.gyration.radius",
        "ch11.gyration.divisor",
    ),
)
def _rod(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    length = value_of(claims, "ch11.fig11-9.rod-length")
    half = length / 2
    divisor = value_of(claims, "ch11.percussion.half-hit.divisor")
    h = half / divisor
    response = rod_impulse(1.0, half, 1.0, h)
    p = float(response.percussion_radius)
    w = float(response.angular_velocity)
    turn = 2 * math.pi / w
    times = [2 * turn * j / 400 for j in range(401)]
    ax = fig.add_subplot()
    for s, colour in ((half, "C0"), (-half, "C4"), (-p, "C3"), (p / 2, "C2"), (0.0, "k")):
        path = [rod_point_position(1.0, half, 1.0, h, s, t) for t in times]
        ax.plot(
            [q[0] for q in path],
            [q[1] for q in path],
            color=colour,
            linewidth=1,
            label=f"s = {s:+.2f}: {cycloid_kind(s, p)}",
        )
    for t in (0.0, turn / 4, turn / 2):
        ends = [rod_point_position(1.0, half, 1.0, h, s, t) for s in (-half, half)]
        ax.plot([e[0] for e in ends], [e[1] for e in ends], color="0.5", linewidth=2)
    ax.axhline(-p, color="0.7", linewidth=0.8)
    gyration = radius_of_gyration(length)
    ax.plot([0, 0], [gyration, -gyration], "x", color="k", label="radius of gyration l/√3")
    ax.set_aspect("equal")
    ax.set_title(f"h = l/{divisor:g}, p = {p / half:.3f} l, road at y = -p", fontsize="small")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), fontsize="x-small", ncols=3)
