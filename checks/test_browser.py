"""The report in a real browser: Debian's Chromium, headless, driven by Playwright.

The page is opened from its file: no console errors, the verdict filter and the text search work,
and a screenshot is saved beside the page. Skips with the reason where Chromium or Playwright is
absent, except under ``CI=true``, where that is a failure (``.ci/run`` installs Chromium).
"""

from __future__ import annotations

import dataclasses
import json
import os
import shutil
from collections import Counter
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING, NoReturn

import pytest

from reference.book import Book
from reference.catalog import Catalog
from reference.evaluated import EvaluatedClaim
from reference.evaluation import Evaluation

if TYPE_CHECKING:
    from playwright.sync_api import Page

    BrowserPage = tuple[Page, list[str]]  # the page and the console errors it logged

# under xdist (--dist loadgroup) every test that reads the session's evaluation or scan is in
# one group, run by one worker, which evaluates the catalog, scans the book and builds the
# report once
pytestmark = [pytest.mark.browser, pytest.mark.xdist_group("evaluation")]

CHROMIUM = "/usr/bin/chromium"
FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]


def _unavailable(reason: str) -> NoReturn:
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail(f"CI=true but {reason}")
    pytest.skip(reason)


@pytest.fixture(scope="module")
def browser_page(
    report_dir: Path, tmp_path_factory: pytest.TempPathFactory
) -> Iterator[BrowserPage]:
    if not (Path(CHROMIUM).exists() or shutil.which("chromium")):
        _unavailable(f"no Chromium at {CHROMIUM}: apt-get install chromium")
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        _unavailable("playwright is not installed: pip install -e '.[test]'")
    profile = tmp_path_factory.mktemp("chromium-profile")
    with sync_playwright() as p:
        context = p.chromium.launch_persistent_context(
            str(profile),
            executable_path=CHROMIUM,
            args=FLAGS,
            headless=True,
            viewport={"width": 1280, "height": 900},
        )
        page = context.new_page()
        errors: list[str] = []
        page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto((report_dir / "index.html").as_uri())
        page.wait_for_load_state("load")
        yield page, errors
        context.close()


def _visible_rows(page: Page) -> list[str]:
    return page.eval_on_selector_all(
        "tr.claim", "rows => rows.filter(r => !r.hidden).map(r => r.dataset.verdict)"
    )


def test_no_console_errors(browser_page: BrowserPage) -> None:
    page, errors = browser_page
    assert page.title().startswith("bangcheck")
    assert errors == []


def test_the_verdict_filter_hides_rows(browser_page: BrowserPage, evaluation: Evaluation) -> None:
    page, _ = browser_page
    assert len(_visible_rows(page)) == len(evaluation)
    page.uncheck("input.verdict-filter[value=verified]")
    shown = _visible_rows(page)
    assert "verified" not in shown
    assert len(shown) == sum(c.verdict != "verified" for c in evaluation)
    assert page.inner_text("#shown-count") == str(len(shown))
    page.check("input.verdict-filter[value=verified]")
    assert len(_visible_rows(page)) == len(evaluation)


def test_the_search_finds_a_claim(browser_page: BrowserPage) -> None:
    page, _ = browser_page
    page.fill("#search", "tower-100-30-10.v3-intro")
    visible = page.eval_on_selector_all(
        "tr.claim", "rows => rows.filter(r => !r.hidden).map(r => r.id)"
    )
    assert visible == ["claim-ch08.tower-100-30-10.v3-intro"]
    page.fill("#search", "")


