"""The fakes the evaluator's tests (``checks/test_evaluate_*.py``) share: a chapter of their
own (``META``), claims built from a few fields, a catalog of them evaluated on the book, and a
model name that resolves to any function."""

from __future__ import annotations

from typing import Any

import pytest

from reference import calls, modelling
from reference import evaluation as evaluate
from reference.book import Book
from reference.catalog import Catalog, ChapterFile
from reference.schema import Claim, Meta

META = Meta.model_validate(
    {"chapter": "8", "title": "t", "lines": [6510, 6935], "complete": False, "schema": 1}
)


def claim(**fields: Any) -> Claim:
    base = {"line": 6562, "quote": "q", "quantity": "q", "unit": "scaled"}
    return Claim.model_validate({**base, **fields})


def run(book: Book, *claims: Claim) -> dict[str, evaluate.EvaluatedClaim]:
    f = ChapterFile("reference/claims/ch08.toml", "ch08", META, claims, (), ())
    return evaluate.evaluate_catalog(Catalog((f,)), book).by_id()


def fake_model(monkeypatch: pytest.MonkeyPatch, func: Any) -> None:
    monkeypatch.setattr(calls, "resolve", lambda name: func)
    monkeypatch.setattr(modelling, "resolve", lambda name: func)


def evaluated(book: Book, *claims: Claim, progress: bool = False) -> evaluate.Evaluation:
    f = ChapterFile("reference/claims/ch08.toml", "ch08", META, claims, (), ())
    return evaluate.evaluate_catalog(Catalog((f,)), book, progress=progress)


def _rounded_given(ident: str = "ch08.v", printed: str = "2.1") -> Claim:
    return claim(id=ident, printed=printed, kind="given", expect="given", rounded=True)
