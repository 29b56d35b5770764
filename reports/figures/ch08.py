"""Figures of chapter 8, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from mechmodel.towers import independent_tower
from reports.figures import figure, value_of

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim


@figure(
    "tower-100-30-10",
    "Fig. 8.1(b)",
    "The 100/30/10 tower with independent collisions: each bang in the plane of the two "
    "velocities it changes, from START to END along the momentum line of slope -m_lower/m_upper.",
    ("ch08.tower-100-30-10.v1", "ch08.tower-100-30-10.v2-mid", "ch08.tower-100-30-10.v3"),
)
def _tower(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    masses = [value_of(claims, f"ch08.tower-100-30-10.m{k}") for k in (1, 2, 3)]
    tower = independent_tower(masses, value_of(claims, "ch08.tower-100-30-10.v-drop"))
    for k, bang in enumerate(tower.bangs):
        ax = fig.add_subplot(1, len(tower.bangs), k + 1)
        (a0, b0), (a1, b1) = bang.before, bang.after
        ax.plot([a0, a1], [b0, b1], "-o")
        ax.annotate("START", (a0, b0), textcoords="offset points", xytext=(5, -10))
        ax.annotate(
            f"END ({a1:.3g}, {b1:.3g})", (a1, b1), textcoords="offset points", xytext=(5, 5)
        )
        ax.set_xlabel(f"V{k + 1}")
        ax.set_ylabel(f"V{k + 2}")
        ax.set_title(
            f"Bang({k + 2}){k + 1}{k + 2}: masses {masses[k]:g}/{masses[k + 1]:g}", fontsize="small"
        )
        ax.axhline(0, color="0.8")
        ax.axvline(0, color="0.8")
    fig.suptitle(f"top ball leaves at V3 = {tower.velocities[-1]:.4g}", fontsize="small")