def test_the_search_reads_the_quote_and_hides_empty_chapters(browser_page: BrowserPage) -> None:
    """A phrase of the book's text finds its claim; chapters left empty are hidden, heading and
    all; a search that finds nothing says so."""
    page, _ = browser_page
    page.fill("#search", "giving final top m3 velocity")
    visible = page.eval_on_selector_all(
        "tr.claim", "rows => rows.filter(r => !r.hidden).map(r => r.id)"
    )
    assert visible == ["claim-ch08.tower-100-30-10.v3"]
    chapters = page.eval_on_selector_all(
        ".chapter-claims", "cs => cs.filter(c => !c.hidden).map(c => c.id)"
    )
    assert chapters == ["chapter-8"]
    assert page.is_hidden("#no-matches")
    page.fill("#search", "no claim says this")
    assert page.is_visible("#no-matches")
    assert page.inner_text("#shown-count") == "0"
    page.fill("#search", "")
    assert page.is_hidden("#no-matches")


@pytest.fixture(scope="class", params=[390, 1400])
def page_at_width(
    browser_page: BrowserPage, request: pytest.FixtureRequest
) -> Iterator[tuple[Page, int]]:
    """The shared page at a phone's and a wide screen's width (each test of the class at both,
    grouped by width: on the 2,000-row page every change of width is a relayout of a second)."""
    page, _ = browser_page
    width: int = request.param
    page.set_viewport_size({"width": width, "height": 900})
    yield page, width
    page.set_viewport_size({"width": 1280, "height": 900})


class TestAtWidth:
    def test_the_page_fits_its_width_and_shows_no_python(
        self, page_at_width: tuple[Page, int]
    ) -> None:
        """No horizontal overflow on a phone (390 px) or a wide screen (1,400 px): wide tables
        scroll inside the page; no Python repr ("None", "[1.0, 2.0]") in the text."""
        page, width = page_at_width
        assert page.evaluate("document.documentElement.scrollWidth") <= width
        words = page.evaluate("document.body.innerText").split()
        assert "None" not in words
        assert "nan" not in words

    def test_screenshot(self, page_at_width: tuple[Page, int], report_dir: Path) -> None:
        page, width = page_at_width
        path = report_dir / f"screenshot-{width}.png"
        page.screenshot(path=str(path), full_page=False)
        assert path.stat().st_size > 10_000
        print(f"screenshot: {path}")


@pytest.mark.parametrize("anchor", ["claim-ch08.tower-100-30-10.v3", "errata", "power"])
def test_anchors_land_below_the_sticky_bar(
    browser_page: BrowserPage, report_dir: Path, anchor: str
) -> None:
    page, _ = browser_page
    page.goto((report_dir / "index.html").as_uri() + "#" + anchor)
    page.wait_for_timeout(50)
    target = page.eval_on_selector(f'[id="{anchor}"]', "e => e.getBoundingClientRect().top")
    top, bottom = page.eval_on_selector(
        ".controls", "e => [e.getBoundingClientRect().top, e.getBoundingClientRect().bottom]"
    )
    assert 0 <= target < 900  # in view
    if top <= 1:  # the bar is stuck at the top of the view: the target is not under it
        assert target >= bottom - 1, (target, bottom)


# Chapters whose page holds every kind of element the report has: every verdict (rounding in 7,
# dated constants in 4), formula claims, garbled numbers and dates (0), errata cards, figures
AUDITED_CHAPTERS = ("0", "4", "7")
# of each kind of row (chapter, verdict, kind, garbled or not) the audited page keeps this many:
# every row of a kind comes from one template, and axe-core's colour-contrast rule measures
# every cell of the page (about 40 ms a row)
ROWS_OF_A_KIND = 2
# a figure drawn on the audited page (one that reads no claim beyond those it shows)
AUDITED_FIGURES = ("soft-pair-linear",)


def audited_claims(evaluation: Evaluation) -> tuple[EvaluatedClaim, ...]:
    """The claims of the audited page, in catalog order: ``ROWS_OF_A_KIND`` of each kind of row
    of ``AUDITED_CHAPTERS``, and the claims ``AUDITED_FIGURES`` show."""
    from reports.figures import registered

    drawn = {c for spec in registered() if spec.key in AUDITED_FIGURES for c in spec.claims}
    kept: Counter[tuple[str, str, str, bool]] = Counter()
    claims = []
    for claim in evaluation:
        if claim.chapter not in AUDITED_CHAPTERS:
            continue
        kind = (claim.chapter, claim.verdict, claim.kind, claim.garble is not None)
        if claim.id in drawn or kept[kind] < ROWS_OF_A_KIND:
            kept[kind] += 1
            claims.append(claim)
    return tuple(claims)


