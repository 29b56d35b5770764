"""The report's figures are legible: every axes that shows a scale has both axis labels, and
no text is smaller than 7 pt at the size the page shows it.

The figures are not drawn again: the session's report (``report_dir``, shared with
``test_report.py``) already drew every registered figure once, as inline SVG, and the checks
read that SVG. matplotlib writes each axes as a group ``<g id="…axes_N">``, each of its axis
(ticks and label) as a child group ``<g id="…matplotlib.axis_N">`` holding one group per tick
and, after them, a text group for the axis label; an axes turned off (a picture) has no axis
group at all. Texts are written as ``<text>`` (with ``svg.fonttype`` none) whose font size, in
the SVG's units of points, is that of the text or of its mathtext glyphs (a sub- or superscript
glyph is smaller: a text's size is that of its largest glyph). The page shows an SVG at its
own size unless it is wider than the page's column, which shrinks it (``PAGE_WIDTH``). A
synthetic figure checks that these checks still catch what they look for.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

import pytest

from reports.figures import _svg, registered

pytestmark = [pytest.mark.report, pytest.mark.xdist_group("evaluation")]

PAGE_WIDTH = 888.0  # pt: the page's column, 76rem less 2 x 1rem of padding (1,184 px)
SMALLEST = 7.0  # pt, as shown on the page

_SVG = "{http://www.w3.org/2000/svg}"
_FIGURE = re.compile(r'<figure id="figure-([^"]+)">.*?(<svg.*?</svg>)', re.S)
_SIZE = re.compile(r"font-size:\s*([\d.]+)px")
_FAMILY = re.compile(r"font-family:\s*([^;\"]+)")
_AXES = re.compile(r"-axes_\d+$")
_AXIS = re.compile(r"-matplotlib\.axis_\d+$")
_TEXT = re.compile(r"-text_\d+$")


@dataclass(frozen=True)
class Legibility:
    """What a figure's SVG shows: its axes without a label, its texts smaller than allowed."""

    unlabelled: list[str]
    small: list[str]


def _groups(element: ET.Element, pattern: re.Pattern[str]) -> list[ET.Element]:
    return [g for g in element if g.tag == f"{_SVG}g" and pattern.search(g.get("id", ""))]


def _words(element: ET.Element) -> str:
    return "".join(element.itertext()).strip()


def legibility(svg: str) -> Legibility:
    """The axes of ``svg`` with an axis but no label on it, and its texts (with their size as
    shown) below ``SMALLEST`` once the SVG is shrunk to ``PAGE_WIDTH``."""
    root = ET.fromstring(svg)
    width = float(root.get("width", "0pt").removesuffix("pt"))
    shown = min(1.0, PAGE_WIDTH / width)
    unlabelled = []
    for axes in root.iter(f"{_SVG}g"):
        if not _AXES.search(axes.get("id", "")):
            continue
        titles = [_words(t) for t in _groups(axes, _TEXT) if _words(t)]
        for name, axis in zip("xy", _groups(axes, _AXIS), strict=False):  # x first, then y
            # the label is a text directly in the axis group; the tick labels are in tick groups
            if not any(_words(t) for t in _groups(axis, _TEXT)):
                unlabelled.append(f"{axes.get('id')} {titles[:1]}: no {name} label")
    small = []
    for text in root.iter(f"{_SVG}text"):
        sizes = [float(s) for e in text.iter() for s in _SIZE.findall(e.get("style", ""))]
        if sizes and max(sizes) * shown < SMALLEST:
            small.append(f"{_words(text)!r} at {max(sizes) * shown:.1f} pt")
    return Legibility(unlabelled, small)


@pytest.fixture(scope="module")
def figures(report_dir: Path) -> dict[str, str]:
    """Each figure of the session's report as its SVG, by key."""
    html = (report_dir / "index.html").read_text("utf-8")
    return dict(_FIGURE.findall(html))


def test_the_report_has_every_figure_as_svg(figures: dict[str, str]) -> None:
    assert sorted(figures) == sorted(spec.key for spec in registered())


def test_every_axis_is_labelled(figures: dict[str, str]) -> None:
    """An axes with a scale names both its quantities; one that is only a picture is off."""
    missing = {key: found for key, svg in figures.items() if (found := legibility(svg).unlabelled)}
    assert missing == {}


def test_no_text_is_smaller_than_7_pt(figures: dict[str, str]) -> None:
    """Titles, labels, tick labels, legends and notes are at least 7 pt on the page."""
    small = {key: found for key, svg in figures.items() if (found := legibility(svg).small)}
    assert small == {}


def test_every_text_falls_back_to_a_generic_font(figures: dict[str, str]) -> None:
    """A mathtext glyph names DejaVu Sans alone: ``_svg`` adds sans-serif for a reader
    without it (and there is no glyph from a font no reader has, like STIX's sizes)."""
    families = {f for svg in figures.values() for f in _FAMILY.findall(svg)}
    assert {f for f in families if not f.endswith(("sans-serif", "serif"))} == set()
    assert not any("STIX" in f for f in families)


def test_the_checks_catch_a_missing_label_and_a_small_text() -> None:
    """A figure with one good axes, one without a y label and a 5 pt note, and one turned off
    (a picture, which needs no labels); and a figure so wide that the page shrinks it."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    fig = Figure(figsize=(6.4, 2.4))
    good, bad, picture = fig.subplots(1, 3)
    good.plot([0, 1], [0, 1])
    good.set_xlabel(r"time $t$ (s)")
    good.set_ylabel(r"velocity $V_1$ (scaled)")
    bad.set_xlabel("x")
    bad.text(0.5, 0.5, "tiny", fontsize=5)
    picture.set_axis_off()
    picture.set_title("a picture")
    found = legibility(_svg(fig, "check"))
    assert [u.split(":")[-1] for u in found.unlabelled] == [" no y label"]
    assert found.small == ["'tiny' at 5.0 pt"]

    wide = Figure(figsize=(24, 2))  # about 1,380 pt wide once trimmed: shown at 0.64 of it
    ax = wide.add_subplot()
    ax.set_xlabel("x (m)", fontsize=10)
    ax.set_ylabel("y (m)", fontsize=12)
    shrunk = [text.split(" at ")[0] for text in legibility(_svg(wide, "wide")).small]
    assert "'x (m)'" in shrunk
    assert "'y (m)'" not in shrunk
