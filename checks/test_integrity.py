"""Integrity of the real catalog and its evaluation.

The catalog's own rules (ids, lines, quotes, tokens, models, references, errata fields) are
checked at collection (conftest) and each is shown to catch its problem in
test_catalog_errors.py; here are the checks that need the evaluation or the scan.
"""

from __future__ import annotations

import json
import math
from fractions import Fraction

import pytest

from reference import calls as calls_module
from reference.book import Book, identity
from reference.catalog import Catalog
from reference.evaluation import Evaluation
from reference.scan import ScanResult
from reference.tables import unit_factor
from reference.validate import parsed, validate

# under xdist (--dist loadgroup) every test that reads the session's evaluation or scan is in
# one group, run by one worker, which evaluates the catalog and scans the book once
pytestmark = [pytest.mark.integrity, pytest.mark.xdist_group("evaluation")]


def test_the_catalog_is_valid_against_the_book(catalog: Catalog, book: Book) -> None:
    assert validate(catalog, book) == []


def test_one_file_per_chapter(catalog: Catalog) -> None:
    assert [f.stem for f in catalog.files] == [c.file_stem for c in identity().chapters]


def test_restatements_equal_what_they_restate(catalog: Catalog) -> None:
    by_id = catalog.by_id()
    unequal = []
    for _, claim in catalog.claims():
        if claim.restates is None:
            continue
        other = by_id[claim.restates]
        mine, theirs = parsed(claim), parsed(other)
        # compare in SI where the two print the quantity in different physical units
        a, b = Fraction(unit_factor(claim.unit)), Fraction(unit_factor(other.unit))
        coarser = max(mine.tolerance * a, theirs.tolerance * b)
        if abs(mine.value * a - theirs.value * b) > coarser:
            unequal.append((claim.id, claim.printed, claim.restates))
    assert not unequal


def test_errata_agree_with_their_correct_value(evaluation: Evaluation) -> None:
    wrong = [
        (c.id, c.correct, c.model_value)
        for c in evaluation
        if c.expect == "erratum" and not c.correct_agrees
    ]
    assert not wrong


def test_expected_errata_really_disagree_with_the_model(evaluation: Evaluation) -> None:
    """An erratum is asserted both ways: beyond twice the tolerance of "=", or failing its
    relation."""
    for c in evaluation:
        if c.expect != "erratum":
            continue
        assert c.model_value is not None, c.id
        if c.relation == "=":
            assert c.tolerance is not None, c.id
            model = c.model_value[0] if isinstance(c.model_value, list) else c.model_value
            assert abs(model - (c.value or 0)) > 2 * c.tolerance, c.id
        else:
            assert c.verdict == "erratum", c.id


def test_no_claim_expects_unmodeled_or_is_indeterminate(evaluation: Evaluation) -> None:
    assert not [c.id for c in evaluation if c.verdict == "indeterminate"]
    assert not [c.id for c in evaluation if c.expect in ("unmodeled", "indeterminate")]


def test_complete_chapters_have_no_missing_token_and_no_unmodeled_claim(
    catalog: Catalog, whole_scan: ScanResult, evaluation: Evaluation
) -> None:
    complete = tuple(f.meta.chapter for f in catalog.files if f.meta.complete)
    if not complete:
        pytest.skip("no chapter is marked complete yet")
    missing = [(t.line, t.text) for t in whole_scan.missing if t.chapter in complete]
    assert missing == []
    assert not [c.id for c in evaluation if c.chapter in complete and c.verdict == "unmodeled"]


def test_rounding_claims_say_why(evaluation: Evaluation) -> None:
    for c in evaluation:
        assert (c.verdict == "rounding") == (c.rounding_reason is not None), c.id


def test_json_has_no_nan_and_every_field(evaluation: Evaluation) -> None:
    fields = [
        "id",
        "chapter",
        "line",
        "line_end",
        "occurrence",
        "quote",
        "printed",
        "means",
        "garble",
        "value",
        "model_value",
        "interval",
        "tolerance",
        "rounding_reason",
        "relation",
        "unit",
        "kind",
        "verdict",
        "expect",
        "correct",
        "diagnosis",
        "quantity",
        "model",
        "args",
        "model_error",
        "assumptions",
        "figure",
        "equation",
    ]
    for c in evaluation:
        row = json.loads(json.dumps(c.to_json(), allow_nan=False))
        assert set(fields) <= set(row), c.id
        for value in (row["value"], row["model_value"], row["tolerance"]):
            assert value is None or isinstance(value, list) or math.isfinite(value)


def test_each_distinct_model_call_is_made_once(evaluation: Evaluation, catalog: Catalog) -> None:
    by_id = catalog.by_id()
    keys = set()
    modelled = 0
    for _, claim in catalog.claims():
        if claim.model is None:
            continue
        modelled += 1
        args, inputs = calls_module.build_args(
            claim.args, lambda ident: (by_id[ident], parsed(by_id[ident]))
        )
        rounded = [i for i in inputs if i.rounded]
        for call in [args, *(calls_module.corners(args, rounded) if rounded else [])]:
            keys.add(calls_module.ModelCache.key(claim.model, {**call, **claim.assumptions}))
    # fewer calls than modelled claims: the tower claims share one call of independent_tower
    assert evaluation.model_calls == len(keys) < modelled


def test_the_cache_calls_a_model_once_per_arguments(monkeypatch: pytest.MonkeyPatch) -> None:
    calls = []

    def model(masses: list[int], v_drop: int) -> float:
        calls.append((masses, v_drop))
        return 1.0

    monkeypatch.setattr(calls_module, "resolve", lambda name: model)
    cache = calls_module.ModelCache()
    for _ in range(3):
        cache.picked("ch08.x", "towers.independent_tower", {"masses": [100, 30], "v_drop": 1}, "")
    cache.picked("ch08.x", "towers.independent_tower", {"masses": [100, 31], "v_drop": 1}, "")
    assert (len(calls), cache.calls) == (2, 2)


def test_to_frame_gives_one_row_per_claim(evaluation: Evaluation) -> None:
    frame = evaluation.to_frame()
    assert len(frame) == len(evaluation)
    assert list(frame["id"]) == [c.id for c in evaluation]
    assert {"verdict", "model_value", "tolerance"} <= set(frame.columns)


def test_every_input_interval_contains_its_own_model_value(evaluation: Evaluation) -> None:
    """An input interval is the model's range over the box of rounded inputs: it contains the
    model's value at the nominal inputs (and at the box's centre), or it was computed wrong (a
    model not monotonic over its box, judged from its corners alone)."""
    outside = [
        (c.id, c.model_value, c.interval)
        for c in evaluation
        if c.interval is not None
        and isinstance(c.model_value, float | int)
        and not c.interval[0] <= c.model_value <= c.interval[1]
    ]
    assert not outside