@pytest.fixture(scope="module")
def audited_report(
    book: Book,
    catalog: Catalog,
    evaluation: Evaluation,
    tmp_path_factory: pytest.TempPathFactory,
) -> Path:
    """The report of a sample of ``AUDITED_CHAPTERS`` (``audited_claims``), from the session's
    evaluation: the whole book's page repeats the same templates over 2,000 rows, and axe-core
    needs minutes for it (its colour-contrast rule measures every cell), a second for these."""
    from reference.scan import scan
    from reports.outdir import write_report_dir
    from reports.page import build_report

    claims = audited_claims(evaluation)
    ids = {c.id for c in claims}
    misprints = {k: v for k, v in evaluation.misprints.items() if k in ids}
    sample = dataclasses.replace(evaluation, claims=claims, misprints=misprints)
    files = build_report(sample, scan(book, catalog, AUDITED_CHAPTERS), catalog, None)
    out = tmp_path_factory.mktemp("audited") / "out"
    write_report_dir(out, files)
    return out


def test_the_audited_page_shows_every_verdict_and_element(
    audited_report: Path, evaluation: Evaluation
) -> None:
    """Every verdict, every kind of claim of the audited chapters, garbled numbers, errata and
    dated-constant cards and the chosen figures are on the audited page, which holds less than
    half of those chapters' claims."""
    page = (audited_report / "index.html").read_text(encoding="utf-8")
    claims = json.loads((audited_report / "claims.json").read_text(encoding="utf-8"))["claims"]
    verdicts = {c["verdict"] for c in claims}
    kinds = {c["kind"] for c in claims}
    assert verdicts == {"verified", "rounding", "erratum", "dated", "given"}
    assert kinds == {c.kind for c in evaluation if c.chapter in AUDITED_CHAPTERS}
    assert any(c["garble"] for c in claims)
    assert '<article class="erratum' in page
    assert '<article class="dated"' in page
    assert len(claims) < sum(c.chapter in AUDITED_CHAPTERS for c in evaluation) / 2
    for key in AUDITED_FIGURES:
        assert f'<figure id="figure-{key}"' in page


def test_no_accessibility_violations(browser_page: BrowserPage, audited_report: Path) -> None:
    """axe-core (the npm package's build, bundled by axe-playwright-python) finds no
    violation of WCAG 2 A/AA or best practice on the page: contrast, landmarks, names."""
    try:
        from axe_playwright_python.sync_playwright import Axe
    except ImportError:
        _unavailable("axe-playwright-python is not installed: pip install -e '.[test]'")
    page = browser_page[0].context.new_page()  # the shared page stays on the whole report
    try:
        page.goto((audited_report / "index.html").as_uri())
        violations = Axe().run(page).response["violations"]
    finally:
        page.close()
    assert [(v["id"], v["impact"], len(v["nodes"])) for v in violations] == []


def test_the_audit_sees_a_violation(browser_page: BrowserPage, tmp_path: Path) -> None:
    """The same audit on a page with an image without a text alternative and grey on grey."""
    from axe_playwright_python.sync_playwright import Axe

    bad = tmp_path / "bad.html"
    bad.write_text(
        '<!doctype html><html lang="en"><title>t</title><main><img src="x.png">'
        '<p style="color:#aaa;background:#bbb">faint</p></main></html>',
        encoding="utf-8",
    )
    page = browser_page[0].context.new_page()
    try:
        page.goto(bad.as_uri())
        found = {v["id"] for v in Axe().run(page).response["violations"]}
    finally:
        page.close()
    assert {"image-alt", "color-contrast"} <= found
