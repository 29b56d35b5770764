"""The report's figures, drawn by calling mechmodel with the catalog's own inputs.

Each figure is one small function registered with ``@figure``: it gets the evaluated claims (to
read the book's givens and to name the claims it illustrates) and a matplotlib ``Figure`` to draw
on. ``render_all`` returns each as inline SVG, deterministic (no date, one ``svg.hashsalt`` per
figure so ids never clash within one page).
"""

from __future__ import annotations

import io
import math
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from mechmodel.bangs import ceiling_sequence
from mechmodel.collisions import collide, kinetic_energy
from mechmodel.fields import tunnel_period
from mechmodel.series import exp_partial_sum
from mechmodel.towers import independent_tower

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim, Evaluation


@dataclass(frozen=True)
class FigureSpec:
    """A registered figure: the book's figure it redraws, a caption and the claims it shows."""

    key: str
    book_figure: str
    caption: str
    claims: tuple[str, ...]
    draw: Callable[[Figure, dict[str, EvaluatedClaim]], None]


@dataclass(frozen=True)
class RenderedFigure:
    """A figure ready for the page."""

    key: str
    book_figure: str
    caption: str
    claims: tuple[str, ...]
    svg: str


FIGURES: list[FigureSpec] = []


def figure(key: str, book_figure: str, caption: str, claims: tuple[str, ...]) -> Callable:
    """Register a drawing function as a report figure."""

    def register(draw: Callable[[Figure, dict[str, EvaluatedClaim]], None]) -> Callable:
        FIGURES.append(FigureSpec(key, book_figure, caption, claims, draw))
        return draw

    return register


def _value(claims: dict[str, EvaluatedClaim], ident: str) -> float:
    value = claims[ident].value
    assert value is not None, ident
    return value


def _ellipse(semi_x: float, semi_y: float, n: int = 361) -> tuple[list[float], list[float]]:
    angles = [2 * math.pi * k / (n - 1) for k in range(n)]
    return [semi_x * math.cos(a) for a in angles], [semi_y * math.sin(a) for a in angles]


