"""Figures of chapter 3, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from mechmodel.collisions import collide
from mechmodel.ellipse import ellipse_outline, ellipse_radii, kinetic_energy
from reports.figures import as_float, figure, value_of

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim


@figure(
    "energy-ellipses",
    "Fig. 3.1",
    (
        "The crash of the 4-ton SUV at 60 mph into the 1-ton VW at 10 mph in the plane of their"
        " velocities (mph): the elastic KE ellipse through the initial point IN, the inelastic "
        "IE ellipse through the COM point, and the momentum line both collisions stay on; "
        "energies in ton·mph²."
    ),
    ("ch03.suv-vw.ke", "ch03.suv-vw.ie"),
)
def _energy_ellipses(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    m_suv, m_vw = value_of(claims, "ch03.suv-vw.m-suv"), value_of(claims, "ch03.suv-vw.m-vw")
    v_suv, v_vw = value_of(claims, "ch03.suv-vw.v-suv"), value_of(claims, "ch03.suv-vw.v-vw")
    elastic = collide(m_suv, m_vw, v_suv, v_vw, 1)
    sticking = collide(m_suv, m_vw, v_suv, v_vw, 0)
    fig.set_size_inches(5.8, 6.2)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    for energy, style, label in (
        (kinetic_energy((m_suv, m_vw), (v_suv, v_vw)), "-", "KE ellipse"),
        (sticking.ke_after, "--", "IE ellipse"),
    ):
        xs, ys = ellipse_outline(*ellipse_radii(m_suv, m_vw, energy))
        ax.plot(xs, ys, style, label=f"{label}, $E$ = {energy:g}")
    p = elastic.momentum
    line_x = [-20.0, 100.0]
    ax.plot(line_x, [(p - m_suv * x) / m_vw for x in line_x], ":", label="momentum line")
    for (x, y), name in (
        ((v_suv, v_vw), "IN"),
        (elastic.after, "FIN (elastic)"),
        (sticking.after, "COM (inelastic)"),
    ):
        ax.plot([as_float(x)], [as_float(y)], "o")
        ax.annotate(f"{name} ({x:g}, {y:g})", (x, y), textcoords="offset points", xytext=(5, 5))
    ax.set_xlabel(r"velocity $V_{\rm SUV}$ (mph)")
    ax.set_ylabel(r"velocity $V_{\rm VW}$ (mph)")
    ax.set_aspect("equal")
    ax.set_xlim(-70, 110)
    ax.set_ylim(-130, 130)
    fig.legend(loc="outside lower center", fontsize="small", ncols=3)
