"""The report's figures, drawn by calling mechmodel with the catalog's own inputs.

Each figure is one small function registered with ``@figure`` in the module of its chapter
(``reports/figures/chNN.py``): it gets the evaluated claims (to read the book's givens and to name
the claims it illustrates) and a matplotlib ``Figure`` to draw on. ``render_all`` imports every
chapter module and returns each figure as inline SVG, deterministic (no date, one
``svg.hashsalt`` per figure, every SVG id prefixed with the figure's key so ids never clash
within one page). Adding a figure is one decorated function.
"""

from __future__ import annotations

import importlib
import io
import multiprocessing
import os
import pkgutil
import re
import signal
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from fractions import Fraction
from typing import TYPE_CHECKING

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
    module: str


@dataclass(frozen=True)
class RenderedFigure:
    """A figure ready for the page."""

    key: str
    book_figure: str
    caption: str
    claims: tuple[str, ...]
    svg: str


FIGURES: list[FigureSpec] = []


def value_of(claims: dict[str, EvaluatedClaim], ident: str) -> float:
    """The value a claim states (its printed number, or ``means``): the book's own input."""
    value = claims[ident].value
    if value is None:
        raise ValueError(f"claim {ident} has no numeric value to draw with")
    return value


def as_float(value: object) -> float:
    """A model's value as matplotlib takes it: a real number (int, Fraction, float) as a float.
    A model typed ``Symbolic`` gives real numbers for real inputs; anything else is a bug."""
    if not isinstance(value, int | float | Fraction):
        raise TypeError(f"not a real number to draw: {value!r}")
    return float(value)


def as_floats(values: Iterable[object]) -> list[float]:
    """Each value ``as_float``."""
    return [as_float(v) for v in values]


def figure(key: str, book_figure: str, caption: str, claims: tuple[str, ...]) -> Callable:
    """Register a drawing function as a report figure."""

    def register(draw: Callable[[Figure, dict[str, EvaluatedClaim]], None]) -> Callable:
        if any(f.key == key for f in FIGURES):
            raise ValueError(f"two figures with the key {key!r}")
        FIGURES.append(FigureSpec(key, book_figure, caption, claims, draw, draw.__module__))
        return draw

    return register


_SVG_ID = re.compile(r'id="([^"]+)"')
_SVG_REF = re.compile(r'(id="|url\(#|"#)([^")]+)(?=[")])')
_METADATA = re.compile(r"<metadata>.*?</metadata>\s*", re.S)
# a mathtext glyph names its one font, DejaVu Sans: a reader without it gets a sans-serif
_ONE_FONT = re.compile(r"(font-family: '[^']+')(?=[;\"])")


def _svg(fig: Figure, key: str) -> str:
    """The figure as inline SVG: no date or RDF metadata, every id prefixed with ``key``, a
    generic sans-serif after a mathtext glyph's font."""
    import matplotlib

    buffer = io.StringIO()
    with matplotlib.rc_context({"svg.hashsalt": f"bangcheck-{key}", "svg.fonttype": "none"}):
        fig.savefig(buffer, format="svg", metadata={"Date": None}, bbox_inches="tight", dpi=200)
    text = buffer.getvalue()
    text = _METADATA.sub("", text[text.index("<svg") :])
    text = _ONE_FONT.sub(r"\1, sans-serif", text)
    # matplotlib names its elements axes_1, line2d_1, ... in every figure: make them unique,
    # in one pass over the text (ids and the url(#id) and href="#id" references to them)
    ids = set(_SVG_ID.findall(text))

    def prefixed(match: re.Match[str]) -> str:
        lead, name = match.groups()
        return f"{lead}{key}-{name}" if name in ids else match.group(0)

    return _SVG_REF.sub(prefixed, text)


def registered() -> list[FigureSpec]:
    """Every figure of every chapter module."""
    _register_all()
    return list(FIGURES)


def _register_all() -> None:
    for module in pkgutil.iter_modules(__path__):
        importlib.import_module(f"{__name__}.{module.name}")


_CLAIMS: dict[str, EvaluatedClaim] = {}  # the claims a forked worker draws with


def _load_matplotlib() -> None:
    """Import matplotlib with its headless backend and the SVG writer. Done once before the
    workers fork, so that each inherits it instead of importing it again (about 0.3 s each)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.backends.backend_svg
    import matplotlib.figure


def _draw(key: str) -> str:
    """One figure as SVG (run in a worker process forked after ``_CLAIMS`` was set)."""
    _load_matplotlib()
    from matplotlib.figure import Figure

    spec = next(f for f in FIGURES if f.key == key)
    fig = Figure(figsize=(6.4, 4.2))
    spec.draw(fig, _CLAIMS)
    return _svg(fig, spec.key)


def _ignore_interrupts() -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)


def render_all(evaluation: Evaluation, workers: int | None = None) -> list[RenderedFigure]:
    """Every registered figure whose claims are evaluated, as inline SVG, in chapter order,
    drawn in parallel by ``workers`` forked processes (by default one per core, at most 4;
    serially where forking is not available or ``workers`` is 1)."""
    _register_all()
    claims = evaluation.by_id()
    # a report of some chapters draws the figures of those chapters only
    specs = [
        spec
        for spec in sorted(FIGURES, key=lambda f: (f.module, FIGURES.index(f)))
        if all(c in claims for c in spec.claims)
    ]
    _CLAIMS.clear()
    _CLAIMS.update(claims)
    keys = [spec.key for spec in specs]
    _load_matplotlib()
    workers = min(len(keys), workers or os.cpu_count() or 1, 4)
    if workers > 1 and "fork" in multiprocessing.get_all_start_methods():
        context = multiprocessing.get_context("fork")
        # an interrupt (Ctrl-C reaches the whole process group) is the parent's to handle:
        # leaving the pool's block terminates the workers, which ignore it
        with context.Pool(workers, initializer=_ignore_interrupts) as pool:
            svgs = pool.map(_draw, keys)
    else:
        svgs = [_draw(key) for key in keys]
    return [
        RenderedFigure(spec.key, spec.book_figure, spec.caption, spec.claims, svg)
        for spec, svg in zip(specs, svgs, strict=True)
    ]


def verdict_chart(counts: dict[str, dict[str, int]], verdicts: tuple[str, ...]) -> str:
    """A small stacked bar chart of claims per chapter by verdict, as inline SVG."""
    _load_matplotlib()
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
    if any(bottom):  # a legend of the bars drawn (a report of no claims draws none)
        ax.legend(fontsize="x-small", ncols=3)
    return _svg(fig, "verdict-chart")
