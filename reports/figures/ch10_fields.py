"""Figures of chapter 10's second half: complex potentials and their fields, the dipole and the
stereographic map, redrawn from ``mechmodel.complexfields`` (see ``reports.figures``).

A potential phi(z) = Phi + i A has the field f = dphi/dz; the book plots f* = (Re f, -Im f), the
field vector, over the level curves of Phi (equipotentials) and A (field lines) (Figs. 10.7-10.14).
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Callable
from typing import TYPE_CHECKING

from mechmodel.complexfields import (
    dipole_pair_field,
    plot_field,
    potential_parts,
    stereographic_projection,
)
from reports.figures import figure, value_of

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim

SPAN = 2.0  # each panel shows |Re z|, |Im z| <= SPAN
ARROWS = 11  # field vectors per side of the panel
LEVELS = 11  # level lines of each of Phi and A
ARROW_LENGTH = 0.26  # of every field vector, in units of z (only the direction is drawn)
GAP = 0.22  # no field vector this close to a source, sink or pole


def _finite(function: Callable[[complex], tuple[float, float]], z: complex) -> tuple[float, float]:
    """``function`` at z, or NaNs at a source, a sink or a pole (where the plot leaves a gap)."""
    try:
        return function(z)
    except (ValueError, ZeroDivisionError):
        return math.nan, math.nan


def _without_jumps(values: npt.NDArray[np.float64], jump: float) -> npt.NDArray[np.float64]:
    """``values`` with NaN on both sides of every jump larger than ``jump`` between grid
    neighbours: a branch cut (the 2 pi of ln z), or the last cells around a pole, where the
    level lines would otherwise pile up into one thick line."""
    import numpy as np

    cut = np.zeros(values.shape, dtype=bool)
    across = np.abs(np.diff(values, axis=1)) > jump
    cut[:, 1:] |= across
    cut[:, :-1] |= across
    down = np.abs(np.diff(values, axis=0)) > jump
    cut[1:, :] |= down
    cut[:-1, :] |= down
    return np.where(cut, np.nan, values)


def _panel(
    ax: Axes,
    title: str,
    potential: Callable[[complex], complex],
    field: Callable[[complex], complex],
    singular: tuple[complex, ...] = (0j,),
    hole: float = 0.0,
    levels: tuple[list[float] | None, list[float] | None] = (None, None),
) -> None:
    """Field vectors of ``field`` over the level curves of Re and Im of ``potential``, no level
    line nearer than ``hole`` to a singular point (where they all crowd in), at ``levels``
    (of Phi, of A) where given, else evenly spaced over the bulk of the values."""
    import numpy as np

    xs = np.linspace(-SPAN, SPAN, 161)
    grid_x, grid_y = np.meshgrid(xs, xs)
    parts = [
        [_finite(lambda z: potential_parts(potential, z), complex(x, y)) for x in xs] for y in xs
    ]
    phi = np.array([[p[0] for p in row] for row in parts])
    big_a = np.array([[p[1] for p in row] for row in parts])
    near = np.zeros(phi.shape, dtype=bool)
    for s in singular:
        near |= np.hypot(grid_x - s.real, grid_y - s.imag) < hole
    for values, colour, chosen in ((phi, "C0", levels[0]), (big_a, "C3", levels[1])):
        values = np.where(near, np.nan, values)
        # evenly spaced levels over the bulk of the values, not out to a pole's infinities
        low, high = np.nanpercentile(values, [5, 95])
        ax.contour(
            grid_x,
            grid_y,
            _without_jumps(values, (high - low) / 2),
            levels=np.linspace(low, high, LEVELS) if chosen is None else chosen,
            colors=colour,
            linewidths=0.7,
            linestyles="solid",
        )
    ticks = np.linspace(-SPAN, SPAN, ARROWS + 2)[1:-1]
    points = [
        complex(x, y)
        for y in ticks
        for x in ticks
        if all(abs(complex(x, y) - s) > GAP for s in singular)
    ]
    vectors = [_finite(lambda z: plot_field(field, z), z) for z in points]
    kept = [(z, u, v) for z, (u, v) in zip(points, vectors, strict=True) if math.hypot(u, v) > 0]
    ax.quiver(
        [z.real for z, _, _ in kept],
        [z.imag for z, _, _ in kept],
        [ARROW_LENGTH * u / math.hypot(u, v) for _, u, v in kept],
        [ARROW_LENGTH * v / math.hypot(u, v) for _, u, v in kept],
        color="0.15",
        angles="xy",
        scale_units="xy",
        scale=1,
        pivot="middle",
        width=0.007,
        headwidth=4,
        headlength=4.5,
        headaxislength=4,
        zorder=3,
    )
    ax.plot([s.real for s in singular], [s.imag for s in singular], "o", color="k", ms=3.5)
    ax.set_title(title, fontsize="medium")
    ax.set_aspect("equal")
    ax.set_xlim(-SPAN, SPAN)
    ax.set_ylim(-SPAN, SPAN)
    ax.set_xticks([-2, -1, 0, 1, 2])
    ax.set_yticks([-2, -1, 0, 1, 2])
    ax.tick_params(labelsize="small")
    ax.set_xlabel(r"Re $z$", fontsize="small", labelpad=1)
    ax.set_ylabel(r"Im $z$", fontsize="small", labelpad=1)


def _sized_levels(value: Callable[[float], float], step: float) -> list[float]:
    """Levels of a multipole potential, whose level curves all pass through its pole: chosen by
    the size of the curve (diameter of a circle of 1/z, reach of a lobe of 1/z^2), ``step``,
    2 ``step``, ... 6 ``step``, instead of evenly by value, which would crowd them at the pole."""
    return sorted(sign * value(step * k) for k in range(1, 7) for sign in (-1, 1))


def _key(fig: Figure) -> None:
    """One legend for the colours of every panel, under the panels."""
    from matplotlib.lines import Line2D

    fig.legend(
        handles=[
            Line2D([], [], color="C0", lw=1.2, label=r"equipotentials $\Phi = \mathrm{Re}\,\phi$"),
            Line2D([], [], color="C3", lw=1.2, label=r"field lines $A = \mathrm{Im}\,\phi$"),
            Line2D(
                [], [], color="0.15", marker=r"$\rightarrow$", ms=12, ls="", label=r"field $f^*$"
            ),
        ],
        loc="outside lower center",
        ncols=3,
        fontsize="small",
        frameon=False,
    )


@figure(
    "complex-potentials",
    "Figs. 10.7-10.14",
    (
        "Six complex potentials φ(z) = Φ + iA over the z-plane with their fields f = dφ/dz: "
        "equipotentials Φ (blue), field lines A (red) and the direction of the plotted field "
        "vector f* (arrows of one length), for the fields z, z², the line source q/z and the "
        "vortex iq/z (q = 1), the dipole 1/z² and the quadrupole 1/z³; all dimensionless. The "
        "branch cut of ln z, where A or Φ jumps by 2πq, is left undrawn."
    ),
    ("ch10.source.q",),
)
def _complex_potentials(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    q = value_of(claims, "ch10.source.q")
    # the arguments of ln z at twelve rays 30 degrees apart, none on its branch cut (angle pi)
    rays = [q * math.pi * (2 * k + 1) / 12 for k in range(-6, 6)]
    circles = _sized_levels(lambda size: 1 / size, 0.7)
    lobes = _sized_levels(lambda size: 1 / (2 * size * size), 0.4)
    none: list[float] | None = None
    cases = (
        (r"$f = z$,  $\phi = z^2/2$", lambda z: z * z / 2, lambda z: z, (), 0.0, (none, none)),
        (r"$f = z^2$,  $\phi = z^3/3$", lambda z: z**3 / 3, lambda z: z * z, (), 0.0, (none, none)),
        (
            r"source: $\phi = q\,\ln z$",
            lambda z: q * cmath.log(z),
            lambda z: q / z,
            (0j,),
            0.1,
            (none, rays),
        ),
        (
            r"vortex: $\phi = i\,q\,\ln z$",
            lambda z: 1j * q * cmath.log(z),
            lambda z: 1j * q / z,
            (0j,),
            0.1,
            ([-r for r in reversed(rays)], none),
        ),
        (
            r"dipole: $\phi = -1/z$",
            lambda z: -1 / z,
            lambda z: 1 / z**2,
            (0j,),
            0.3,
            (circles, circles),
        ),
        (
            r"quadrupole: $\phi = -1/(2z^2)$",
            lambda z: -1 / (2 * z * z),
            lambda z: 1 / z**3,
            (0j,),
            0.1,
            (lobes, lobes),
        ),
    )
    fig.set_size_inches(10.5, 7.6)
    fig.set_layout_engine("constrained", w_pad=0.06, h_pad=0.06)
    for k, (title, potential, field, singular, hole, levels) in enumerate(cases, start=1):
        _panel(fig.add_subplot(2, 3, k), title, potential, field, singular, hole, levels)
    _key(fig)


@figure(
    "dipole-pair",
    "Fig. 10.11 and (10.41)",
    (
        "(Left) A source +1 at z = −D/2 and a sink −1 at z = +D/2 (D = 1), with the field f = "
        "1/(z + D/2) − 1/(z − D/2); (right) the point dipole they tend to as D shrinks with the"
        " charge times D held fixed, f = −D/z². Equipotentials Φ (blue), field lines A (red) "
        "and the direction of f* (arrows); all dimensionless."
    ),
    ("ch10.dipole.position-divisor",),
)
def _dipole(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    divisor = value_of(claims, "ch10.dipole.position-divisor")
    separation = 1.0
    s = separation / divisor

    def pair(z: complex) -> complex:
        return dipole_pair_field(z, separation, divisor)

    def pair_potential(z: complex) -> complex:
        return cmath.log(z + s) - cmath.log(z - s)

    fig.set_size_inches(8.4, 4.6)
    fig.set_layout_engine("constrained", w_pad=0.08)
    left, right = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    _panel(left, rf"source-sink pair, $D = {separation:g}$", pair_potential, pair, (-s, s))
    for x, sign in ((-s, "+1"), (s, "\u22121")):
        left.annotate(
            sign,
            (x, 0),
            textcoords="offset points",
            xytext=(0, 7),
            ha="center",
            fontsize="small",
            fontweight="bold",
            bbox={"facecolor": "white", "edgecolor": "none", "pad": 0.6, "alpha": 0.85},
            zorder=4,
        )
    _panel(
        right,
        r"point dipole: $f = -D/z^2$",
        lambda z: separation / z,
        lambda z: -separation / z**2,
        hole=0.3,
        levels=(_sized_levels(lambda size: 1 / size, 0.7),) * 2,
    )
    _key(fig)


@figure(
    "stereographic-map",
    "Fig. 10.15",
    (
        "The stereographic picture of 1/z, lengths in units of the sphere's diameter D: the "
        "sphere stands on the w-plane at S and touches the z-plane at N; the line from S "
        "through a point P of the sphere at angle θ meets the z-plane at |z| = D tan(θ/2), the "
        "line from N through P the w-plane at |w| = D cot(θ/2), so that |z||w| = D² (w = 1/z "
        "for D = 1). Rays for θ = 30° to 150°."
    ),
    ("ch10.stereo.diameter",),
)
def _stereographic(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    d = value_of(claims, "ch10.stereo.diameter")
    fig.set_size_inches(9.0, 3.8)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    angles = [math.pi * k / 100 for k in range(201)]
    ax.plot(
        [d / 2 * math.sin(a) for a in angles],
        [d / 2 + d / 2 * math.cos(a) for a in angles],
        color="0.4",
    )
    ax.axhline(d, color="C0", linewidth=0.8)
    ax.axhline(0, color="C3", linewidth=0.8)
    ax.annotate(r"$z$-plane", (-2.4 * d, d), textcoords="offset points", xytext=(0, 4), color="C0")
    ax.annotate(r"$w$-plane", (-2.4 * d, 0), textcoords="offset points", xytext=(0, 4), color="C3")
    for degrees in (30, 60, 120, 150):
        theta = math.radians(degrees)
        point = stereographic_projection(theta, d)
        px, py = d / 2 * math.sin(theta), d / 2 + d / 2 * math.cos(theta)
        ax.plot([0, point.z_radius], [0, d], color="C0", linewidth=0.7)
        ax.plot([0, point.w_radius], [d, 0], color="C3", linewidth=0.7)
        ax.plot([px], [py], "ko", markersize=3)
        ax.plot([point.z_radius], [d], "o", color="C0", markersize=3)
        ax.plot([point.w_radius], [0], "o", color="C3", markersize=3)
        ax.annotate(
            f"{degrees}°", (px, py), textcoords="offset points", xytext=(4, 0), fontsize="small"
        )
        ax.annotate(
            f"$|z|$ = {point.z_radius:.2f}",
            (point.z_radius, d),
            textcoords="offset points",
            xytext=(0, 4),
            fontsize="small",
            color="C0",
            rotation=45,
            rotation_mode="anchor",
        )
        ax.annotate(
            f"$|w|$ = {point.w_radius:.2f}",
            (point.w_radius, 0),
            textcoords="offset points",
            xytext=(0, -5),
            ha="right",
            va="top",
            fontsize="small",
            color="C3",
            rotation=45,
            rotation_mode="anchor",
        )
    ax.plot([0, 0], [0, d], "k:", linewidth=0.6)
    ax.annotate("N", (0, d), textcoords="offset points", xytext=(-12, 4))
    ax.annotate("S", (0, 0), textcoords="offset points", xytext=(-12, -14))
    ax.set_xlim(-2.5 * d, 4.2 * d)
    ax.set_ylim(-0.75 * d, 1.75 * d)
    ax.set_aspect("equal")
    ax.set_xlabel("distance from the axis NS (units of $D$)")
    ax.set_ylabel("height above S (units of $D$)")
