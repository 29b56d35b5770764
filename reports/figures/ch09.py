"""Figures of chapter 9, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from mechmodel.ellipse import ellipse_outline
from mechmodel.fields import (
    chord_tunnel_position,
    clock_angle,
    clock_hour,
    gravity_field,
    gravity_potential,
    interior_potential,
    oscillator_orbit,
    parabola_geometry,
    tunnel_period,
)
from reports.figures import figure, value_of

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim


@figure(
    "tunnel-and-orbit",
    "Fig. 9.8",
    (
        "A body dropped through a tunnel across a uniform Earth and a satellite in the grazing "
        "circular orbit keep the same x coordinate and meet on the far side after half a "
        "period; a body in a tunnel off the centre (dashed chord) keeps the same time. "
        "Positions in units of the Earth's radius R, times in minutes."
    ),
    ("ch09.tunnel-time", "ch09.orbit-speed", "ch09.tunnel.period"),
)
def _tunnel(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    g = value_of(claims, "ch09.surface-gravity")
    radius = value_of(claims, "ch09.earth-radius")
    period = tunnel_period(g, radius)
    fig.set_size_inches(7.0, 6.4)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    xs, ys = ellipse_outline(1.0, 1.0)
    ax.plot(xs, ys, color="0.6", label="Earth's surface (= the orbit)")
    ax.plot([-1, 1], [0, 0], color="0.3", label="tunnel through the centre")
    offset = radius / 2  # a chord half a radius off the centre, tilted to run below the diameter
    half = math.sqrt(radius * radius - offset * offset) / radius
    ax.plot([-half, half], [-offset / radius] * 2, "--", color="0.5", label="a chord off centre")
    for k in range(9):
        time = period * k / 16
        angle = math.pi * k / 8
        s, _ = chord_tunnel_position(g, radius, 0.0, time)
        s_chord, _ = chord_tunnel_position(g, radius, offset, time)
        first = k == 0
        ax.plot(
            [math.cos(angle)],
            [math.sin(angle)],
            "o",
            color="C0",
            label="satellite" if first else None,
        )
        ax.plot([s / radius], [0], "s", color="C1", label="body in the tunnel" if first else None)
        ax.plot(
            [s_chord / radius],
            [-offset / radius],
            "d",
            color="C2",
            label="body in the chord" if first else None,
        )
        ax.plot([math.cos(angle)] * 2, [0, math.sin(angle)], ":", color="0.7")
        if k in (0, 4, 8):
            ax.annotate(
                f"{time / 60:.1f} min",
                (math.cos(angle), math.sin(angle)),
                textcoords="offset points",
                xytext=(4, 6),
                fontsize="small",
            )
    ax.set_aspect("equal")
    ax.set_xlabel("$x/R$")
    ax.set_ylabel("$y/R$")
    ax.set_title(f"period $2\\pi√(R/g)$ = {period / 60:.1f} min on every chord", fontsize="medium")
    fig.legend(loc="outside lower center", fontsize="small", ncols=3)


@figure(
    "earth-potential",
    "Fig. 9.7",
    (
        "Potential and field of a uniform Earth in units of mgR and mg, against x = r/R: the "
        "parabola (x² − 3)/2 inside meets −1/x outside at the surface with the same slope; the "
        "focus of the parabola is λ = 1 straight across from the surface point and its "
        "directrix λ below."
    ),
    (
        "ch09.earth.interior-offset",
        "ch09.earth.surface-potential",
        "ch09.earth.surface-force",
        "ch09.earth.parabola-lambda",
        "ch09.earth.parabola-directrix",
    ),
)
def _earth_potential(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    surface = value_of(claims, "ch09.surface-x")
    pot = interior_potential(surface)
    geo = parabola_geometry(pot.quadratic)
    fig.set_size_inches(7.6, 4.6)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    xs = [-3 + 6 * k / 600 for k in range(601)]
    # in units of the surface: g = 1 and R = surface give U in mgR and F in mg
    us = [float(gravity_potential(1, surface, abs(x))) for x in xs]
    fs = [math.copysign(1, x) * gravity_field(1, surface, abs(x)) for x in xs]
    ax.plot(xs, us, color="C0", label="potential $U(x)$")
    ax.plot(xs, fs, color="C3", label="force $F(x)$")
    focus = float(pot.offset + geo.focal_height)
    directrix = float(pot.offset + geo.directrix_height)
    at_surface = float(pot.surface_potential)
    ax.plot([0], [focus], "o", color="C2", label="focus of the inside parabola")
    ax.axhline(directrix, color="C2", linestyle="--", linewidth=1, label="directrix")
    ax.plot([0, surface], [focus, at_surface], color="C2", linewidth=1)
    ax.plot([surface] * 2, [at_surface, directrix], color="C2", linewidth=1, zorder=3)
    ax.plot([surface], [at_surface], "ko")
    ax.axvline(-surface, color="0.85")
    ax.axvline(surface, color="0.85")
    ax.axhline(0, color="0.85")
    ax.set_ylim(-2.5, 1.5)
    ax.set_xlabel("distance $x = r/R$")
    ax.set_ylabel("$U$ (units of $mgR$), $F$ (units of $mg$)")
    ax.legend(loc="upper right", fontsize="small")


@figure(
    "parabola-focus-directrix",
    "Figs. 9.3-9.4",
    (
        "The parabola y = x² (scaled units): every point is as far from the focus (0, 1/4) as "
        "from the directrix y = −1/4 (the numbers give that distance); the half-width at the "
        "focus is λ = 1/2, where the slope is 1 and the kite of focal radius and drop line is a"
        " square."
    ),
    ("ch09.parabola.lambda", "ch09.parabola.focal-points", "ch09.parabola.square-kite-slope"),
)
def _parabola(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    geo = parabola_geometry(1)
    focus, directrix = float(geo.focal_height), float(geo.directrix_height)
    lam = value_of(claims, "ch09.parabola.lambda")
    fig.set_size_inches(6.4, 5.2)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    xs = [-1.6 + 3.2 * k / 320 for k in range(321)]
    ax.plot(xs, [float(geo.height(x)) for x in xs], color="C0", label="$y = x^2$")
    ax.axhline(directrix, color="C2", linestyle="--", label="directrix")
    ax.plot([0], [focus], "o", color="C2", label="focus")
    ax.plot(
        [-lam, lam],
        [focus] * 2,
        color="C1",
        linewidth=2,
        label=r"latus rectum $2\lambda$",
    )
    for x in (-1.4, -0.9, 0.5, 1.1):
        y = float(geo.height(x))
        ax.plot([x, 0], [y, focus], color="0.4", linewidth=1)
        ax.plot([x, x], [y, directrix], ":", color="0.4", linewidth=1)
        ax.plot([x, x], [y, 2.6], color="C3", linewidth=0.8, alpha=0.6)
        ax.annotate(
            f"{geo.focal_radius(x):.3g}",
            (x, y),
            textcoords="offset points",
            xytext=(5, -12),
            fontsize="small",
        )
    ax.set_aspect("equal")
    ax.set_ylim(directrix - 0.3, 2.6)
    ax.set_xlabel("$x$ (scaled)")
    ax.set_ylabel("$y$ (scaled)")
    ax.set_title("focal radius = distance to the directrix", fontsize="medium")
    ax.legend(loc="upper center", fontsize="small", ncols=2)


@figure(
    "starlet-orbits",
    "Figs. 9.10-9.11",
    (
        "Orbits of a starlet inside the Earth, in units of their amplitude: x and y oscillate "
        "with the same amplitude and period, x behind y by 0 to 8 hours of the 16-hour phasor "
        "clock, and every orbit is an ellipse inside the square |x|, |y| ≤ 1. The 2-hour (45°) "
        "orbit of Fig. 9.10b (bold) is marked with its (x, y) clock hours."
    ),
    ("ch09.phasor.lag-angle", "ch09.phasor.y-hour", "ch09.phasor.quadrature-rad"),
)
def _starlet_orbits(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    clock = int(value_of(claims, "ch09.phasor.clock"))
    lead = int(value_of(claims, "ch09.phasor.lead"))
    omega = 2 * math.pi / clock  # one turn per clock period, time in hours
    fig.set_size_inches(6.4, 6.0)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    ax.plot([-1, 1, 1, -1, -1], [-1, -1, 1, 1, -1], color="0.6", label="envelope")
    steps = [clock * k / 240 for k in range(241)]
    for lag in range(clock // 2 + 1):
        phase_y = clock_angle(lag, clock)  # y ahead of x by lag hours
        path = [oscillator_orbit(omega, 1, 1, 0, phase_y, t) for t in steps]
        style = {"color": "C0", "linewidth": 2} if lag == lead else {"color": "0.75"}
        ax.plot([p.x for p in path], [p.y for p in path], **style)
    for hour in range(clock):
        # x at the hour-th mark of its clock, y lead hours ahead: (cos wh, cos w(h + lead))
        state = oscillator_orbit(omega, 1, 1, 0, clock_angle(lead, clock), hour)
        ax.plot([state.x], [state.y], "o", color="C1", markersize=3)
        ax.annotate(
            f"({clock_hour(hour, 0, clock)},{clock_hour(hour, lead, clock)})",
            (state.x, state.y),
            textcoords="offset points",
            xytext=(4 if state.x >= 0 else -4, 3 if state.y >= 0 else -3),
            ha="left" if state.x >= 0 else "right",
            va="bottom" if state.y >= 0 else "top",
            fontsize="small",
        )
    ax.set_aspect("equal")
    ax.set_xlim(-1.3, 1.3)
    ax.set_ylim(-1.2, 1.2)
    ax.set_xlabel("$x$ / amplitude")
    ax.set_ylabel("$y$ / amplitude")
    ax.set_title(f"$x$ behind $y$ by 0 to {clock // 2} hours", fontsize="medium")
