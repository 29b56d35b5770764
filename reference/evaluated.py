"""The results of an evaluation: ``EvaluatedClaim``, one claim with its verdict, and ``Evaluation``.

``EvaluatedClaim`` holds the fields of ``claims --json`` (design section 4): the claim as
catalogued, its model value and input interval in the printed unit, its tolerance h and verdict.
``Evaluation`` is the run's claims in catalog order with what the report and the tests read
beside them: the judging contexts, the model's values at the centres of the boxes of rounded
inputs, the misprints judged (design 3a), the book's errors among the claims and the detection
power; ``.to_frame()`` gives a pandas DataFrame. ``reference.evaluation`` builds them.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field, fields
from fractions import Fraction
from functools import cached_property
from typing import TYPE_CHECKING, Any, overload

from reference.book import Book
from reference.catalog import Catalog
from reference.compare import Context, Verdict
from reference.errata import Error, errors
from reference.power import Outcome, PowerReport, power_report

if TYPE_CHECKING:
    import pandas as pd


@dataclass(frozen=True)
class EvaluatedClaim:
    """A claim with its evaluation: the fields of ``claims --json`` (design section 4)."""

    id: str
    chapter: str
    file: str
    line: int
    line_end: int | None
    occurrence: int | None
    quote: str
    printed: str | None
    means: str | None
    garble: str | None
    value: float | None
    model_value: float | list[float] | None
    interval: list[float] | None
    interval_note: str | None
    interval_wide: bool
    tolerance: float | None
    rounding_reason: str | None
    relation: str
    unit: str
    kind: str
    verdict: Verdict
    expect: str
    correct: str | None
    correct_agrees: bool | None
    diagnosis: dict[str, str | None] | None
    quantity: str
    model: str | None
    args: dict[str, Any]
    pick: str
    model_error: float | None
    assumptions: dict[str, Any]
    rounded_assumptions: list[str]
    precision_reason: str | None
    rel_tol: float | None
    sigfigs: int | None
    rounding: str | None
    exact: bool
    monotonic: bool | None
    restates: str | None
    figure: str | None
    equation: str | None
    note: str | None
    expression: str | None
    model_expression: str | None
    symbols: dict[str, Any] | None
    tokens: list[dict[str, Any]] | None
    edition: str | None
    matched_edition: str | None
    same_error: str | None
    summary: str | None
    error_class: str | None
    section: str | None
    catches: list[str] | None
    reads: str | None = None

    @property
    def passed(self) -> bool:
        """The claim test's condition: verdict equals expect, an erratum's model agrees with its
        ``correct``, and a dated claim matched the edition it names."""
        if self.verdict != self.expect:
            return False
        if self.expect == "dated":
            return self.matched_edition is not None and self.matched_edition == self.edition
        return self.expect != "erratum" or self.correct_agrees is True

    @property
    def failure(self) -> str | None:
        """Why the claim test fails, in words (None when it passes)."""
        if self.verdict != self.expect:
            return f"verdict {self.verdict}, expected {self.expect}"
        if self.expect == "dated" and self.matched_edition != self.edition:
            found = self.matched_edition or "no edition"
            return f"matched {found}, the catalog names {self.edition}"
        if self.expect == "erratum" and self.correct_agrees is not True:
            model = self.model_expression if self.kind == "formula" else self.model_value
            shown = f"{model:.10g}" if isinstance(model, float) else str(model)
            return f"the model gives {shown}, not the catalog's correct value {self.correct}"
        return None

    def to_json(self) -> dict[str, Any]:
        """The claim as a JSON object (missing values null, never NaN); the error class is
        ``class`` there."""
        out = {f.name: getattr(self, f.name) for f in fields(self) if f.name != "file"}
        out["class"] = out.pop("error_class")
        return out


@dataclass(frozen=True)
class Evaluation(Sequence[EvaluatedClaim]):
    """The evaluated claims of a run, in catalog order; ``contexts`` holds each judged claim's
    ``Context`` (what ``reference.power`` judges misprints in), ``centres`` the model's value
    at the centre of each box of rounded inputs, and ``misprints`` each measured claim's
    misprints as judged (design 3a)."""

    claims: tuple[EvaluatedClaim, ...]
    catalog: Catalog = field(repr=False)
    book: Book = field(repr=False)
    model_calls: int
    contexts: Mapping[str, Context] = field(default_factory=dict, repr=False)
    centres: Mapping[str, Fraction] = field(default_factory=dict, repr=False)
    misprints: Mapping[str, list[Outcome]] = field(default_factory=dict, repr=False)
    chapters: tuple[str, ...] | None = None  # the chapters evaluated, in book order; None: all

    def __len__(self) -> int:
        return len(self.claims)

    @overload
    def __getitem__(self, index: int) -> EvaluatedClaim: ...

    @overload
    def __getitem__(self, index: slice) -> tuple[EvaluatedClaim, ...]: ...

    def __getitem__(self, index: int | slice) -> EvaluatedClaim | tuple[EvaluatedClaim, ...]:
        return self.claims[index]

    def __iter__(self) -> Iterator[EvaluatedClaim]:
        return iter(self.claims)

    @cached_property
    def _index(self) -> dict[str, EvaluatedClaim]:
        """The claims by id (not ``index``: that is ``Sequence.index``)."""
        return {c.id: c for c in self.claims}

    def by_id(self) -> dict[str, EvaluatedClaim]:
        """The claims by id (a shared dict: do not modify)."""
        return self._index

    def verdict_counts(self) -> Counter[str]:
        return Counter(c.verdict for c in self.claims)

    def errors(self) -> list[Error]:
        """The errors of the book among the evaluated claims (one per error, however many
        claims print it), in book order."""
        by_id = self.catalog.by_id()
        return errors(
            ((by_id[c.id], c.chapter) for c in self.claims if c.verdict == "erratum"),
            by_id,
            self.book.lines,
            self.book.identity,
        )

    def power(self) -> PowerReport:
        """The detection power of the evaluated claims (design 3a), from the misprints judged
        during the evaluation."""
        return power_report(
            (c.id, c.chapter, c.line, c.means or c.printed or "", self.misprints[c.id])
            for c in self.claims
            if c.id in self.misprints
        )

    def to_frame(self) -> pd.DataFrame:
        """The claims as a pandas DataFrame, one row per claim (pandas is imported only here)."""
        import pandas as pd

        return pd.DataFrame([c.to_json() for c in self.claims])
