"""Figures of chapter 5, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from mechmodel.bangs import ceiling_sequence
from mechmodel.collisions import kinetic_energy
from reports.figures import ellipse_points, figure, value_of

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim


@figure(
    "bang-sequence-49-1",
    "Fig. 5.1(a)",
    "The 49:1 pair under a ceiling in the (v1, v2) plane: each ball-ball bang and ceiling bang "
    "from the state (1, -1) after the floor bounce, to the last bang, on the energy ellipse.",
    ("ch05.pair-49-1.v1-after-9", "ch05.pair-49-1.v1-after-11", "ch05.pair-49-1.v2-after-11"),
)
def _bang_sequence(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    m1, m2 = value_of(claims, "ch05.pair-49-1.m1"), value_of(claims, "ch05.pair-49-1.m2")
    v1, v2 = (
        value_of(claims, "ch05.pair-49-1.v1-start"),
        value_of(claims, "ch05.pair-49-1.v2-start"),
    )
    sequence = ceiling_sequence(m1, m2, v1, v2)
    ax = fig.add_subplot()
    energy = kinetic_energy((m1, m2), (v1, v2))
    xs, ys = ellipse_points(math.sqrt(2 * energy / m1), math.sqrt(2 * energy / m2))
    ax.plot(xs, ys, color="0.7", label="energy ellipse")
    points = sequence.velocities
    ax.plot(
        [p[0] for p in points],
        [p[1] for p in points],
        "-o",
        markersize=3,
        label=f"{sequence.count} bangs after the floor bounce",
    )
    for n in (0, 8, 10):
        ax.annotate(
            f"after Bang-{n + 1}",
            points[n],
            textcoords="offset points",
            xytext=(6, -4),
            fontsize="small",
        )
    ax.set_xlabel("v1 (big ball)")
    ax.set_ylabel("v2 (little ball)")
    ax.legend(loc="upper right", fontsize="small")
