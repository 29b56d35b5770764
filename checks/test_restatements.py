"""Hand exclusions that name a claim (``restates ID``, ``part-of ID``) agree with it (design 3a)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from reference.book import Book
from reference.catalog import Catalog
from reference.restatements import pointed_claim, restatement_conflicts, restatement_problem
from reference.scan import scan
from reference.schema import Claim, Excluded
from reference.validate import checked_catalog

pytestmark = pytest.mark.integrity
CLAIMS = Path(__file__).parents[1] / "reference" / "claims"


def test_every_restatement_and_piece_agrees_with_its_claim(catalog: Catalog) -> None:
    pointing = [e for f in catalog.files for e in f.excluded if pointed_claim(e)]
    assert len(pointing) > 400  # the check has the catalog's exclusions to look at
    assert list(restatement_conflicts(catalog)) == []


def _claim(printed: str, unit: str = "1", **fields: object) -> Claim:
    base = {"id": "ch09.c", "line": 1, "quote": "q", "printed": printed, "quantity": "q"}
    return Claim.model_validate(
        {**base, "kind": "given", "expect": "given", "unit": unit, **fields}
    )


def _excluded(token: str, reason: str = "restates ch09.c", **fields: object) -> Excluded:
    return Excluded.model_validate({"line": 2, "token": token, "reason": reason, **fields})


@pytest.mark.parametrize(
    ("token", "fields", "claim", "holds"),
    [
        ("24", {}, _claim("24"), True),
        ("24", {}, _claim("24.25"), True),  # the token's own precision: 24 +- 0.5
        ("24.2", {}, _claim("24"), False),  # finer than the claim: a number of its own
        ("25", {}, _claim("24"), False),
        ("3·10-15", {"unit": "m"}, _claim("3", unit="fm"), True),
        ("3·10-15", {}, _claim("3", unit="fm"), False),  # without the unit: 3e-15 fm
        ("45°", {"unit": "deg"}, _claim("π/4", unit="rad"), True),
        ("60.2", {"means": "60.2e22"}, _claim("6.02E23"), True),
        ("1", {"means": "±1"}, _claim("-1"), True),  # |ve| = 1 restating ve = -1
        ("1", {}, _claim("-1"), False),
        ("7", {"unit": "scaled"}, _claim("7", unit="m"), False),  # no conversion
    ],
)
def test_a_restatement_holds_within_the_tokens_precision(
    token: str, fields: dict[str, str], claim: Claim, holds: bool
) -> None:
    assert (restatement_problem(_excluded(token, **fields), claim) is None) == holds


@pytest.mark.parametrize(
    ("token", "fields", "claim", "holds"),
    [
        ("3", {}, _claim("π/3"), True),  # the 3 of π/3, set on a line of its own
        ("4", {}, _claim("π/3"), False),  # digits that are not in the whole
        ("6", {"means": "π/6", "unit": "rad"}, _claim("30°", unit="deg"), True),
        ("6", {"means": "π/6", "unit": "rad"}, _claim("35°", unit="deg"), False),
        ("6", {"means": "π/5", "unit": "rad"}, _claim("36°", unit="deg"), False),  # no 6
        ("43", {}, _claim("10-43"), True),  # the exponent digits of 10^-43
    ],
)
def test_a_piece_is_in_the_whole_and_the_whole_agrees(
    token: str, fields: dict[str, str], claim: Claim, holds: bool
) -> None:
    e = _excluded(token, reason="part-of ch09.c", **fields)
    assert (restatement_problem(e, claim) is None) == holds


def test_a_disagreement_is_a_scan_conflict_not_a_catalog_error(book: Book, tmp_path: Path) -> None:
    """A draft catalog with one edited value still evaluates; ``scan`` names the restatements
    that no longer agree with it."""
    text = (CLAIMS / "ch08.toml").read_text(encoding="utf-8")
    edited = re.sub(
        r'(id = "ch08.tower-3.ratio"\n(?:.+\n)*?printed = "3"\n)',
        '\\1means = "4"\ngarble = "other"\nnote = "a draft\'s edit"\n',
        text,
        count=1,
    )
    assert edited != text
    (tmp_path / "ch08.toml").write_text(edited, encoding="utf-8")
    draft = checked_catalog(book, tmp_path)  # no CatalogError
    conflicts = scan(book, draft, ("8",)).conflicts
    assert conflicts
    assert all("restates ch08.tower-3.ratio" in line for line in conflicts), conflicts
