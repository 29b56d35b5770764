"""Figures of chapter 11, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from mechmodel.ellipse import ellipse_outline
from mechmodel.oscillators import (
    apsis_speeds,
    dual_ellipse,
    orbit_derivative,
    orbit_period,
    orbit_position,
    triad_angle,
    triad_vectors,
)
from mechmodel.rotation import (
    cycloid_kind,
    radius_of_gyration,
    rod_impulse,
    rod_point_position,
)
from reports.figures import figure, value_of

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim

_NAMES = (
    r"$\mathbf{r}$",
    r"$\mathbf{v}/\omega$",
    r"$\mathbf{a}/\omega^2$",
    r"$\mathbf{j}/\omega^3$",
)
_ARROWS = (("C1", r"$\mathbf{v}$"), ("C2", r"$\mathbf{a}$"), ("C3", r"$\mathbf{j}$"))


@figure(
    "oscillator-orbit",
    "Figs. 11.1, 11.5 and 11.8",
    (
        "(a) The orbit r = (a cos ωt, b sin ωt) of Fig. 11.1 (a = 2.2, b = 1, ω = 1; scaled "
        "lengths) at twelve equal time steps, with the velocity, acceleration and jerk (half "
        "length) at one of them: the mass crosses the minor axis a/b = 2.2 times faster than "
        "the ends of the major one, and the sectors swept in equal times have equal areas (Fig."
        " 11.8). (b) r, v/ω, a/ω² and j/ω³ all lie on the same ellipse, a quarter turn of phase"
        " apart (Fig. 11.5(a))."
    ),
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
    fig.set_size_inches(9.6, 3.4)
    fig.set_layout_engine("constrained")
    left, right = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    xs, ys = ellipse_outline(a, b)
    for ax in (left, right):
        ax.plot(xs, ys, color="0.6")
        ax.set_aspect("equal")
        ax.set_xlim(-a * 1.25, a * 1.25)
        ax.set_ylim(-1.5 * b, 1.5 * b)
        ax.set_xlabel("$x$ (scaled)")
        ax.set_ylabel("$y$ (scaled)")
    steps = 12
    for k in range(steps):
        x, y = orbit_position(a, b, w, period * k / steps)
        left.plot([x], [y], "o", color="C0", markersize=3.5)
    for k0 in (0, 3):  # two sectors of one step each: at apogee and at perigee
        t0, t1 = period * k0 / steps, period * (k0 + 1) / steps
        pts = [orbit_position(a, b, w, t0 + (t1 - t0) * j / 20) for j in range(21)]
        left.fill([0, *(p[0] for p in pts)], [0, *(p[1] for p in pts)], color="C0", alpha=0.2)
    t = period / 10
    x, y = orbit_position(a, b, w, t)
    for order, (colour, name) in enumerate(_ARROWS, start=1):
        dx, dy = orbit_derivative(a, b, w, t, order)
        tip = (x + dx / 2, y + dy / 2)
        left.annotate("", tip, (x, y), arrowprops={"arrowstyle": "->", "color": colour, "lw": 1.5})
        left.annotate(
            name,
            tip,
            textcoords="offset points",
            xytext=(3 if dx >= 0 else -3, 2 if dy >= 0 else -11),
            ha="left" if dx >= 0 else "right",
            color=colour,
        )
    speeds = apsis_speeds(a, b, w)
    left.set_title(f"(a) orbit: apsis speeds {speeds.ratio:.2f} : 1", fontsize="medium")
    for order, colour in zip(range(4), ("C0", "C1", "C2", "C3"), strict=True):
        dx, dy = orbit_derivative(a, b, w, t, order)
        scale = w**order
        tip = (dx / scale, dy / scale)
        right.annotate("", tip, (0, 0), arrowprops={"arrowstyle": "->", "color": colour, "lw": 1.5})
        right.annotate(
            _NAMES[order],
            tip,
            textcoords="offset points",
            xytext=(4 if tip[0] >= 0 else -4, 4 if tip[1] >= 0 else -12),
            ha="left" if tip[0] >= 0 else "right",
            color=colour,
        )
    right.set_title("(b) derivatives a quarter turn apart", fontsize="medium")


@figure(
    "triads",
    "Fig. 11.7 and (11.18)",
    (
        "The Q-ellipse r·Q·r = 1 (solid, a = 2, b = 1/2) and its dual p·Q⁻¹·p = 1 (dashed, "
        "radii 1/a and 1/b), in scaled lengths, with the triad sequence started at φ₀ = π/4: "
        "the radius r(φₖ₋₁) = (a cos φₖ, b sin φₖ) and the perpendicular p(φₖ₊₁) = Q·r(φₖ₋₁) of"
        " each triad, on lines of slope (a/b)ᵏ (dotted)."
    ),
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
    dual = dual_ellipse(a, b)
    fig.set_size_inches(6.0, 5.0)
    ax = fig.add_subplot()
    xs, ys = ellipse_outline(a, b)
    ax.plot(xs, ys, color="C0", label=r"$Q$-ellipse $\mathbf{r}\cdot Q\cdot\mathbf{r} = 1$")
    xs, ys = ellipse_outline(dual.radius_x, dual.radius_y)
    ax.plot(
        xs, ys, "--", color="C1", label=r"dual ellipse $\mathbf{p}\cdot Q^{-1}\cdot\mathbf{p} = 1$"
    )
    for k in range(-2, 3):
        phi = triad_angle(a, b, phi0, k)
        triad = triad_vectors(a, ab, phi0, k)
        r, p = triad.r, triad.p
        ax.plot([0, r[0]], [0, r[1]], color="C0", linewidth=1)
        ax.plot([0, p[0]], [0, p[1]], color="C1", linewidth=1)
        reach = 2.2
        ax.plot(
            [0, reach * math.cos(phi)], [0, reach * math.sin(phi)], ":", color="0.6", linewidth=1
        )
        ax.annotate(
            rf"$\varphi_{{{k}}}$",
            (reach * math.cos(phi), reach * math.sin(phi)),
            textcoords="offset points",
            xytext=(2, 2),
        )
    ax.set_aspect("equal")
    ax.set_xlim(-0.2, 2.6)
    ax.set_ylim(-0.2, 2.45)
    ax.set_xlabel(r"$x$, $p_x$ (scaled)")
    ax.set_ylabel(r"$y$, $p_y$ (scaled)")
    ax.legend(loc="upper right", fontsize="small")


@figure(
    "rod-cycloids",
    "Figs. 11.9 and 11.10",
    (
        "A free rod of length 2l struck at h = l/2 above its centre rolls on a 'tire' of "
        "percussion radius p = l²/(3h) = 2l/3 along the road y = −p (lengths in units of l): "
        "the point at p on the far side traces a normal cycloid, points inside it prolate and "
        "the ends curlate ones; the centre moves straight. The crosses mark the radius of "
        "gyration l/√3 = 0.577 l, where h = p (the book prints 0.866)."
    ),
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
    fig.set_size_inches(10.0, 3.9)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    points = (
        (half, "C0", "end $s = +l$"),
        (-half, "C4", "end $s = -l$"),
        (-p, "C3", "$s = -p$"),
        (p / 2, "C2", "$s = +p/2$"),
        (0.0, "k", "centre $s = 0$"),
    )
    for s, colour, name in points:
        path = [rod_point_position(1.0, half, 1.0, h, s, t) for t in times]
        ax.plot(
            [q[0] / half for q in path],
            [q[1] / half for q in path],
            color=colour,
            linewidth=1.2,
            label=f"{name}: {cycloid_kind(s, p)}",
        )
    for k, t in enumerate((0.0, turn / 4, turn / 2)):
        ends = [rod_point_position(1.0, half, 1.0, h, s, t) for s in (-half, half)]
        ax.plot(
            [e[0] / half for e in ends],
            [e[1] / half for e in ends],
            color="0.55",
            linewidth=2.5,
            solid_capstyle="round",
            label="the rod" if k == 0 else None,
        )
    ax.axhline(-p / half, color="0.7", linewidth=1, linestyle="--", label="road $y = -p$")
    gyration = radius_of_gyration(length) / half
    ax.plot([0, 0], [gyration, -gyration], "x", color="k", ms=7, label=r"gyration radius $l/√3$")
    ax.set_aspect("equal")
    ax.set_ylim(-1.25, 1.25)
    ax.set_xlabel("$x/l$")
    ax.set_ylabel("$y/l$")
    ax.set_title(f"struck at $h = l/{divisor:g}$: $p = {p / half:.3f}\\,l$", fontsize="medium")
    fig.legend(loc="outside right center", fontsize="small")
