"""Figures of chapter 8, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING

from mechmodel.towers import geometric_tower, independent_tower, pellet_rocket, zero_gap_tower
from reports.figures import as_floats, figure, value_of

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim


@figure(
    "tower-100-30-10",
    "Fig. 8.1(b)",
    (
        "The 100/30/10 tower with independent collisions: each bang in the plane of the two "
        "velocities it changes (scaled), from START to END along the momentum line of slope "
        "−(lower mass)/(upper mass)."
    ),
    ("ch08.tower-100-30-10.v1", "ch08.tower-100-30-10.v2-mid", "ch08.tower-100-30-10.v3"),
)
def _tower(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    masses = [value_of(claims, f"ch08.tower-100-30-10.m{k}") for k in (1, 2, 3)]
    tower = independent_tower(masses, value_of(claims, "ch08.tower-100-30-10.v-drop"))
    fig.set_size_inches(9.0, 4.4)
    fig.set_layout_engine("constrained", w_pad=0.1)
    for k, bang in enumerate(tower.bangs):
        ax = fig.add_subplot(1, len(tower.bangs), k + 1)
        (a0, b0), (a1, b1) = bang.before, bang.after
        ax.plot(as_floats([a0, a1]), as_floats([b0, b1]), "-o")
        ax.annotate("START", (a0, b0), textcoords="offset points", xytext=(-8, -6), ha="right")
        ax.annotate(
            f"END ({a1:.3g}, {b1:.3g})", (a1, b1), textcoords="offset points", xytext=(8, -4)
        )
        ax.set_xlabel(f"velocity $V_{k + 1}$ (scaled)")
        ax.set_ylabel(f"velocity $V_{k + 2}$ (scaled)")
        ax.set_title(
            f"Bang-{k + 2}({k + 1}{k + 2}): masses {masses[k]:g}/{masses[k + 1]:g}",
            fontsize="medium",
        )
        ax.axhline(0, color="0.8")
        ax.axvline(0, color="0.8")
        ax.margins(0.25)
    fig.suptitle(f"top ball leaves at $V_3$ = {tower.velocities[-1]:.4g}", fontsize="medium")


# Fig. 8.1(c)'s linear law: F = k y, the power 1 (the label "F(y) = k y" prints no number).
LINEAR = 1


def _tower_paths(ax: Axes, masses: list[float], power: float, v_drop: float, title: str) -> None:
    """Heights (offsets) of a zero-gap tower's balls against time, and their final velocities."""
    run = zero_gap_tower(masses, power, v_drop)
    finals = [e.value for e in run.velocities]
    # stack the balls (sizes taken out by the model) with a size D larger than any squeeze
    squeezes = [max(-x for x in run.positions[0])]
    squeezes += [
        max(lo - up for lo, up in zip(a, b, strict=True))
        for a, b in itertools.pairwise(run.positions)
    ]
    size = 1.5 * max(squeezes)
    t_end = run.duration * 1.5
    for k, row in enumerate(run.positions):
        times = [*run.times, t_end]
        heights = [*row, row[-1] + finals[k] * (t_end - run.times[-1])]
        ax.plot(
            times,
            [h + k * size for h in heights],
            label=f"$m_{k + 1} = {masses[k]:g}$: $V_{k + 1}$ = {finals[k]:.3g}",
        )
    ax.axhline(0, color="k", linewidth=0.8)
    ax.set_title(title, fontsize="medium")
    ax.set_xlabel("time $t$ (contact-time units)")
    ax.set_ylabel("height of each ball's bottom (scaled)")
    ax.legend(fontsize="small", loc="upper left")


