"""Figures of chapter 5, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from mechmodel.bangs import bang_history, ceiling_sequence, floor_bounce
from mechmodel.ellipse import ellipse_outline, energy_ellipse, kinetic_energy, velocity_radius
from mechmodel.operators import (
    bang_angle,
    integral_right_triangle,
    mass_scaling,
    mirror_angle,
    mirror_pair_rotation,
    reflection,
    rotation_angle,
    scaled_collision_matrix,
    scaled_double_bang_matrix,
    sigma,
)
from mechmodel.planar import apply, matrix_product
from reports.figures import as_floats, figure, value_of

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from mechmodel.typing import Matrix
    from reference.evaluation import EvaluatedClaim

# The book prints no heights for Fig. 5.1(b): the balls start stacked on the floor (the X2
# launcher of Fig. 4.3a) under a ceiling at unit height, which only sets the scale.
CEILING = 1
# A non-symmetric flag to show what mirrors and rotations do to it (Fig. 5.3).
FLAG = ((0.45, 0.1), (0.95, 0.1), (0.95, 0.26), (0.62, 0.26), (0.62, 0.42), (0.45, 0.42))


@figure(
    "bang-sequence-49-1",
    "Fig. 5.1(a)",
    (
        "The 49:1 pair under a ceiling in the plane of the velocities (v₁, v₂), scaled: each "
        "ball-ball and ceiling bang from the state (1, −1) after the floor bounce to the last "
        "bang, all on the energy ellipse."
    ),
    ("ch05.pair-49-1.v1-after-9", "ch05.pair-49-1.v1-after-11", "ch05.pair-49-1.v2-after-11"),
)
def _bang_sequence(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    m1, m2 = value_of(claims, "ch05.pair-49-1.m1"), value_of(claims, "ch05.pair-49-1.m2")
    v1, v2 = (
        value_of(claims, "ch05.pair-49-1.v1-start"),
        value_of(claims, "ch05.pair-49-1.v2-start"),
    )
    sequence = ceiling_sequence(m1, m2, v1, v2)
    fig.set_size_inches(8.0, 4.8)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    xs, ys = ellipse_outline(*energy_ellipse(m1, m2, v1, v2).radii)
    ax.plot(xs, ys, color="0.7", label="energy ellipse")
    points = sequence.velocities
    ax.plot(
        [float(p[0]) for p in points],
        [float(p[1]) for p in points],
        "-o",
        markersize=3,
        label=f"{sequence.count} bangs after the floor bounce",
    )
    for n, offset, ha in ((0, (6, -4), "left"), (8, (6, -4), "left"), (10, (-6, -10), "right")):
        ax.annotate(
            f"after Bang-{n + 1}",
            points[n],
            textcoords="offset points",
            xytext=offset,
            ha=ha,
            fontsize="small",
        )
    ax.set_xlabel(f"velocity $v_1$ of the big ball, $m_1 = {m1:g}$ (scaled)")
    ax.set_ylabel(f"velocity $v_2$ of $m_2 = {m2:g}$ (scaled)")
    ax.set_xlim(-1.25, 1.35)
    ax.legend(loc="upper right", fontsize="small")


@figure(
    "bang-history-49-1",
    "Fig. 5.1(b)",
    (
        "Heights against time of the 49:1 pair from the event simulator, stacked on the floor "
        "after Bang-1 with velocities (1, −1) under a ceiling at unit height (the book prints "
        "no heights), the floor open after Bang-1. Little m₂ rattles between m₁ and the ceiling"
        " and turns m₁ back; after Bang-21 both fall, and the last bang (off the plot) comes "
        "long after."
    ),
    (
        "ch05.pair-49-1.v1-after-9",
        "ch05.pair-49-1.v1-after-11",
        "ch05.pair-49-1.v2-after-11",
        "ch05.pair-49-1.game-over",
    ),
)
def _history_49_1(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    m1, m2 = value_of(claims, "ch05.pair-49-1.m1"), value_of(claims, "ch05.pair-49-1.m2")
    v1, v2 = (
        value_of(claims, "ch05.pair-49-1.v1-start"),
        value_of(claims, "ch05.pair-49-1.v2-start"),
    )
    # start just before Bang-1, the floor bounce, so that the numbering is the book's
    h = bang_history(m1, m2, 0, 0, floor_bounce(v1), v2, ceiling=CEILING, floor_bounces=1)
    shown = [e for e in h.bangs if e.y1 > -CEILING]
    end = shown[-1].time * 1.04
    times = [0, *(e.time for e in shown), end]
    paths = [h.positions_at(t) for t in times]
    fig.set_size_inches(8.0, 4.8)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    ax.axhline(CEILING, color="0.6", lw=3, label="ceiling")
    ax.axhline(0, color="0.3", lw=1.5, ls="--", label="floor (open after Bang-1)")
    ts = [float(t) for t in times]
    ax.plot(ts, [float(p[0]) for p in paths], color="C0", lw=2, label=f"$y_1$ of $m_1 = {m1:g}$")
    ax.plot(ts, [float(p[1]) for p in paths], color="C1", lw=0.9, label=f"$y_2$ of $m_2 = {m2:g}$")
    for e in shown:
        if e.kind == "12" and e.number % 4 == 0:
            ax.annotate(
                str(e.number),
                (e.time, e.y1),
                textcoords="offset points",
                xytext=(-4, -13),
                fontsize="small",
            )
    last = h.bangs[-1]
    ax.text(
        0.02,
        0.04,
        f"last bang: Bang-{last.number} at $t$ = {last.time:.3g}, $y$ = ${last.y1:.3g}$",
        transform=ax.transAxes,
        fontsize="small",
    )
    ax.set_xlabel("time $t$ (ceiling height / unit speed)")
    ax.set_ylabel("height $y$ (ceiling = 1)")
    ax.legend(loc="lower right", fontsize="small")


def _hand(ax: Axes, v: tuple[float, float], label: str, colour: str) -> None:
    ax.annotate("", v, (0, 0), arrowprops={"arrowstyle": "->", "color": colour, "lw": 1.2})
    ax.annotate(label, v, textcoords="offset points", xytext=(3, -10), fontsize="small")


@figure(
    "velocity-clock-49-1",
    "Fig. 5.2(b)-(c)",
    (
        "(b) The 49:1 sequence of Fig. 5.1 in mass-scaled velocities V = (v₁√m₁, v₂√m₂), where "
        "the energy ellipse is a circle: a ball bang reflects V in the collision line, a "
        "ceiling bang in the V₁ axis, so each double bang turns the clock hand by −θ. (c) The "
        "bang triangle with base m₁ − m₂, altitude 2√(m₁m₂) and hypotenuse M = m₁ + m₂ that "
        "defines θ."
    ),
    (
        "ch05.pair-49-1.theta",
        "ch05.pair-49-1.double-bang-angle",
        "ch05.pair-49-1.n-theta",
        "ch05.triangle-49-1.base",
        "ch05.triangle-49-1.altitude",
        "ch05.triangle-49-1.hypotenuse",
    ),
)
def _velocity_clock(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    m1, m2 = value_of(claims, "ch05.pair-49-1.m1"), value_of(claims, "ch05.pair-49-1.m2")
    start = (
        value_of(claims, "ch05.pair-49-1.v1-start"),
        value_of(claims, "ch05.pair-49-1.v2-start"),
    )
    fig.set_size_inches(9.6, 4.8)
    fig.set_layout_engine("constrained", w_pad=0.1)
    left, right = fig.subplots(1, 2, gridspec_kw={"width_ratios": (1.15, 1)})
    _clock(left, m1, m2, start, int(value_of(claims, "ch05.pair-49-1.n")))
    _bang_triangle(right, m1, m2)


def _clock(ax: Axes, m1: float, m2: float, start: tuple[float, float], n: int) -> None:
    """Fig. 5.2(b): the states of ``ceiling_sequence`` as hands of the V-space clock."""
    scale = mass_scaling(m1, m2)
    states = [apply(scale, v) for v in ceiling_sequence(m1, m2, *start).velocities]
    radius = velocity_radius(1, kinetic_energy((m1, m2), start))  # V = sqrt(m) v: a circle (5.6)
    ax.plot(*ellipse_outline(radius, radius), color="0.75")
    ax.plot([s[0] for s in states], [s[1] for s in states], "-", color="0.55", lw=0.7)
    mirror = mirror_angle(scaled_collision_matrix(m1, m2))
    c, s = radius * math.cos(mirror), radius * math.sin(mirror)
    ax.plot([-c, c], [-s, s], "--", color="C3", lw=1, label="collision line $v_1 = v_2$")
    for k in range(0, len(states), 2):  # after Bang-1, 3, 5, ...: the clock hands
        _hand(ax, states[k], f"{k + 1}" if k % 4 == 0 and k != 8 else "", "C0")
    power = scaled_double_bang_matrix(m1, m2, n)
    turned = apply(power, states[0])
    ax.annotate("", turned, (0, 0), arrowprops={"arrowstyle": "->", "color": "C2", "lw": 2})
    ax.plot(
        [],
        [],
        color="C2",
        label=f"$(CM)^{n}$: hand 1 turned {math.degrees(rotation_angle(power)):.2f}°".replace(
            "-", "\u2212"
        ),
    )
    ax.set_aspect("equal")
    ax.set_xlim(-1.15 * radius, 1.15 * radius)
    ax.set_ylim(-1.15 * radius, 1.15 * radius)
    ax.set_xlabel(r"$V_1 = v_1√m_1$ (scaled)")
    ax.set_ylabel(r"$V_2 = v_2√m_2$ (scaled)")
    turn = math.degrees(rotation_angle(scaled_double_bang_matrix(m1, m2)))
    ax.set_title(
        f"(b) each double bang $CM$ turns {turn:.2f}°".replace("-", "\u2212"), fontsize="medium"
    )
    ax.legend(loc="upper left", fontsize="small")


def _bang_triangle(ax: Axes, m1: float, m2: float) -> None:
    """Fig. 5.2(c), (f): the right triangle of the bang angle, sides scaled by M = m1 + m2."""
    t = integral_right_triangle(m1, m2)
    theta = math.degrees(bang_angle(m1, m2).angle)
    ax.fill([0, t.base, t.base], [0, 0, t.altitude], color="C0", alpha=0.2)
    base, altitude = float(t.base), float(t.altitude)
    ax.plot([0, base, base, 0], [0, 0, altitude, 0], color="C0")
    labels = (
        (f"$m_1 - m_2 = {t.base:g}$", (t.base / 2, 0), (0, -14), "center", 0),
        (rf"$2√(m_1 m_2) = {t.altitude:g}$", (t.base, t.altitude / 2), (4, 0), "left", 0),
        (f"$m_1 + m_2 = {t.hypotenuse:g}$", (t.base / 2, t.altitude / 2), (-8, 8), "right", theta),
        (rf"$\theta = {theta:.2f}°$", (0, 0), (26, 1), "left", 0),
    )
    for text, xy, offset, ha, rotation in labels:
        ax.annotate(
            text,
            xy,
            textcoords="offset points",
            xytext=offset,
            ha=ha,
            rotation=rotation,
            rotation_mode="anchor",
            fontsize="small",
        )
    ax.set_aspect("equal")
    ax.set_xlim(-t.base * 0.05, t.base * 1.4)
    ax.set_ylim(-t.altitude * 0.4, t.altitude * 1.3)
    ax.set_axis_off()
    ax.set_title(r"(c) bang triangle: $\cos\theta = (m_1 - m_2)/M$", fontsize="medium")


def _flag(ax: Axes, matrix: Matrix, colour: str, label: str, style: str = "-") -> None:
    points = [apply(matrix, p) for p in (*FLAG, FLAG[0])]
    ax.fill([p[0] for p in points], [p[1] for p in points], color=colour, alpha=0.35)
    xs, ys = as_floats(p[0] for p in points), as_floats(p[1] for p in points)
    ax.plot(xs, ys, style, color=colour, label=label)


def _mirror(ax: Axes, angle: float, colour: str, label: str | None = None) -> None:
    c, s = math.cos(angle), math.sin(angle)
    ax.plot([-1.1 * c, 1.1 * c], [-1.1 * s, 1.1 * s], ":", color=colour, lw=1.2, label=label)


def _mirror_axes(ax: Axes, title: str) -> None:
    """A picture of the plane: no axes, a legend under it."""
    ax.set_aspect("equal")
    ax.set_xlim(-1.15, 1.15)
    ax.set_ylim(-1.15, 1.15)
    ax.set_axis_off()
    ax.set_title(title, fontsize="medium")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, 0), fontsize="small", ncols=2)


@figure(
    "mirrors-and-rotations",
    "Fig. 5.3",
    (
        "(a) A flag and its images under the reflections ±σA (mirrors along the axes) and ±σB "
        "(mirrors at ±π/4), each mirror dotted in its image's colour. (b) Two mirrors σA and σφ"
        " tilted at φ/2 (the 60° of the clothing-store mirrors of Fig. 5.4a): the products σφσA"
        " and σAσφ are rotations by +φ and −φ, not reflections."
    ),
    (
        "ch05.sigma-b.mirror-angle",
        "ch05.minus-sigma-b.mirror-angle",
        "ch05.mirrors.rotation-ccw",
        "ch05.mirrors.rotation-cw",
    ),
)
def _mirrors(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    fig.set_size_inches(9.0, 5.2)
    fig.set_layout_engine("constrained", w_pad=0.1)
    left, right = fig.subplots(1, 2)
    _flag(left, sigma("0"), "k", "flag")
    for k, name in enumerate(("A", "-A", "B", "-B")):
        m = sigma(name)
        _flag(left, m, f"C{k}", f"${'-' if name[0] == '-' else '+'}\\sigma_{name[-1]}$")
        _mirror(left, mirror_angle(m), f"C{k}")
    _mirror_axes(left, r"(a) reflections $\pm\sigma_A$, $\pm\sigma_B$")
    half = math.radians(value_of(claims, "ch05.mirrors.angle-60"))
    s_a, s_phi = sigma("A"), reflection(2 * half)
    _flag(right, sigma("0"), "k", "flag")
    for m, name, colour in (
        (matrix_product(s_phi, s_a), r"$\sigma_\phi\sigma_A$", "C2"),
        (matrix_product(s_a, s_phi), r"$\sigma_A\sigma_\phi$", "C3"),
    ):
        turned = f"{math.degrees(rotation_angle(m)):+.0f}°".replace("-", "\u2212")
        _flag(right, m, colour, f"{name}: {turned}")
    _mirror(right, mirror_angle(s_a), "C0", r"$\sigma_A$ mirror")
    _mirror(
        right,
        mirror_angle(s_phi),
        "C1",
        rf"$\sigma_\phi$ mirror at $\phi/2$ = {math.degrees(half):g}°",
    )
    turn = math.degrees(mirror_pair_rotation(0, half))
    _mirror_axes(right, f"(b) mirrors {math.degrees(half):g}° apart: rotation by {turn:+.0f}°")
