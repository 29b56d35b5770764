"""Figures of chapter 7, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING

from mechmodel.contact import linear_target
from mechmodel.towers import independent_tower, zero_gap_tower
from reports.figures import figure, value_of

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim

# Fig. 4.4's pair, which Figs. 7.6-7.7 drop with no gap: the masses 7 and 1, drop speed 1.
PAIR = (7, 1)
LINEAR = 1  # the power of the linear force of Fig. 7.7


def _squeezes(positions: tuple[tuple[float, ...], ...]) -> list[float]:
    """Largest overlap of each pair of neighbouring balls over the run."""
    return [
        max(lo - up for lo, up in zip(a, b, strict=True)) for a, b in itertools.pairwise(positions)
    ]


def _soft_pair(ax: Axes, power: float, title: str) -> tuple[float, ...]:
    """Draw the zero-gap 7:1 pair's heights against time; return the final velocities (one
    per ball)."""
    run = zero_gap_tower(list(PAIR), power)
    finals = tuple(e.value for e in run.velocities)
    # stack the balls (sizes taken out by the model) with a size D larger than any squeeze,
    # and draw a little free flight after the contact ends
    size = 1.5 * max(max(-x for x in run.positions[0]), *_squeezes(run.positions))
    t_end = run.duration * 1.6
    for k, row in enumerate(run.positions):
        times = [*run.times, t_end]
        heights = [*row, row[-1] + finals[k] * (t_end - run.times[-1])]
        ax.plot(
            times,
            [h + k * size for h in heights],
            label=f"$m_{k + 1} = {PAIR[k]:g}$: leaves at $V_{k + 1}$ = {finals[k]:.3g}",
        )
    ax.axhline(0, color="k", linewidth=0.8)
    ax.set_xlabel("time $t$ (contact-time units)")
    ax.set_ylabel("height of each ball's bottom (scaled)")
    ax.set_title(title, fontsize="medium")
    ax.legend(fontsize="small", loc="lower right")
    return finals


@figure(
    "soft-pair-quartic",
    "Fig. 7.6",
    (
        "CrapCorp's zero-gap simulation: the 7:1 pair of Fig. 4.4 dropped at speed 1 onto the "
        "floor with quartic contact forces F = ky⁴ (floor and ball-ball alike, no gravity "
        "during the contact); heights of the balls' bottoms in scaled units. RumpCo's "
        "independent bangs give 0.5 and 2.5."
    ),
    ("ch07.crapcorp.v1", "ch07.crapcorp.v2", "ch07.rumpco.v1", "ch07.rumpco.v2"),
)
def _soft_pair_quartic(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    power = value_of(claims, "ch07.superball-force.power")
    fig.set_size_inches(7.6, 4.4)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    _soft_pair(ax, power, f"quartic force $F = k\\,y^{{{power:g}}}$")
    rump = independent_tower(list(PAIR), 1).velocities
    ax.text(
        0.02,
        0.95,
        f"independent bangs: $V_1$ = {rump[0]:g}, $V_2$ = {rump[1]:g}",
        transform=ax.transAxes,
        fontsize="small",
        va="top",
    )


@figure(
    "soft-pair-linear",
    "Fig. 7.7",
    (
        "Linear force kills super-elastic bounce: the same 7:1 pair with linear contact forces "
        "F = ky leaves nearly together (compare the quartic case of Fig. 7.6); heights of the "
        "balls' bottoms in scaled units."
    ),
    ("ch07.crapcorp.v2", "ch07.rumpco.v2"),
)
def _soft_pair_linear(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    fig.set_size_inches(7.6, 4.4)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    _soft_pair(ax, LINEAR, r"linear force $F = k\,y$")


@figure(
    "linear-targets",
    "Fig. 7.4",
    (
        "Total potentials u(y) = y above the target and ay² + y inside it (graph units, y = "
        "Y/10 m) for the hardball (a = 8), medium (a = 1) and softball (a = 1/4) targets, and "
        "the energy of the 30 m fall (dotted, y = 3). The dot is the book's hardball stop y = "
        "−0.61, where the target's 8y² alone takes up that energy; the total potential reaches "
        "it at −0.68."
    ),
    ("ch07.hardball.quadratic", "ch07.softball.quadratic", "ch07.hardball.stop"),
)
def _linear_targets(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    hard = value_of(claims, "ch07.hardball.quadratic")
    soft = value_of(claims, "ch07.softball.quadratic")
    height = value_of(claims, "ch07.hardball.fall-height")
    slope = value_of(claims, "ch07.graph.gravity-slope")
    fig.set_size_inches(7.6, 4.4)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    ys = [-4 + 0.02 * k for k in range(351)]
    for a, name in ((hard, "hardball"), (1, "medium"), (soft, "softball")):
        us = [slope * y + (a * y * y if y < 0 else 0) for y in ys]
        ax.plot(ys, us, label=f"{name}, $a = {a:g}$")
    ax.axhline(height, linestyle=":", color="0.4", label="energy of the fall")
    stop = linear_target(hard, height, value_of(claims, "ch07.daredevil.height")).stop
    ax.plot([stop], [hard * stop * stop + slope * stop], "ko", label="book's hardball stop")
    ax.set_ylim(-1.5, 4)
    ax.set_xlabel(r"height $y = Y/(10\,\mathrm{m})$ (graph units)")
    ax.set_ylabel("potential $u(y)$ (graph units)")
    ax.legend(fontsize="small", loc="lower right")
