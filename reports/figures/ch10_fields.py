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
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim

GRID = 21  # points per side of the field-vector grid
LEVELS = 15  # level lines of each of Phi and A


def _finite(function: Callable[[complex], tuple[float, float]], z: complex) -> tuple[float, float]:
    """``function`` at z, or NaNs at a source, a sink or a pole (where the plot leaves a gap)."""
    try:
        return function(z)
    except (ValueError, ZeroDivisionError):
        return math.nan, math.nan


def _panel(
    ax: Axes,
    title: str,
    potential: Callable[[complex], complex],
    field: Callable[[complex], complex],
) -> None:
    """Field vectors of ``field`` over the level curves of Re and Im of ``potential``."""
    import numpy as np

    xs = np.linspace(-2, 2, 121)
    grid_x, grid_y = np.meshgrid(xs, xs)
    parts = [
        [_finite(lambda z: potential_parts(potential, z), complex(x, y)) for x in xs] for y in xs
    ]
    phi = np.array([[p[0] for p in row] for row in parts])
    big_a = np.array([[p[1] for p in row] for row in parts])
    for values, colour in ((phi, "C0"), (big_a, "C3")):
        # evenly spaced levels over the bulk of the values, not out to a pole's infinities
        low, high = np.nanpercentile(values, [5, 95])
        levels = np.linspace(low, high, LEVELS)
        ax.contour(grid_x, grid_y, values, levels=levels, colors=colour, linewidths=0.6)
    ticks = np.linspace(-1.8, 1.8, GRID)
    points = [complex(x, y) for y in ticks for x in ticks if abs(complex(x, y)) > 0.3]
    vectors = [_finite(lambda z: plot_field(field, z), z) for z in points]
    kept = [(z, u, v) for z, (u, v) in zip(points, vectors, strict=True) if math.hypot(u, v) > 0]
    ax.quiver(
        [z.real for z, _, _ in kept],
        [z.imag for z, _, _ in kept],
        [u / math.hypot(u, v) for _, u, v in kept],
        [v / math.hypot(u, v) for _, u, v in kept],
        color="0.3",
        scale=30,
        width=0.004,
    )
    ax.set_title(title, fontsize="small")
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])


@figure(
    "complex-potentials",
    "Figs. 10.7-10.14",
    "Complex potentials phi and their fields f = dphi/dz: the field vector f* (grey arrows, "
    "unit length) over the level lines of Phi = Re phi (blue, equipotentials) and A = Im phi "
    "(red, field lines) for phi = z^2/2 (field z), z^3/3 (field z^2), ln z (the line source "
    "of strength q), i ln z (the vortex), -1/z (field 1/z^2) and -1/(2z^2) (field 1/z^3).",
    ("ch10.source.q",),
)
def _complex_potentials(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    q = value_of(claims, "ch10.source.q")
    cases = (
        ("f = z", lambda z: z * z / 2, lambda z: z),
        ("f = z^2", lambda z: z**3 / 3, lambda z: z * z),
        ("line source: phi = q ln z", lambda z: q * cmath.log(z), lambda z: q / z),
        ("vortex: phi = i q ln z", lambda z: 1j * q * cmath.log(z), lambda z: 1j * q / z),
        ("dipole: phi = -1/z", lambda z: -1 / z, lambda z: 1 / z**2),
        ("quadrupole: phi = -1/(2 z^2)", lambda z: -1 / (2 * z * z), lambda z: 1 / z**3),
    )
    for k, (title, potential, field) in enumerate(cases, start=1):
        _panel(fig.add_subplot(2, 3, k), title, potential, field)


@figure(
    "dipole-pair",
    "Fig. 10.11 and (10.41)",
    "A source +1 and a sink -1 at z = -D/2 and +D/2 (left) and the point dipole they tend to as "
    "D shrinks with q D fixed (right): the field vectors f* of f = 1/(z + D/2) - 1/(z - D/2) "
    "and of -D/z^2.",
    ("ch10.dipole.position-divisor",),
)
def _dipole(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    divisor = value_of(claims, "ch10.dipole.position-divisor")
    separation = 1.0

    def pair(z: complex) -> complex:
        return dipole_pair_field(z, separation, divisor)

    def pair_potential(z: complex) -> complex:
        s = separation / divisor
        return cmath.log(z + s) - cmath.log(z - s)

    _panel(fig.add_subplot(1, 2, 1), "source-sink pair, D = 1", pair_potential, pair)
    _panel(
        fig.add_subplot(1, 2, 2),
        "point dipole",
        lambda z: separation / z,
        lambda z: -separation / z**2,
    )


@figure(
    "stereographic-map",
    "Fig. 10.15",
    "The stereographic picture of 1/z: a sphere of diameter D stands on the w-plane at S and "
    "touches the z-plane at N; the line from S through a point P of the sphere meets the z-plane "
    "at |z| = D tan(theta/2), the line from N through P meets the w-plane at |w| = D cot(theta/2), "
    "so that |z||w| = D^2 (w = 1/z for D = 1). Rays drawn for theta = 30 to 150 degrees.",
    ("ch10.stereo.diameter",),
)
def _stereographic(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    d = value_of(claims, "ch10.stereo.diameter")
    ax = fig.add_subplot()
    angles = [math.pi * k / 100 for k in range(201)]
    ax.plot(
        [d / 2 * math.sin(a) for a in angles],
        [d / 2 + d / 2 * math.cos(a) for a in angles],
        color="0.4",
    )
    ax.axhline(d, color="C0", linewidth=0.8)
    ax.axhline(0, color="C3", linewidth=0.8)
    ax.annotate("z-plane", (-2.4 * d, d), textcoords="offset points", xytext=(0, 4), color="C0")
    ax.annotate("w-plane", (-2.4 * d, 0), textcoords="offset points", xytext=(0, 4), color="C3")
    for degrees in (30, 60, 120, 150):
        theta = math.radians(degrees)
        point = stereographic_projection(theta, d)
        px, py = d / 2 * math.sin(theta), d / 2 + d / 2 * math.cos(theta)
        ax.plot([0, point.z_radius], [0, d], color="C0", linewidth=0.7)
        ax.plot([0, point.w_radius], [d, 0], color="C3", linewidth=0.7)
        ax.plot([px], [py], "ko", markersize=3)
        ax.annotate(
            f"{degrees}°: |z| = {point.z_radius:.2f}, |w| = {point.w_radius:.2f}",
            (point.z_radius, d),
            textcoords="offset points",
            xytext=(2, 6),
            fontsize="x-small",
            rotation=30,
        )
    ax.plot([0, 0], [0, d], "k:", linewidth=0.6)
    ax.annotate("N", (0, d), textcoords="offset points", xytext=(-10, 4))
    ax.annotate("S", (0, 0), textcoords="offset points", xytext=(-10, -12))
    ax.set_xlim(-2.5 * d, 4 * d)
    ax.set_ylim(-0.3 * d, 1.6 * d)
    ax.set_aspect("equal")
    ax.set_yticks([])
