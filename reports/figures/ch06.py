"""Figures of chapter 6, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from mechmodel.forces import (
    adiabatic_force,
    adiabatic_potential,
    isothermal_force,
    isothermal_potential,
    trapped_ball,
)
from mechmodel.oscillators import orbit_period, oscillator_frequency
from reports.figures import figure, value_of

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from mechmodel.typing import Real
    from reference.evaluation import EvaluatedClaim

# Fig. 6.4(a) starts the trapped ball 3 units from the wall (the figure, not the text); the
# catalog's action claims carry the same number as an assumption.
TRAPPED_GAP = 3
# Fig. 6.3(c) gives no starting point: we release the big ball at rest a third of the way to
# one wall, far enough out for the anharmonic stiffening to show.
RELEASE_FRACTION = 1 / 3


@figure(
    "force-laws",
    "Fig. 6.1, (6.4)-(6.11)",
    (
        "Bang-force laws on the big ball at gap Y, for a tiny ball of unit mass at unit speed "
        "at Y = 1 (scaled units): (a) the isothermal force F = m₂v₂²/Y and the adiabatic F = "
        "m₂(v₀Y₀)²/Y³; (b) their potentials −m₂v₂² ln Y and ½m₂(v₀Y₀/Y)²."
    ),
    ("ch06.isothermal.inverse-power", "ch06.adiabatic.inverse-power"),
)
def _force_laws(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    gaps = [0.3 + 0.02 * k for k in range(136)]
    iso = [float(isothermal_force(1, 1, y).force) for y in gaps]
    adi = [float(adiabatic_force(1, 1, 1, y).force) for y in gaps]
    fig.set_size_inches(9.0, 4.0)
    fig.set_layout_engine("constrained", w_pad=0.1)
    left, right = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    n_iso = value_of(claims, "ch06.isothermal.inverse-power")
    n_adi = value_of(claims, "ch06.adiabatic.inverse-power")
    left.plot(gaps, iso, label=f"isothermal $\\propto 1/Y^{{{n_iso:g}}}$")
    left.plot(gaps, adi, label=f"adiabatic $\\propto 1/Y^{{{n_adi:g}}}$")
    left.set_ylim(0, 8)
    left.set_xlabel("gap $Y$ (scaled)")
    left.set_ylabel("force $F$ on $m_1$ (scaled)")
    left.set_title("(a) force", fontsize="medium")
    left.legend(fontsize="small")
    iso_u = [float(isothermal_potential(1, 1, y)) for y in gaps]
    adi_u = [float(adiabatic_potential(1, 1, 1, y)) for y in gaps]
    right.plot(gaps, iso_u, label=r"isothermal $-\ln Y$")
    right.plot(gaps, adi_u, label=r"adiabatic $1/(2Y^2)$")
    right.set_ylim(-1.5, 4)
    right.set_xlabel("gap $Y$ (scaled)")
    right.set_ylabel("potential $U(Y)$ (scaled)")
    right.set_title("(b) potential", fontsize="medium")
    right.legend(fontsize="small")


def _two_gas_force(big_m: float, m: float, v0: float, y0: float, x: float) -> Real:
    """Force on the big ball displaced x from the middle of two adiabatic gases (Fig. 6.3)."""
    return adiabatic_force(m, v0, y0, y0 + x).force - adiabatic_force(m, v0, y0, y0 - x).force


@figure(
    "two-gas-oscillator",
    "Fig. 6.3(c)",
    (
        "Displacement against time of M = 50 kg oscillating between two adiabatic gases of m = "
        "0.1 kg at v₀ = 20 m/s in ranges Y₀ = 3 m, released at rest a third of the way to one "
        "wall (our choice: the book gives no start). Dashed: the harmonic motion with the "
        "spring constant at x = 0."
    ),
    (
        "ch06.fig6-3c.big-mass",
        "ch06.fig6-3c.small-mass",
        "ch06.fig6-3c.speed",
        "ch06.fig6-3c.range",
    ),
)
def _two_gas_oscillator(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    from scipy.integrate import solve_ivp

    big_m = value_of(claims, "ch06.fig6-3c.big-mass")
    m = value_of(claims, "ch06.fig6-3c.small-mass")
    v0 = value_of(claims, "ch06.fig6-3c.speed")
    y0 = value_of(claims, "ch06.fig6-3c.range")
    x0 = RELEASE_FRACTION * y0
    # the spring constant at the middle, -dF/dx at x = 0, by a central difference
    step = 1e-4 * y0
    k = -(_two_gas_force(big_m, m, v0, y0, step) - _two_gas_force(big_m, m, v0, y0, -step)) / (
        2 * step
    )
    omega = oscillator_frequency(k, big_m)
    period = orbit_period(omega)
    times = [3 * period * j / 400 for j in range(401)]
    run = solve_ivp(
        lambda _t, s: [s[1], _two_gas_force(big_m, m, v0, y0, s[0]) / big_m],
        (0, times[-1]),
        [x0, 0.0],
        t_eval=times,
        rtol=1e-10,
        atol=1e-12,
    )
    fig.set_size_inches(8.0, 4.2)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    ax.plot(run.t, run.y[0], label="between the adiabatic gases")
    ax.plot(times, [x0 * math.cos(omega * t) for t in times], "--", label="harmonic")
    ax.set_xlabel("time $t$ (s)")
    ax.set_ylabel("displacement $x$ (m)")
    ax.set_title(f"harmonic period $2\\pi√(M/k)$ = {period:.3g} s", fontsize="medium")
    fig.legend(fontsize="small", loc="outside lower center", ncols=2)


@figure(
    "trapped-ball",
    "Fig. 6.4(a)",
    (
        "Space-time paths (scaled units) of the little ball trapped between the big ball "
        "closing at v₁ = 1 and the wall at x = 0, starting at rest 3 units out: the range times"
        " the speed at each wall bang stays 3."
    ),
    ("ch06.trapped.after-bang-1", "ch06.trapped.action"),
)
def _trapped_ball(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    v_wall = value_of(claims, "ch06.trapped.v-wall")
    v_ball = value_of(claims, "ch06.trapped.v-ball")
    run = trapped_ball(v_wall, v_ball, TRAPPED_GAP, 6)
    fig.set_size_inches(7.6, 4.8)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    # the little ball: from the big ball to the wall and back, bang after bang
    xs: list[Real] = [-TRAPPED_GAP]
    ts: list[Real] = [0.0]
    for speed, wall_time in zip(run.speeds, run.times, strict=True):
        xs.append(0.0)
        ts.append(wall_time)
        # back to meet the big ball, which is then at -gap + v1 t
        meet = wall_time + (TRAPPED_GAP - v_wall * wall_time) / (speed + v_wall)
        xs.append(-speed * (meet - wall_time))
        ts.append(meet)
    ax.plot(
        [float(x) for x in xs],
        [float(t) for t in ts],
        "-o",
        markersize=3,
        label="little ball $m_2$",
    )
    t_end = ts[-1]
    ax.plot(
        [-TRAPPED_GAP, float(-TRAPPED_GAP + v_wall * t_end)],
        [0, float(t_end)],
        label=f"big ball, $v_1 = {v_wall:g}$",
    )
    ax.axvline(0, color="k", label="wall")
    for k, (rng, wall_time, prod) in enumerate(
        zip(run.ranges, run.times, run.products, strict=True)
    ):
        ax.plot(
            [-float(rng), 0],
            [float(wall_time)] * 2,
            ":",
            color="0.5",
            label="range" if k == 0 else None,
        )
        if k < 3:  # the later ones crowd together near the wall
            ax.annotate(
                f"range × speed = {prod:.2g}",
                (-rng, wall_time),
                fontsize="small",
                xytext=(-6, 0),
                textcoords="offset points",
                ha="right",
                va="center",
            )
    ax.set_xlabel("position $x$ (scaled)")
    ax.set_ylabel("time $t$ (scaled)")
    ax.legend(fontsize="small", loc="upper left")
