"""Figures of chapter 4, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

import math
from fractions import Fraction
from typing import TYPE_CHECKING

from mechmodel.bangs import (
    bang_history,
    galileo_shifted_collision,
    x2_full_transfer_ratio,
    x2_infinite_ratio_launch,
    x2_launch,
)
from mechmodel.ellipse import ellipse_outline, energy_ellipse
from mechmodel.operators import bang_facet_slope, bang_line_slope
from reports.figures import figure, value_of

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from mechmodel.bangs import History
    from mechmodel.typing import Real
    from reference.evaluation import EvaluatedClaim

# How far the book's BounceIt panels of Fig. 4.9 (a) and (b) run: display settings of the
# figure, not claims.
FIG_4_9_BANGS = (15, 150)


def _history(claims: dict[str, EvaluatedClaim], bangs: int) -> History:
    """The 7:1 history of Figs. 4.6-4.12 (floor at 0, elastic ceiling) up to ``bangs`` bangs."""
    return bang_history(
        value_of(claims, "ch04.history.m1"),
        value_of(claims, "ch04.history.m2"),
        value_of(claims, "ch04.history.y1"),
        value_of(claims, "ch04.history.y2"),
        value_of(claims, "ch04.history.v1"),
        value_of(claims, "ch04.history.v2"),
        ceiling=value_of(claims, "ch04.history.ceiling"),
        max_bangs=bangs,
    )


def _ellipse(ax: Axes, claims: dict[str, EvaluatedClaim], label: str | None = None) -> None:
    e = energy_ellipse(
        value_of(claims, "ch04.history.m1"),
        value_of(claims, "ch04.history.m2"),
        value_of(claims, "ch04.history.v1"),
        value_of(claims, "ch04.history.v2"),
    )
    ax.plot(*ellipse_outline(*e.radii), color="0.75", label=label)


def _vv_axes(ax: Axes, lim: float = 3.2) -> None:
    ax.axhline(0, color="0.85", lw=0.8)
    ax.axvline(0, color="0.85", lw=0.8)
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_aspect("equal")
    ax.set_xlabel("velocity $V_1$ of $M_1$ (scaled)")
    ax.set_ylabel("velocity $V_2$ of $M_2$ (scaled)")


def _point(ax: Axes, p: tuple[Real, Real], text: str, offset: tuple[int, int]) -> None:
    xy = (float(p[0]), float(p[1]))
    ax.plot(*xy, "o", color="k", markersize=4)
    ax.annotate(text, xy, textcoords="offset points", xytext=offset, fontsize="small")


def _signed(x: Real) -> str:
    """x with its sign (none for 0), a true minus for a negative one."""
    return "0" if x == 0 else f"{x:+g}".replace("-", "\u2212")


def _two_panels(fig: Figure, height: float = 4.8) -> tuple[Axes, Axes]:
    """Two square velocity or position panels side by side, at the page's width."""
    fig.set_size_inches(9.6, height)
    fig.set_layout_engine("constrained", w_pad=0.1)
    left, right = fig.subplots(1, 2)
    return left, right