@figure(
    "tower-zero-gap",
    "Fig. 8.1(a), (c)",
    (
        "The 100/30/10 tower dropped at speed 1 with zero gaps, integrated with one contact law"
        " for the floor and both ball pairs and no gravity during the contact: (a) quartic F = "
        "ky⁴, the top ball leaves at 3.41; (c) linear F = ky, super-elastic bounce squelched. "
        "Heights of the balls' bottoms in scaled units."
    ),
    ("ch08.tower-100-30-10.v3-quartic", "ch08.tower-100-30-10.v3"),
)
def _tower_zero_gap(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    masses = [value_of(claims, f"ch08.tower-100-30-10.m{k}") for k in (1, 2, 3)]
    v_drop = value_of(claims, "ch08.tower-100-30-10.v-drop")
    fig.set_size_inches(9.6, 4.4)
    fig.set_layout_engine("constrained", w_pad=0.1)
    quartic = fig.add_subplot(1, 2, 1)
    _tower_paths(quartic, masses, 4, v_drop, "(a) quartic force $F = k\\,y^4$")
    _tower_paths(fig.add_subplot(1, 2, 2), masses, LINEAR, v_drop, "(c) linear force $F = k\\,y$")


@figure(
    "four-ball-towers",
    "Fig. 8.2(a), (b)",
    (
        "Velocities, in units of the drop speed, of the 4-ball towers with independent bangs, "
        "each ball 3 (a) or 7 (b) times the one above: at each bang the rising ball's velocity "
        "grows by the factor 2mₖ/(mₖ + mₖ₊₁) on V + 1, and the top ball reaches 5.75 and 9.72. "
        "Solid: each ball just after its bang; dotted: the final velocities."
    ),
    ("ch08.tower-3.top", "ch08.tower-7.top"),
)
def _four_ball_towers(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    n = round(value_of(claims, "ch08.tower-3.n-balls"))
    v_drop = value_of(claims, "ch08.tower-100-30-10.v-drop")
    fig.set_size_inches(7.6, 4.4)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    for k, (key, marker) in enumerate((("ch08.tower-3.ratio", "o"), ("ch08.tower-7.ratio", "s"))):
        ratio = value_of(claims, key)
        tower = geometric_tower(n, ratio, v_drop)
        rising = [tower.rebound, *(bang.v2 for bang in tower.bangs)]
        ax.plot(
            range(1, n + 1),
            as_floats(rising),
            f"-{marker}",
            label=f"({'ab'[k]}) ratio {ratio:g}: $V_{n}$ = {rising[-1]:.3g}",
        )
        ax.plot(
            range(1, n + 1),
            as_floats(tower.velocities),
            f":{marker}",
            color="0.6",
            label="final velocities" if k == 1 else None,
        )
    ax.plot(
        range(1, n + 1),
        [2**k - 1 for k in range(1, n + 1)],
        "k--",
        label="infinite ratio: $2^k - 1$",
    )
    ax.set_xticks(range(1, n + 1))
    ax.set_xlabel("ball $k$ (bottom = 1)")
    ax.set_ylabel("velocity $V_k$ (units of the drop speed)")
    ax.legend(fontsize="small")


@figure(
    "pellet-rocket",
    "Fig. 8.8",
    (
        "The rocket of 11 unit balls blown apart one pellet at a time at exhaust velocity −1, "
        "velocities in units of |vₑ|: the rocket's V(b) after blast b (harmonic partial sums) "
        "and each pellet's final velocity V(b−1) − 1; pellets 7, 8 and 9 end up moving forward."
    ),
    ("ch08.rocket.velocity-9", "ch08.rocket.first-forward-pellet", "ch08.rocket.first-fast-blast"),
)
def _pellet_rocket(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    rocket = pellet_rocket(
        round(value_of(claims, "ch08.rocket.n-balls")),
        value_of(claims, "ch08.rocket.pellet-mass"),
        value_of(claims, "ch08.rocket.exhaust"),
    )
    blasts = list(range(rocket.blasts))
    fig.set_size_inches(7.6, 4.4)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    ax.step(blasts, as_floats(rocket.velocities), where="post", label="rocket $V(b)$")
    ax.plot(blasts, as_floats(rocket.pellet_velocities), "o", label="pellet $b$, final")
    ax.axhline(0, color="k", linewidth=0.8)
    ax.axhline(
        -value_of(claims, "ch08.rocket.exhaust"), color="0.6", linestyle=":", label="$|v_e|$"
    )
    ax.set_xlabel("blast $b$")
    ax.set_ylabel("velocity (units of $|v_e|$)")
    ax.legend(fontsize="small")
