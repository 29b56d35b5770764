"""Figures of chapter 12, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from mechmodel.ellipse import ellipse_outline, velocity_radius
from mechmodel.lagrange import (
    contact_point,
    energy_ellipse_radii,
    envelope_height,
    ke_ellipse_slopes,
    legendre_transform,
    momenta,
    oscillator_paths,
    polar_jacobian,
    polar_kajobian,
    projectile_family,
    quasi_velocities,
    trajectory_height,
)
from reports.figures import as_float, figure, value_of

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.colors import Colormap
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim


@figure(
    "lagrange-estrangian-hamiltonian",
    "Figs. 12.1-12.2",
    (
        "The kinetic energy KE = 1 as an ellipse L(v) in velocities, a circle E(V) in "
        "quasi-velocities Vₖ = √mₖ vₖ and an ellipse H(p) in momenta (scaled units), for the "
        "figure's mass ratio m₁/m₂ = 16 (read from its collision slope −16): the collision line"
        " through the COM point (red) and the COM bisector (dashed), perpendicular only in V. "
        "Each H radius is mₖ times its L radius."
    ),
    (
        "ch12.fig12-1.collision-slope",
        "ch12.fig12-1.velocity-bisector",
        "ch12.fig12-1.quasi-collision",
        "ch12.fig12-1.quasi-bisector",
        "ch12.fig12-1.momentum-collision",
        "ch12.fig12-1.momentum-bisector",
    ),
)
def _ellipses(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    slope = value_of(claims, "ch12.fig12-1.collision-slope")
    s = ke_ellipse_slopes(int(slope))
    m1, m2 = float(s.mass_ratio), 1.0
    energy = 1.0
    radii = energy_ellipse_radii([m1, m2], energy)
    # the COM point: both bodies at the velocity u with KE = 1, (m1 + m2) u^2 / 2 = 1
    u = velocity_radius(m1 + m2, energy)
    planes = [
        (
            "$L(v)$: velocities",
            ("$v_1$ (scaled)", "$v_2$ (scaled)"),
            radii.velocity,
            (u, u),
            s.velocity_collision,
            s.velocity_bisector,
        ),
        (
            "$E(V)$: quasi-velocities",
            (r"$V_1 = √m_1\,v_1$ (scaled)", r"$V_2 = √m_2\,v_2$ (scaled)"),
            [velocity_radius(1, energy)] * 2,  # E(V) = V.V/2: the unit-mass circle (12.5)
            quasi_velocities([m1, m2], [u, u]),
            s.quasi_collision,
            s.quasi_bisector,
        ),
        (
            "$H(p)$: momenta",
            ("$p_1 = m_1 v_1$ (scaled)", "$p_2 = m_2 v_2$ (scaled)"),
            radii.momentum,
            momenta([m1, m2], [u, u]),
            s.momentum_collision,
            s.momentum_bisector,
        ),
    ]
    fig.set_size_inches(11.0, 4.8)
    fig.set_layout_engine("constrained", w_pad=0.1)
    for k, (title, (xlabel, ylabel), (a, b), (cx, cy), collision, bisector) in enumerate(planes):
        ax = fig.add_subplot(1, 3, k + 1)
        x, y = ellipse_outline(a, b)
        ax.plot(x, y, color="C0")
        span = 1.3 * max(a, b)
        t = np.linspace(-span, span, 3)
        ax.plot(
            t,
            float(bisector) * t,
            "--",
            color="0.4",
            lw=1,
            label=f"COM bisector, slope ${bisector}$",
        )
        dx = span / math.hypot(1, float(collision))
        ax.plot(
            [cx - dx, cx + dx],
            [cy - float(collision) * dx, cy + float(collision) * dx],
            "C3",
            label=f"collision line, slope ${collision}$",
        )
        ax.plot([as_float(cx)], [as_float(cy)], "ko", ms=4)
        ax.set_aspect("equal")
        ax.set_xlim(-span, span)
        ax.set_ylim(-span, span)
        ax.set_title(title, fontsize="medium")
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.17), fontsize="small", frameon=False)


@figure(
    "legendre-tangent",
    "Figs. 12.3-12.4",
    (
        "Legendre contact geometry with the figure's numbers (scaled units): (a) the convex "
        "L(v) = v^1.6 has value 1 and slope p = 1.6 at v = 1, and its tangent there meets the L"
        " axis at −H = −0.6 (grey: lines of that slope with lower intercepts, Fig. 12.4a); (b) "
        "H(p) = max over v of (pv − L), found numerically, has slope v = 1 at p = 1.6 and a "
        "tangent meeting the H axis at −L = −1."
    ),
    (
        "ch12.fig12-3.h",
        "ch12.fig12-3.l-intercept",
        "ch12.fig12-3.h-intercept",
    ),
)
def _legendre(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    v0 = value_of(claims, "ch12.fig12-3.v")
    p0 = value_of(claims, "ch12.fig12-3.p")
    l0 = value_of(claims, "ch12.fig12-3.l")
    power = p0 * v0 / l0  # L = l0 (v/v0)^power has value l0 and slope p0 at v0
    lag = lambda v: l0 * abs(v / v0) ** power  # noqa: E731
    ham = lambda p: legendre_transform(lag, p, -6.0, 6.0).value  # noqa: E731
    h0 = value_of(claims, "ch12.fig12-3.h")
    vs = np.linspace(-0.2, 2.0, 121)
    ps = np.linspace(-0.2, 3.0, 81)
    fig.set_size_inches(9.6, 4.2)
    fig.set_layout_engine("constrained", w_pad=0.1)
    ax1, ax2 = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    ax1.plot(vs, [lag(v) for v in vs], color="C0", label=f"$L(v) = v^{{{power:g}}}$")
    ax1.plot(vs, p0 * vs - h0, color="C3", label=f"tangent, slope $p = {p0:g}$")
    for shift in (0.3, 0.6):
        ax1.plot(vs, p0 * vs - h0 - shift, color="0.7", lw=0.8)
    ax1.plot([0, v0], [-h0, l0], "ko", ms=4)
    ax1.set_title(
        f"(a) intercept $-H = {value_of(claims, 'ch12.fig12-3.l-intercept'):g}$", fontsize="medium"
    )
    ax1.set_xlabel("velocity $v$ (scaled)")
    ax1.set_ylabel("Lagrangian $L$ (scaled)")
    ax2.plot(ps, [ham(p) for p in ps], color="C2", label=r"$H(p) = \max_v\,(pv - L)$")
    ax2.plot(ps, v0 * ps - l0, color="C3", label=f"tangent, slope $v = {v0:g}$")
    ax2.plot([0, p0], [-l0, h0], "ko", ms=4)
    ax2.set_title(
        f"(b) intercept $-L = {value_of(claims, 'ch12.fig12-3.h-intercept'):g}$", fontsize="medium"
    )
    ax2.set_xlabel("momentum $p$ (scaled)")
    ax2.set_ylabel("Hamiltonian $H$ (scaled)")
    for ax in (ax1, ax2):
        ax.axhline(0, color="0.5", lw=0.5)
        ax.axvline(0, color="0.5", lw=0.5)
        ax.legend(fontsize="small", loc="upper left")


@figure(
    "fountain-envelope",
    "Figs. 12.5-12.6",
    (
        "The volcanoes of Io and the atomic fountain: trajectories of one speed v₀ = 1 (g = 1; "
        "lengths in units of v₀²/g) at elevations every 7.5°, each touching the envelope y = "
        "v₀²/(2g) − gx²/(2v₀²) once, at x = v₀²/(g tan a) (dots). The 45° paths (red) touch it "
        "at the ground; the horizontal launch (green) has the envelope's shape and never "
        "touches it."
    ),
    (
        "ch12.fountain.envelope-constant-denominator",
        "ch12.fountain.envelope-denominator",
        "ch12.fountain.contact-tan-v0-power",
        "ch12.fountain.envelope-shape-angle",
    ),
)
def _fountain(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    fam = projectile_family()
    v0, g = 1.0, 1.0
    reach = v0**2 / g
    xs = np.linspace(-1.2 * reach, 1.2 * reach, 241)
    fig.set_size_inches(8.0, 4.6)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    for k in range(1, 24):
        a = k * math.pi / 24
        if abs(a - math.pi / 2) < 1e-9:
            continue
        ahead = xs[xs >= 0] if a < math.pi / 2 else xs[xs <= 0]  # from the launch point on
        ys = [trajectory_height(x, v0, a, g) for x in ahead]
        steep = k in (6, 18)
        ax.plot(
            ahead,
            ys,
            color="C3" if steep else "C0",
            lw=1.4 if steep else 0.6,
            label="45° paths" if k == 6 else ("other elevations" if k == 1 else None),
        )
        xc, yc = contact_point(v0, a, g)
        ax.plot(
            [float(xc)],
            [float(yc)],
            "o",
            color="k",
            ms=3,
            label="contact points" if k == 1 else None,
        )
    shape = float(value_of(claims, "ch12.fountain.envelope-shape-angle"))
    ax.plot(
        xs,
        [trajectory_height(x, v0, shape, g) for x in xs],
        color="C2",
        lw=1.4,
        label="horizontal launch",
    )
    ax.plot(
        xs, [float(envelope_height(x, v0, g)) for x in xs], "k--", lw=1.4, label="envelope (12.17)"
    )
    ax.set_ylim(-0.6 * reach, 0.62 * reach)
    ax.set_xlim(-1.2 * reach, 1.2 * reach)
    ax.set_aspect("equal")
    ax.set_xlabel("$x$ (units of $v_0^2/g$)")
    ax.set_ylabel("$y$ (units of $v_0^2/g$)")
    ax.set_title(
        f"$y_{{\\rm env}} = v_0^{{{fam.envelope_constant_v0_power}}}"
        f"/({fam.envelope_constant_denominator}g)"
        f" - g\\,x^{{{fam.envelope_x_power}}}/({fam.envelope_quadratic_denominator}"
        f"\\,v_0^{{{fam.envelope_v0_power}}})$",
        fontsize="medium",
    )
    fig.legend(loc="outside right center", fontsize="small")


@figure(
    "polar-bases",
    "Fig. 12.10",
    (
        "The polar coordinate grid (scaled units) with the covariant bases Eᵣ, Eᵩ (columns of "
        "the Jacobian J, tangent to the coordinate lines; Eᵩ grows with r) and the "
        "contravariant bases Eʳ, Eᵠ (rows of K = J⁻¹, normal to the lines; Eᵠ shrinks as 1/r) "
        "at three points; Eᵣ and Eʳ coincide. Their dot products give the metric diag(1, r²) "
        "and its inverse diag(1, 1/r²) (12.30)."
    ),
    (
        "ch12.polar.metric-rr",
        "ch12.polar.metric-rphi",
        "ch12.polar.inverse-metric-phiphi",
        "ch12.fig12-10.dq1",
        "ch12.fig12-10.dq2",
    ),
)
def _polar(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    fig.set_size_inches(6.4, 5.4)
    ax = fig.add_subplot()
    theta = np.linspace(0, math.pi / 2, 91)
    for r in np.arange(0.5, 3.01, 0.5):
        ax.plot(r * np.cos(theta), r * np.sin(theta), color="0.8", lw=0.6)
    for phi in np.linspace(0, math.pi / 2, 7):
        ax.plot([0, 3 * math.cos(phi)], [0, 3 * math.sin(phi)], color="0.8", lw=0.6)
    for r, phi in ((1.0, math.pi / 6), (2.0, math.pi / 4), (2.5, math.pi / 3)):
        j = polar_jacobian(r, phi)
        k = polar_kajobian(r, phi)
        x, y = r * math.cos(phi), r * math.sin(phi)
        scale = 0.35
        # covariant wide and underneath, contravariant thin and dashed on top: E_r and E^r
        # are the same vector, E_phi and E^phi point the same way
        for (dx, dy), color in (
            ((j[0][0], j[1][0]), "C0"),
            ((j[0][1], j[1][1]), "C1"),
        ):
            ax.annotate(
                "",
                (x + scale * dx, y + scale * dy),
                (x, y),
                arrowprops={"arrowstyle": "->", "color": color, "lw": 3, "alpha": 0.7},
            )
        for (dx, dy), color in (((k[0][0], k[0][1]), "C2"), ((k[1][0], k[1][1]), "C3")):
            ax.annotate(
                "",
                (x + scale * dx, y + scale * dy),
                (x, y),
                arrowprops={"arrowstyle": "-|>", "color": color, "ls": "--", "lw": 1.2},
            )
        ax.plot([x], [y], "ko", ms=3)
    ax.plot([], [], "C0", lw=3, alpha=0.7, label=r"$\mathbf{E}_r$ (covariant)")
    ax.plot([], [], "C1", lw=3, alpha=0.7, label=r"$\mathbf{E}_\phi$ (covariant, length $r$)")
    ax.plot([], [], "C2--", label=r"$\mathbf{E}^r$ (contravariant)")
    ax.plot([], [], "C3--", label=r"$\mathbf{E}^\phi$ (contravariant, length $1/r$)")
    ax.set_aspect("equal")
    ax.set_xlim(-0.1, 3.3)
    ax.set_ylim(-0.1, 3.3)
    ax.set_xlabel("$x$ (scaled)")
    ax.set_ylabel("$y$ (scaled)")
    ax.legend(fontsize="small", loc="upper right")


@figure(
    "oscillator-phase-colour",
    "Figs. 12.13-12.14",
    (
        "Paths (scaled units) of the 2-D oscillator (ω = M = 1) blasted from r(0) = (1, 0) with"
        " the starlet's speed |v(0)| = 1 in 72 directions (exercise 1.12.3), coloured by the "
        "phase of their reduced action S_H = ∫p·dr in units of ħ = 1/8, modulo 2π (the hue "
        "circle: red 0, cyan π). Over one period every path gathers S_H = 2πE = 2π."
    ),
    ("ch12.starlet.speed", "ch12.bohr.phase-turn", "ch12.palette.orange", "ch12.palette.blue"),
)
def _phase(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    from matplotlib.collections import LineCollection

    speed = value_of(claims, "ch12.starlet.speed")
    turn = value_of(claims, "ch12.bohr.phase-turn")
    hbar = 1 / 8
    angles = [2 * math.pi * k / 72 for k in range(72)]
    paths = oscillator_paths((1.0, 0.0), speed, angles, duration=math.pi, samples=240)
    fig.set_size_inches(6.4, 5.0)
    ax = fig.add_subplot()
    import matplotlib as mpl

    cmap = mpl.colormaps["hsv"]
    for x, y, s in zip(paths.x, paths.y, paths.action, strict=True):
        pts = np.column_stack([x, y])
        segs = np.stack([pts[:-1], pts[1:]], axis=1)
        phase = ((s[:-1] + s[1:]) / 2 / hbar) % turn / turn
        # 17,000 coloured segments: drawn as one embedded image, not 17,000 SVG paths
        ax.add_collection(
            LineCollection(list(segs), colors=cmap(phase), linewidths=0.7, rasterized=True)
        )
    ax.set_xlim(-1.6, 1.6)
    ax.set_ylim(-1.6, 1.6)
    ax.set_aspect("equal")
    ax.set_xlabel("$x$ (scaled)")
    ax.set_ylabel("$y$ (scaled)")
    _hue_key(ax.inset_axes((0.75, 0.7, 0.24, 0.24)), cmap)


def _hue_key(ax: Axes, cmap: Colormap) -> None:
    """The hue circle of the phase, a picture: red at 0, cyan at pi."""
    from matplotlib.patches import Wedge

    steps = 72
    for k in range(steps):
        ax.add_patch(
            Wedge(
                (0, 0), 1, 360 * k / steps, 360 * (k + 1) / steps, width=0.35, color=cmap(k / steps)
            )
        )
    for angle, name in ((0, "0"), (90, r"$\pi/2$"), (180, r"$\pi$"), (270, r"$3\pi/2$")):
        c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
        ax.text(0.4 * c, 0.4 * s, name, ha="center", va="center", fontsize="small")
    ax.set_xlim(-1.05, 1.05)
    ax.set_ylim(-1.05, 1.05)
    ax.set_aspect("equal")
    ax.set_title("phase", fontsize="small", pad=2)
    ax.set_axis_off()