@figure(
    "x2-two-bangs",
    "Fig. 4.4",
    (
        "The two bangs of the X2 launcher (M₁:M₂ = 7:1, both dropped at unit speed) in the "
        "plane of the velocities (V₁, V₂), in units of the drop speed: (a) Bang-1(01), M₁ off "
        "the floor, a horizontal jump; (b) Bang-2(12), M₁ hits M₂, along the bang line of slope"
        " −M₁/M₂. Both stay on the energy ellipse."
    ),
    (
        "ch04.history.bang1.v1",
        "ch04.history.bang1.v2",
        "ch04.history.bang2.v1",
        "ch04.history.bang2.v2",
        "ch04.x2.bang-line-slope",
    ),
)
def _two_bangs(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    h = _history(claims, 2)
    start = h.start[2:]
    one, two = ((e.v1, e.v2) for e in h.bangs)
    slope = bang_line_slope(value_of(claims, "ch04.x2.m1"), value_of(claims, "ch04.x2.m2"))
    for ax, (a, b), name in zip(
        _two_panels(fig),
        ((start, one), (one, two)),
        ("(a) Bang-1(01): $M_1$ off the floor", "(b) Bang-2(12): $M_1$ hits $M_2$"),
        strict=True,
    ):
        _ellipse(ax, claims, "energy ellipse")
        ax.annotate("", b, a, arrowprops={"arrowstyle": "->", "color": "C3", "lw": 1.5})
        _point(ax, a, f"INIT ({_signed(a[0])}, {_signed(a[1])})", (-24, -16))
        _point(ax, b, f"FINAL ({_signed(b[0])}, {_signed(b[1])})", (6, 4))
        _vv_axes(ax)
        ax.set_title(name, fontsize="medium")
    ax.text(
        0.03, 0.03, f"bang line, slope {_signed(slope)}", transform=ax.transAxes, fontsize="small"
    )
    ax.legend(loc="upper left", fontsize="small")


@figure(
    "x2-final-locus",
    "Fig. 4.5",
    (
        "(a) The final velocities (V₁, V₂) of the X2 launch for mass ratios M₁/M₂ from 1/64 to "
        "1024 (line) and for an infinite one (point I): all lie on the 45° line CPL. (b) The "
        "bang lines from INIT (+1, −1) to the points U (ratio 1), M (the ratio that stops M₁, "
        "all energy to M₂), the 7:1 superball and pen, and I; dashed and dotted: the U line "
        "Galileo-boosted by −1 (the pool shot) and by half that. Velocities in units of the "
        "drop speed."
    ),
    (
        "ch04.x2.final-locus-angle",
        "ch04.x2.inf.speed-ratio",
        "ch04.x2.m-point.ratio",
        "ch04.x2.m-point.v1",
        "ch04.x2.u-point.final-v1",
        "ch04.x2.u-point.final-v2",
        "ch04.x2.pool-shot.before-v2",
        "ch04.x2.pool-shot.after-v1",
        "ch04.x2.half-speed.before-v2",
        "ch04.x2.half-speed.after-v1",
    ),
)
def _final_locus(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    v0 = -value_of(claims, "ch04.history.v1")  # the drop speed
    left, right = _two_panels(fig)
    ratios = [2 ** (k / 4) for k in range(-24, 41)]
    finals = [x2_launch(r, 1, v0) for r in ratios]
    left.plot(
        [float(f.v1) for f in finals],
        [float(f.v2) for f in finals],
        color="C0",
        lw=2,
        label="CPL",
    )
    for r in (Fraction(1, 4), 1, 4, 16):
        f = x2_launch(r, 1, v0)
        _point(left, (f.v1, f.v2), f"$M_1/M_2 = {r}$", (7, -9))
    inf = x2_infinite_ratio_launch(v0)
    _point(left, (inf.v1, inf.v2), f"I: $V_2 = {inf.speed_ratio:g}\\,V_0$", (-86, -3))
    named = (
        ("U", value_of(claims, "ch04.x2.u-point.ratio"), (-14, 7)),
        ("M", x2_full_transfer_ratio(v0), (-58, -3)),
        ("7:1", value_of(claims, "ch04.x2.mass-ratio"), (-76, -3)),
    )
    for name, ratio, offset in named:
        f = x2_launch(ratio, 1, v0)
        right.plot([float(f.start[0]), float(f.v1)], [float(f.start[1]), float(f.v2)], "-", lw=1)
        _point(right, (f.v1, f.v2), f"{name} ({_signed(f.v1)}, {_signed(f.v2)})", offset)
    right.plot(
        [float(inf.start[0]), float(inf.v1)], [float(inf.start[1]), float(inf.v2)], "-", lw=1
    )
    _point(right, (inf.v1, inf.v2), "I", (6, -4))
    _point(right, inf.start, "INIT", (4, -12))
    boost = value_of(claims, "ch04.x2.u-point.boost")
    u = value_of(claims, "ch04.x2.u-point.ratio")
    for scale, style in ((1, "--"), (Fraction(1, 2), ":")):
        shot = galileo_shifted_collision(u, 1, v0, -v0, boost, scale)
        right.annotate("", shot.after, shot.before, arrowprops={"arrowstyle": "->", "ls": style})
    right.text(-3.2, -2.6, "pool shots\n(U boosted)", fontsize="small")
    for ax, title in ((left, "(a) final point locus"), (right, "(b) points I, M, U")):
        _vv_axes(ax, lim=3.4)
        ax.set_title(title, fontsize="medium")
    left.legend(loc="lower right", fontsize="small")


@figure(
    "bang-history-7-1",
    "Figs. 4.6-4.8",
    (
        "Heights against time of the 7:1 pair from the event simulator (M₁ from height 1, M₂ "
        "from 3, both falling at unit speed; floor at 0, elastic ceiling at 7; scaled units) to"
        " Bang-9, each bang numbered with its kind (01 floor, 12 ball-ball, 02 ceiling). The "
        "cross is the book's y₂(2) = 3 at Bang-2, where the paths in fact meet."
    ),
    (
        "ch04.history.bang1.time",
        "ch04.history.bang2.time",
        "ch04.history.bang2.y1",
        "ch04.history.bang2.y2",
        "ch04.history.bang4.v1",
        "ch04.history.bang6.v1",
        "ch04.history.bang6.v2",
        "ch04.history.bang7.number",
        "ch04.history.bang9.number",
    ),
)
def _space_time(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    last = int(value_of(claims, "ch04.history.bang9.number"))
    h = _history(claims, last)
    end = h.bangs[-1].time * 1.06
    times = [0, *(e.time for e in h.bangs), end]
    paths = [h.positions_at(t) for t in times]
    fig.set_size_inches(9.0, 4.6)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    ceiling = value_of(claims, "ch04.history.ceiling")
    ax.axhline(0, color="0.3", lw=3, label="floor")
    ax.axhline(ceiling, color="0.6", lw=3, label="ceiling")
    ts = [float(t) for t in times]
    ax.plot(ts, [float(p[0]) for p in paths], "-", color="C0", label="$y_1$ of $M_1 = 7$")
    ax.plot(ts, [float(p[1]) for p in paths], "-", color="C1", label="$y_2$ of $M_2 = 1$")
    offsets = {"01": (-10, -13), "12": (6, -5), "02": (-10, 5)}  # floor: below, ceiling: above
    for e in h.bangs:
        ax.annotate(
            f"{e.number}({e.kind})",
            (e.time, e.y2 if e.kind == "02" else e.y1),
            textcoords="offset points",
            xytext=offsets[e.kind],
            fontsize="small",
        )
    two = h.bangs[1]
    ax.plot([float(two.time)], [value_of(claims, "ch04.history.bang2.y2")], "x", color="C3", ms=7)
    ax.annotate(
        "book: $y_2(2) = 3$",
        (two.time, value_of(claims, "ch04.history.bang2.y2")),
        textcoords="offset points",
        xytext=(6, 2),
        fontsize="small",
        color="C3",
    )
    ax.set_xlabel("time $t$ (scaled)")
    ax.set_ylabel("height $y$ (scaled)")
    ax.set_ylim(-0.8, ceiling + 1.9)
    ax.legend(loc="upper right", fontsize="small", ncols=4)


@figure(
    "energy-ellipse-7-1",
    "Fig. 4.9",
    (
        "The 7:1 history in the plane of the velocities (V₁, V₂), in units of the drop speed, "
        "after 15 (a) and 150 (b) bangs: every bang jumps between two points of the energy "
        "ellipse 7V₁² + V₂² = 8 (horizontally off the floor, vertically off the ceiling, at "
        "slope −7 between the balls). Its semi-axes are a = √(2 KE/M₁) = √(8/7) along V₁ and b "
        "= √8: the book prints the two values the other way round."
    ),
    (
        "ch04.ellipse.twice-energy",
        "ch04.ellipse.minor",
        "ch04.ellipse.major",
    ),
)
def _ellipse_fill(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    e = energy_ellipse(
        value_of(claims, "ch04.history.m1"),
        value_of(claims, "ch04.history.m2"),
        value_of(claims, "ch04.history.v1"),
        value_of(claims, "ch04.history.v2"),
    )
    panels = _two_panels(fig)
    fig.set_size_inches(7.2, 5.6)
    for k, (ax, bangs) in enumerate(zip(panels, FIG_4_9_BANGS, strict=True)):
        h = _history(claims, bangs)
        states = [h.start[2:], *((b.v1, b.v2) for b in h.bangs)]
        ax.plot(*ellipse_outline(*e.radii), color="0.7")
        width = 0.8 if bangs < 50 else 0.3
        ax.plot(
            [float(s[0]) for s in states], [float(s[1]) for s in states], "-", lw=width, color="C0"
        )
        _vv_axes(ax, lim=3.2)
        ax.set_xlim(-1.9, 1.9)  # the ellipse is tall and narrow
        ax.set_title(f"({'ab'[k]}) to Bang-{bangs}", fontsize="medium")
    ax.annotate(
        f"$a$ = {e.radius_v1:.4g}",
        (e.radius_v1, 0),
        textcoords="offset points",
        xytext=(3, 4),
        fontsize="small",
        color="C3",
    )
    ax.annotate(
        f"$b$ = {e.radius_v2:.4g}",
        (0, e.radius_v2),
        textcoords="offset points",
        xytext=(5, 2),
        fontsize="small",
        color="C3",
    )


@figure(
    "space-space-7-1",
    "Figs. 4.11-4.12",
    (
        "The 7:1 history as one billiard ball, in scaled units: (a) the velocities v(n) = (V₁, "
        "V₂) after each bang, on the energy ellipse; (b) the positions y(n) = (y₁, y₂) bouncing"
        " inside the triangle of floor, ceiling and collision line y₂ = y₁, each step along "
        "v(n). At Bang-2: the bang line of slope −M₁/M₂ and its perpendicular facet. The book "
        "calls the bang line the bisector of the incident and reflected paths, which holds only"
        " for equal masses; the true bisector is grey."
    ),
    (
        "ch04.history.bang1.y1",
        "ch04.history.bang1.y2",
        "ch04.history.bang2.y2-vector",
        "ch04.history.bang3.y1",
        "ch04.history.bang3.y2",
        "ch04.collision-line.angle",
        "ch04.bang-line.slope",
        "ch04.bang-line.facet-slope",
    ),
)
def _space_space(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    last = int(value_of(claims, "ch04.history.bang6.number"))
    h = _history(claims, last)
    left, right = _two_panels(fig, 5.0)
    _ellipse(left, claims)
    velocities = [h.start[2:], *((e.v1, e.v2) for e in h.bangs)]
    for n, v in enumerate(velocities):
        left.annotate("", v, (0, 0), arrowprops={"arrowstyle": "->", "color": f"C{n}"})
        left.annotate(f"$v({n})$", v, textcoords="offset points", xytext=(3, 3), fontsize="small")
    _vv_axes(left)
    left.set_title("(a) velocity space", fontsize="medium")
    ceiling = value_of(claims, "ch04.history.ceiling")
    right.fill([0, 0, ceiling], [0, ceiling, ceiling], color="0.95", edgecolor="0.4")
    points = [h.start[:2], *((e.y1, e.y2) for e in h.bangs)]
    kinds = ["start", *(e.kind for e in h.bangs)]
    offsets = {"start": (4, -4), "01": (4, -4), "12": (6, -9), "02": (-26, 4)}
    for n, (point, kind) in enumerate(zip(points, kinds, strict=True)):
        if n + 1 < len(points):
            right.annotate(
                "", points[n + 1], point, arrowprops={"arrowstyle": "->", "color": f"C{n}"}
            )
        dx, dy = offsets[kind]
        if kind == "02":
            offsets["02"] = (4, 4)  # the next ceiling label goes to the right
        right.annotate(
            f"$y({n})$", point, textcoords="offset points", xytext=(dx, dy), fontsize="small"
        )
    m1, m2 = value_of(claims, "ch04.history.m1"), value_of(claims, "ch04.history.m2")
    (a1, a2), (b1, b2) = velocities[1], velocities[2]  # incident and reflected at Bang-2
    bisector = (b2 / math.hypot(b1, b2) - a2 / math.hypot(a1, a2)) / (
        b1 / math.hypot(b1, b2) - a1 / math.hypot(a1, a2)
    )
    x, y = points[2]
    for slope, style, colour, name in (
        (bang_line_slope(m1, m2), "--", "k", "bang line, slope $-M_1/M_2$"),
        (bang_facet_slope(m1, m2), ":", "k", "facet, slope $M_2/M_1$"),
        (bisector, "-", "0.6", f"bisector, slope {_signed(float(f'{bisector:.2g}'))}"),
    ):
        d = 0.9 / math.hypot(1, slope)
        right.plot([x - d, x + d], [y - slope * d, y + slope * d], style, color=colour, label=name)
    right.set_aspect("equal")
    right.set_xlim(-0.5, ceiling + 0.5)
    right.set_ylim(-0.5, ceiling + 0.8)
    right.set_xlabel("height $y_1$ of $M_1$ (scaled)")
    right.set_ylabel("height $y_2$ of $M_2$ (scaled)")
    right.set_title("(b) space-space: $y_2$ against $y_1$", fontsize="medium")
    right.legend(loc="lower right", fontsize="small")
