"""The report in a real browser: Debian's Chromium, headless, driven by Playwright.

The page is opened from its file: no console errors, the verdict filter and the text search work,
and a screenshot is saved beside the page. Skips with the reason where Chromium or Playwright is
absent, except under ``CI=true``, where that is a failure (``.ci/run`` installs Chromium).
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from reference.evaluation import Evaluation

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


def _unavailable(reason: str) -> None:
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail(f"CI=true but {reason}")
    pytest.skip(reason)


@pytest.fixture(scope="module")
def browser_page(report_dir: Path, tmp_path_factory: pytest.TempPathFactory):
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


def _visible_rows(page) -> list[str]:
    return page.eval_on_selector_all(
        "tr.claim", "rows => rows.filter(r => !r.hidden).map(r => r.dataset.verdict)"
    )


def test_no_console_errors(browser_page) -> None:
    page, errors = browser_page
    assert page.title().startswith("bangcheck")
    assert errors == []


def test_the_verdict_filter_hides_rows(browser_page, evaluation: Evaluation) -> None:
    page, _ = browser_page
    assert len(_visible_rows(page)) == len(evaluation)
    page.uncheck("input.verdict-filter[value=verified]")
    shown = _visible_rows(page)
    assert "verified" not in shown
    assert len(shown) == sum(c.verdict != "verified" for c in evaluation)
    assert page.inner_text("#shown-count") == str(len(shown))
    page.check("input.verdict-filter[value=verified]")
    assert len(_visible_rows(page)) == len(evaluation)


def test_the_search_finds_a_claim(browser_page) -> None:
    page, _ = browser_page
    page.fill("#search", "tower-100-30-10.v3-intro")
    visible = page.eval_on_selector_all(
        "tr.claim", "rows => rows.filter(r => !r.hidden).map(r => r.id)"
    )
    assert visible == ["claim-ch08.tower-100-30-10.v3-intro"]
    page.fill("#search", "")


def test_screenshot(browser_page, report_dir: Path) -> None:
    page, _ = browser_page
    path = report_dir / "screenshot.png"
    page.screenshot(path=str(path), full_page=False)
    assert path.stat().st_size > 10_000
    print(f"screenshot: {path}")
