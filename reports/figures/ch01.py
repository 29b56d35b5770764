"""Figures of chapter 1, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

import math
from fractions import Fraction
from typing import TYPE_CHECKING

from matplotlib import colormaps

from mechmodel.ellipse import ellipse_outline
from mechmodel.geometry import (
    minkowski_slope,
    newton_slope,
    rescaled_slope,
    unit_circle_segments,
    whirling_rectangles,
)
from reference.tables import unit_factor
from reports.figures import figure, value_of

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim

SQUARES = 5  # half-width of the plots of Fig. 1.2, in graph squares
LIMITS = (-0.15, 2.0)  # the extent of both panels of Figs. 1.4b and 1.5b


def _si(claims: dict[str, EvaluatedClaim], ident: str) -> float:
    """A claim's value in SI units (the model's units)."""
    return value_of(claims, ident) * unit_factor(claims[ident].unit)


def _fraction(x: float) -> str:
    return str(Fraction(x).limit_denominator(100))


def _slope_axes(ax: Axes, sx: float, sy: float, horizontal: str) -> None:
    """Square grid of Fig. 1.2, ticks labelled in miles and seconds."""
    ticks = range(-SQUARES, SQUARES + 1)
    ax.set_xticks(ticks)
    ax.set_yticks(ticks)
    ax.set_xlim(-SQUARES, SQUARES)
    ax.set_ylim(-SQUARES, SQUARES)
    ax.set_aspect("equal")
    ax.grid(color="0.88")
    # with a true minus sign, as matplotlib's own tick labels have
    miles = [f"{k * sx:g}".replace("-", "\u2212") if k % SQUARES == 0 else "" for k in ticks]
    seconds = [f"{k * sy:g}".replace("-", "\u2212") if k % 2 == 0 else "" for k in ticks]
    if horizontal == "x":
        ax.set_xticklabels(miles)
        ax.set_yticklabels(seconds)
        ax.set_xlabel("position $x$ (mile)")
        ax.set_ylabel("time $t$ (s)")
    else:
        ax.set_xticklabels(seconds)
        ax.set_yticklabels(miles)
        ax.set_xlabel("time $t$ (s)")
        ax.set_ylabel("position $x$ (mile)")


@figure(
    "slope-plots",
    "Fig. 1.2",
    (
        "The jet (600 mph), SUV (60 mph) and VW (10 mph) as lines of time t (s) against "
        "position x (mile) in Minkowski's plot (a) and of x against t in Newton's (b), one "
        "graph square being 0.1 mile by 6 s so that the SUV line is the 1:1 diagonal of both. "
        "The slopes, from the model, are in graph squares; the two plots are mirror images in "
        "that diagonal."
    ),
    (
        "ch01.plot.unit-speed-mph",
        "ch01.plot.suv-slope",
        "ch01.plot.jet-minkowski-slope",
        "ch01.plot.jet-newton-slope",
        "ch01.plot.vw-minkowski-slope",
        "ch01.plot.vw-newton-slope",
        "ch01.rescale.suv-slope-fps",
    ),
)
def _slope_plots(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    sx, sy = _si(claims, "ch01.plot.sx"), _si(claims, "ch01.plot.sy")
    lines = (
        ("jet", "ch01.plot.v-jet", "C3"),
        ("SUV", "ch01.crash.v-suv", "C0"),
        ("VW", "ch01.crash.v-vw", "C2"),
    )
    fig.set_size_inches(9.2, 4.6)
    fig.set_layout_engine("constrained", w_pad=0.1)
    left, right = fig.subplots(1, 2)
    for name, ident, colour in lines:
        v, mph = _si(claims, ident), value_of(claims, ident)
        k_m, k_n = float(minkowski_slope(v, sx, sy)), float(newton_slope(v, sx, sy))
        ends = [-SQUARES, SQUARES]
        left.plot(ends, [k_m * e for e in ends], color=colour, label=f"{name} {mph:g} mph")
        right.plot(ends, [k_n * e for e in ends], color=colour)
        for ax, k in ((left, k_m), (right, k_n)):
            # label each line where it leaves the plot, in the upper right quadrant
            reach = min(SQUARES, SQUARES / k) * 0.8
            ax.annotate(
                f"{_fraction(k)}",
                (reach, k * reach),
                color=colour,
                fontsize="small",
                textcoords="offset points",
                xytext=(-3, 4),
                ha="right",
                fontweight="bold",
            )
    _slope_axes(left, value_of(claims, "ch01.plot.sx"), value_of(claims, "ch01.plot.sy"), "x")
    _slope_axes(right, value_of(claims, "ch01.plot.sx"), value_of(claims, "ch01.plot.sy"), "t")
    left.set_title(r"(a) Minkowski: slope $\Delta t/\Delta x = 1/v$", fontsize="medium")
    right.set_title(r"(b) Newton: slope $\Delta x/\Delta t = v$", fontsize="medium")
    fx = value_of(claims, "ch01.rescale.feet-per-mile")
    fy = value_of(claims, "ch01.rescale.seconds-per-minute")
    suv = newton_slope(_si(claims, "ch01.crash.v-suv"), sx, sy)
    right.text(
        0.97,
        0.03,
        f"in ft vs s the SUV slope\nis $(f_x/f_y)\\cdot{suv:.4g}$"
        f" = {rescaled_slope(suv, fx, fy):.4g}",
        transform=right.transAxes,
        ha="right",
        va="bottom",
        fontsize="small",
        bbox={"facecolor": "white", "edgecolor": "0.8"},
    )
    left.legend(loc="upper left", fontsize="small")


def _circle_segments(ax: Axes, sigma: float) -> None:
    """Fig. 1.4b: the six trigonometric segments of angle sigma on the unit circle."""
    seg = unit_circle_segments(sigma)
    xs, ys = ellipse_outline(1.0, 1.0)
    ax.plot(xs, ys, color="0.75")
    p = (seg.base, seg.altitude)
    drawn = (
        ("radius 1", (0, 0), p, "0.3", "-"),
        (rf"$\cos\sigma = {seg.base:.4f}$", (0, 0), (seg.base, 0), "C0", "-"),
        (rf"$\sin\sigma = {seg.altitude:.4f}$", (seg.base, 0), p, "C1", "-"),
        (rf"$\tan\sigma = {seg.tangent:.4f}$", p, (seg.secant, 0), "C3", "-"),
        (rf"$\cot\sigma = {seg.cotangent:.4f}$", p, (0, seg.cosecant), "C2", "-"),
        (rf"$\sec\sigma = {seg.secant:.4f}$", (0, 0), (seg.secant, 0), "C4", ":"),
        (rf"$\csc\sigma = {seg.cosecant:.4f}$", (0, 0), (0, seg.cosecant), "C5", ":"),
    )
    for label, a, b, colour, style in drawn:
        ax.plot([a[0], b[0]], [a[1], b[1]], style, color=colour, lw=2, label=label)
    ax.plot(*p, "o", color="k", markersize=3)
    ax.set_aspect("equal")
    ax.set_xlim(*LIMITS)
    ax.set_ylim(*LIMITS)
    ax.legend(loc="upper right", fontsize="small")
    ax.set_title(rf"(a) the segments of $\sigma = {sigma:g}$ rad", fontsize="medium")


def _whirl(ax: Axes, sigma: float, terms: int) -> None:
    """Fig. 1.5b: each side turned a quarter turn clockwise and shrunk by cot sigma."""
    seq = whirling_rectangles(sigma, terms)
    seg = unit_circle_segments(sigma)
    corners = [(seg.secant, 0.0)]  # start where the tangent tan(sigma) meets the x-axis
    direction = math.pi + seq.first_angle  # up the tangent line, towards the tangent point
    for length in seq.lengths:
        x, y = corners[-1]
        corners.append((x + length * math.cos(direction), y + length * math.sin(direction)))
        direction -= seq.rotation
    for k in range(len(corners) - 2):  # largest first: each nested one paints over the last
        (ax0, ay0), (bx, by), (cx, cy) = corners[k : k + 3]
        ax.fill(
            [ax0, bx, cx, ax0 + cx - bx],
            [ay0, by, cy, ay0 + cy - by],
            facecolor=colormaps["Blues"](0.12 + 0.1 * k),
            edgecolor="0.4",
            lw=0.6,
        )
    ax.plot([c[0] for c in corners], [c[1] for c in corners], "-", color="k", lw=1.5)
    quarter = [(x, y) for x, y in zip(*ellipse_outline(1.0, 1.0), strict=True) if x >= 0 <= y]
    ax.plot([q[0] for q in quarter], [q[1] for q in quarter], color="0.75", lw=0.8)
    names = [r"$\tan\sigma$", "1", r"$\cot\sigma$", r"$\cot^2\sigma$"]
    for k, name in enumerate(names):
        (x0, y0), (x1, y1) = corners[k], corners[k + 1]
        length = seq.lengths[k]
        ax.annotate(
            name if k == 1 else f"{name} = {length:.3f}",
            ((x0 + x1) / 2, (y0 + y1) / 2),
            fontsize="small",
            ha="center",
            va="center",
            bbox={"facecolor": "white", "edgecolor": "none", "alpha": 0.85, "pad": 0.5},
        )
    ax.set_aspect("equal")
    left = corners[1][0] - 0.25  # the leftmost corner, the tangent point, just inside
    ax.set_xlim(left, left + LIMITS[1] - LIMITS[0])
    ax.set_ylim(*LIMITS)
    ax.set_title(
        rf"(b) $\times\cot\sigma = {seq.scale_factor:.4f}$ per quarter turn", fontsize="medium"
    )


@figure(
    "trig-segments-whirl",
    "Figs. 1.4b and 1.5b",
    (
        "Left (Fig. 1.4b): the trigonometric ratios of σ = 1 rad as segments of the unit "
        "circle. Right (Fig. 1.5b): whirling rectangles whose sides tan σ, 1, cot σ, cot²σ, … "
        "each turn a quarter turn clockwise and shrink by cot σ, starting up the tangent "
        "segment at the slope angle σ − π/2 = −σc; lengths in units of the radius. The book "
        "prints that angle as −1 radian and the caption's cot σ with two digits swapped."
    ),
    (
        "ch01.fig14.base",
        "ch01.fig14.altitude",
        "ch01.fig14.tangent",
        "ch01.fig14.cotangent",
        "ch01.fig14.secant",
        "ch01.fig14.cosecant",
        "ch01.whirl.scale-percent",
        "ch01.whirl.scale-caption",
        "ch01.whirl.first-angle-deg",
    ),
)
def _trig_and_whirl(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    sigma = value_of(claims, "ch01.fig14.sigma")
    fig.set_size_inches(9.6, 4.9)
    fig.set_layout_engine("constrained", w_pad=0.1)
    left, right = fig.subplots(1, 2)
    _circle_segments(left, sigma)
    _whirl(right, value_of(claims, "ch01.whirl.sigma"), terms=7)
    for ax in (left, right):
        ax.set_xlabel("$x$ (radius 1)")
        ax.set_ylabel("$y$ (radius 1)")