@figure(
    "energy-ellipses",
    "Fig. 3.1",
    "The SUV/VW crash in the (V_SUV, V_VW) plane: the elastic KE ellipse through the initial "
    "point, the inelastic IE ellipse through the COM point, and the momentum line that both "
    "collisions stay on.",
    ("ch03.suv-vw.ke", "ch03.suv-vw.ie"),
)
def _energy_ellipses(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    m_suv, m_vw = _value(claims, "ch03.suv-vw.m-suv"), _value(claims, "ch03.suv-vw.m-vw")
    v_suv, v_vw = _value(claims, "ch03.suv-vw.v-suv"), _value(claims, "ch03.suv-vw.v-vw")
    elastic = collide(m_suv, m_vw, v_suv, v_vw, 1)
    sticking = collide(m_suv, m_vw, v_suv, v_vw, 0)
    ax = fig.add_subplot()
    for energy, style, label in (
        (kinetic_energy((m_suv, m_vw), (v_suv, v_vw)), "-", "KE ellipse"),
        (sticking.ke_after, "--", "IE ellipse"),
    ):
        # 1/2 M x^2 + 1/2 m y^2 = E has semi-axes sqrt(2E/M) and sqrt(2E/m)
        xs, ys = _ellipse(math.sqrt(2 * energy / m_suv), math.sqrt(2 * energy / m_vw))
        ax.plot(xs, ys, style, label=f"{label} (E = {energy:g})")
    p = elastic.momentum
    line_x = [-20.0, 100.0]
    ax.plot(line_x, [(p - m_suv * x) / m_vw for x in line_x], ":", label="momentum line")
    for (x, y), name in (
        ((v_suv, v_vw), "IN"),
        (elastic.after, "FIN (elastic)"),
        (sticking.after, "COM (inelastic)"),
    ):
        ax.plot([x], [y], "o")
        ax.annotate(f"{name} ({x:g}, {y:g})", (x, y), textcoords="offset points", xytext=(5, 5))
    ax.set_xlabel("V_SUV")
    ax.set_ylabel("V_VW")
    ax.set_aspect("equal")
    ax.set_xlim(-70, 110)
    ax.set_ylim(-130, 130)
    ax.legend(loc="lower left", fontsize="small")


@figure(
    "bang-sequence-49-1",
    "Fig. 5.1(a)",
    "The 49:1 pair under a ceiling in the (v1, v2) plane: each ball-ball bang and ceiling bang "
    "from the state (1, -1) after the floor bounce, to the last bang, on the energy ellipse.",
    ("ch05.pair-49-1.v1-after-9", "ch05.pair-49-1.v1-after-11", "ch05.pair-49-1.v2-after-11"),
)
def _bang_sequence(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    m1, m2 = _value(claims, "ch05.pair-49-1.m1"), _value(claims, "ch05.pair-49-1.m2")
    v1, v2 = _value(claims, "ch05.pair-49-1.v1-start"), _value(claims, "ch05.pair-49-1.v2-start")
    sequence = ceiling_sequence(m1, m2, v1, v2)
    ax = fig.add_subplot()
    energy = kinetic_energy((m1, m2), (v1, v2))
    xs, ys = _ellipse(math.sqrt(2 * energy / m1), math.sqrt(2 * energy / m2))
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


@figure(
    "tower-100-30-10",
    "Fig. 8.1(b)",
    "The 100/30/10 tower with independent collisions: each bang in the plane of the two "
    "velocities it changes, from START to END along the momentum line of slope -m_lower/m_upper.",
    ("ch08.tower-100-30-10.v1", "ch08.tower-100-30-10.v2-mid", "ch08.tower-100-30-10.v3"),
)
def _tower(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    masses = [_value(claims, f"ch08.tower-100-30-10.m{k}") for k in (1, 2, 3)]
    tower = independent_tower(masses, _value(claims, "ch08.tower-100-30-10.v-drop"))
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


@figure(
    "tunnel-and-orbit",
    "Fig. 9.8",
    "A body dropped through a tunnel across a uniform Earth and a satellite in the grazing "
    "circular orbit keep the same x coordinate and meet on the far side after half a period.",
    ("ch09.tunnel-time", "ch09.orbit-speed"),
)
def _tunnel(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    g = _value(claims, "ch09.surface-gravity")
    radius = _value(claims, "ch09.earth-radius")
    period = tunnel_period(g, radius)
    ax = fig.add_subplot()
    xs, ys = _ellipse(1.0, 1.0)
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


@figure(
    "e-series",
    "(10.6)",
    "Partial sums of the e-series (10.5) at r t = 1 against the order o: each term adds "
    "1/o! and the sums close in on e.",
    tuple(f"ch10.e-series.o{o}" for o in range(1, 9)),
)
def _e_series(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    x = _value(claims, "ch10.e-series.x")
    orders = list(range(0, 11))
    sums = [exp_partial_sum(x, o) for o in orders]
    limit = exp_partial_sum(x, 40)
    ax = fig.add_subplot()
    ax.semilogy(orders, [abs(limit - s) for s in sums], "-o", label="|e - partial sum|")
    ax.set_xlabel("precision order o")
    ax.set_ylabel("error")
    ax.legend(fontsize="small")


_SVG_ID = re.compile(r'id="([^"]+)"')
_METADATA = re.compile(r"<metadata>.*?</metadata>\s*", re.S)


def _svg(fig: Figure, key: str) -> str:
    """The figure as inline SVG: no date or RDF metadata, every id prefixed with ``key``."""
    import matplotlib

    buffer = io.StringIO()
    with matplotlib.rc_context({"svg.hashsalt": f"bangcheck-{key}", "svg.fonttype": "none"}):
        fig.savefig(buffer, format="svg", metadata={"Date": None}, bbox_inches="tight")
    text = buffer.getvalue()
    text = _METADATA.sub("", text[text.index("<svg") :])
    # matplotlib names its elements axes_1, line2d_1, ... in every figure: make them unique
    for ident in set(_SVG_ID.findall(text)):
        new = f"{key}-{ident}"
        text = text.replace(f'id="{ident}"', f'id="{new}"')
        text = text.replace(f"#{ident})", f"#{new})").replace(f'"#{ident}"', f'"#{new}"')
    return text


def render_all(evaluation: Evaluation) -> list[RenderedFigure]:
    """Every registered figure as inline SVG (figures whose claims are absent are skipped)."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    claims = evaluation.by_id()
    out = []
    for spec in FIGURES:
        missing = [c for c in spec.claims if c not in claims]
        if missing:
            raise KeyError(f"figure {spec.key} illustrates unknown claims {missing}")
        fig = Figure(figsize=(6.4, 4.2))
        spec.draw(fig, claims)
        out.append(
            RenderedFigure(
                spec.key, spec.book_figure, spec.caption, spec.claims, _svg(fig, spec.key)
            )
        )
    return out


def verdict_chart(counts: dict[str, dict[str, int]], verdicts: tuple[str, ...]) -> str:
    """A small stacked bar chart of claims per chapter by verdict, as inline SVG."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    fig = Figure(figsize=(6.4, 2.4))
    ax = fig.add_subplot()
    chapters = list(counts)
    bottom = [0] * len(chapters)
    colours = {
        "verified": "#2e7d32",
        "rounding": "#f9a825",
        "erratum": "#c62828",
        "given": "#90a4ae",
        "unmodeled": "#6a1b9a",
        "indeterminate": "#000000",
    }
    for verdict in verdicts:
        heights = [counts[c].get(verdict, 0) for c in chapters]
        if any(heights):
            ax.bar(chapters, heights, bottom=bottom, label=verdict, color=colours.get(verdict))
            bottom = [b + h for b, h in zip(bottom, heights, strict=True)]
    ax.set_xlabel("chapter")
    ax.set_ylabel("claims")
    ax.legend(fontsize="x-small", ncols=3)
    return _svg(fig, "verdict-chart")
