"""Figures of chapter 9, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from mechmodel.fields import tunnel_period
from reports.figures import ellipse_points, figure, value_of

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim


@figure(
    "tunnel-and-orbit",
    "Fig. 9.8",
    "A body dropped through a tunnel across a uniform Earth and a satellite in the grazing "
    "circular orbit keep the same x coordinate and meet on the far side after half a period.",
    ("ch09.tunnel-time", "ch09.orbit-speed"),
)
def _tunnel(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    g = value_of(claims, "ch09.surface-gravity")
    radius = value_of(claims, "ch09.earth-radius")
    period = tunnel_period(g, radius)
    ax = fig.add_subplot()
    xs, ys = ellipse_points(1.0, 1.0)
    ax.plot(xs, ys, color="0.6", label="Earth's surface (= the orbit)")
    ax.plot([-1, 1], [0, 0], color="0.3", label="tunnel")
    for k in range(9):
        angle = math.pi * k / 8
        minutes = period * k / 16 / 60
        ax.plot([math.cos(angle)], [math.sin(angle)], "o", color="C0")
        ax.plot([math.cos(angle)], [0], "s", color="C1")
        ax.plot([math.cos(angle)] * 2, [0, math.sin(angle)], ":", color="0.7")
        if k in (0, 4, 8):
            ax.annotate(
                f"{minutes:.1f} min",
                (math.cos(angle), math.sin(angle)),
                textcoords="offset points",
                xytext=(4, 6),
                fontsize="small",
            )
    ax.set_aspect("equal")
    ax.set_xlabel("x / R")
    ax.legend(loc="lower center", fontsize="small")
