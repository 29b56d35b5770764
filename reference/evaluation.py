"""Evaluating the catalog: every claim's model value, interval, tolerance and verdict.

``evaluate()`` is the Python entry point (design section 4): it reads and validates the catalog
against the book, calls each claim's model once (cached on model and arguments), and returns an
``Evaluation`` of ``EvaluatedClaim`` dataclasses; ``.to_frame()`` gives a pandas DataFrame.
"""

from __future__ import annotations

import math
import sys
from collections import Counter
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field, fields
from decimal import Decimal
from fractions import Fraction
from functools import cached_property
from typing import TYPE_CHECKING, Any

from reference.book import Book, book_path, chapter_keys, load_book
from reference.calls import MAX_ROUNDED_INPUTS, ModelCache, ModelCallError, build_args, corners
from reference.catalog import Catalog, ChapterFile
from reference.compare import Judgement, Verdict, exact, judge_equal, judge_relation
from reference.diagnose import diagnose
from reference.models import is_monotonic, resolve
from reference.numbers import Printed, parse_number
from reference.schema import Claim
from reference.tables import constants, unit_factor
from reference.validate import checked_catalog, parsed

if TYPE_CHECKING:
    import pandas as pd

WIDE_INTERVAL = 10  # an interval wider than this many h is flagged in the report


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
    printed: str
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
    precision_reason: str | None
    rel_tol: float | None
    sigfigs: int | None
    restates: str | None
    figure: str | None
    equation: str | None
    note: str | None

    @property
    def passed(self) -> bool:
        """The claim test's condition: verdict equals expect, and an erratum's model agrees with
        its ``correct``."""
        if self.verdict != self.expect:
            return False
        return self.expect != "erratum" or self.correct_agrees is True

    def to_json(self) -> dict[str, Any]:
        """The claim as a JSON object (missing values null, never NaN)."""
        return {f.name: getattr(self, f.name) for f in fields(self) if f.name != "file"}


@dataclass(frozen=True)
class Evaluation(Sequence[EvaluatedClaim]):
    """The evaluated claims of a run, in catalog order."""

    claims: tuple[EvaluatedClaim, ...]
    catalog: Catalog = field(repr=False)
    book: Book = field(repr=False)
    model_calls: int = 0

    def __len__(self) -> int:
        return len(self.claims)

    def __getitem__(self, index):
        return self.claims[index]

    def __iter__(self) -> Iterator[EvaluatedClaim]:
        return iter(self.claims)

    @cached_property
    def index(self) -> dict[str, EvaluatedClaim]:
        """The claims by id."""
        return {c.id: c for c in self.claims}

    def by_id(self) -> dict[str, EvaluatedClaim]:
        """The claims by id (a shared dict: do not modify)."""
        return self.index

    def verdict_counts(self) -> Counter[str]:
        return Counter(c.verdict for c in self.claims)

    def to_frame(self) -> pd.DataFrame:
        """The claims as a pandas DataFrame, one row per claim (pandas is imported only here)."""
        import pandas as pd

        return pd.DataFrame([c.to_json() for c in self.claims])


def _as_json_number(value: Any) -> float | list[float] | None:
    if value is None:
        return None
    if isinstance(value, complex):
        return [float(value.real), float(value.imag)]
    f = float(value)
    return f if math.isfinite(f) else None


def _correct_string(printed: Printed, model: Fraction) -> str | None:
    """The model value written to the printed precision, as a curator would write ``correct``."""
    if printed.quantum is None:
        return None
    q = Decimal(printed.quantum.numerator) / Decimal(printed.quantum.denominator)
    exponent = q.as_tuple().exponent
    assert isinstance(exponent, int)
    rounded = round(model / printed.quantum) * printed.quantum
    return f"{Decimal(rounded.numerator) / Decimal(rounded.denominator):.{max(0, -exponent)}f}"


class _Evaluator:
    def __init__(self, catalog: Catalog) -> None:
        self.claims = catalog.by_id()
        self.files = catalog.file_of()
        self.cache = ModelCache()
        self.done: dict[str, EvaluatedClaim] = {}
        self.model_values: dict[str, tuple[Any, list[Fraction] | None, str | None]] = {}

    # -- values --------------------------------------------------------------------------
    def lookup(self, ident: str) -> tuple[Claim, Printed]:
        claim = self.claims[ident]
        return claim, parsed(claim)

    def call_model(self, claim: Claim) -> tuple[Any, list[Fraction] | None, str | None, Any]:
        """Model value (printed unit), input interval, why there is none, model error."""
        assert claim.model is not None
        args, inputs = build_args(claim.args, self.lookup)
        args.update(claim.assumptions)
        value, error = self._value_at(claim, args)
        rounded = [i for i in inputs if i.rounded]
        interval, note = None, None
        if rounded:
            if not is_monotonic(resolve(claim.model)):
                note = f"{claim.model} declares it is not monotonic: no interval"
            elif len(rounded) > MAX_ROUNDED_INPUTS:
                note = f"{len(rounded)} rounded inputs: too many corners for an interval"
            else:
                values = [self._value_at(claim, corner)[0] for corner in corners(args, rounded)]
                reals = [exact(v.real if isinstance(v, complex) else v) for v in values]
                interval = [min(reals), max(reals)]
        return value, interval, note, error

    def _value_at(self, claim: Claim, args: dict[str, Any]) -> tuple[Any, float | None]:
        """The model's picked value at ``args`` in the printed unit, and its declared error."""
        assert claim.model is not None
        raw = self.cache.picked(claim.id, claim.model, args, claim.pick)
        error = None
        if hasattr(raw, "value") and hasattr(raw, "error"):
            raw, error = raw.value, raw.error
        factor = unit_factor(claim.unit)
        return self._convert(claim, raw, factor), None if error is None else float(error) / factor

    @staticmethod
    def _convert(claim: Claim, value: Any, factor: float) -> Any:
        if isinstance(value, bool) or not isinstance(value, int | float | complex | Fraction):
            try:
                value = complex(value) if isinstance(value, complex) else float(value)
            except (TypeError, ValueError) as err:
                raise ModelCallError(
                    claim.id,
                    "pick",
                    f"the model result is a {type(value).__name__}, not a "
                    "number: pick a part of it",
                ) from err
        if isinstance(value, complex) and value.imag == 0:
            value = value.real
        if isinstance(value, float) and not math.isfinite(value):
            raise ModelCallError(claim.id, "model", f"{claim.model} returned {value}")
        if factor == 1:
            return value
        return value / factor

    # -- verdicts ------------------------------------------------------------------------
    def judge(
        self, claim: Claim, printed: Printed, model: Any, interval: list[Fraction] | None
    ) -> Judgement:
        if isinstance(model, complex):
            # A complex model value meets a real printed value: the real part is compared and
            # the imaginary part must vanish within the same tolerance.
            judgement = self._judge_real(claim, printed, exact(model.real), interval)
            if judgement.verdict != "erratum" and abs(exact(model.imag)) > printed.tolerance:
                return Judgement("erratum", None, judgement.tolerance)
            return judgement
        return self._judge_real(claim, printed, exact(model), interval)

    @staticmethod
    def _judge_real(
        claim: Claim, printed: Printed, model: Fraction, interval: list[Fraction] | None
    ) -> Judgement:
        if claim.relation == "=":
            box = (interval[0], interval[1]) if interval else None
            return judge_equal(printed, model, interval=box, exact_only=claim.kind == "count")
        bounds = None
        if claim.bounds is not None:
            bounds = (parse_number(claim.bounds[0]), parse_number(claim.bounds[1]))
        return judge_relation(claim.relation, printed, model, rel_tol=claim.rel_tol, bounds=bounds)

    def evaluate(self, ident: str) -> EvaluatedClaim:
        if ident in self.done:
            return self.done[ident]
        claim = self.claims[ident]
        f = self.files[ident]
        printed = parsed(claim)
        model_value: Any = None
        interval: list[Fraction] | None = None
        interval_note: str | None = None
        model_error: Any = None
        auto: str | None = None
        if claim.kind == "given" or (
            claim.restates and self.claims[claim.restates].kind == "given"
        ):
            judgement = Judgement("given", None, None)
        elif claim.kind == "constant" or (
            claim.restates and self.claims[claim.restates].kind == "constant"
        ):
            key = claim.constant or self.claims[claim.restates or ""].constant
            assert key is not None
            judgement, model_value, auto = self.judge_constant(claim, printed, key)
        elif claim.restates:
            source = self.evaluate(claim.restates)
            model_value, interval, interval_note = self.model_values[claim.restates]
            # a restatement may print the quantity in another physical unit (7 mile/s for
            # 11.3 km/s): convert the restated model value
            scale = unit_factor(self.claims[claim.restates].unit) / unit_factor(claim.unit)
            if scale != 1:
                model_value = model_value * scale
                interval = None if interval is None else [v * Fraction(scale) for v in interval]
            interval_note = source.interval_note
            judgement = self.judge(claim, printed, model_value, interval)
        elif claim.model is None:
            judgement = Judgement("unmodeled", None, None)
        else:
            model_value, interval, interval_note, model_error = self.call_model(claim)
            judgement = self.judge(claim, printed, model_value, interval)
            if model_error:
                err = Fraction(model_error)
                shifted = [
                    self.judge(claim, printed, exact(model_value) + s * err, interval).verdict
                    for s in (-1, 1)
                ]
                if any(v != judgement.verdict for v in shifted):
                    judgement = Judgement("indeterminate", None, judgement.tolerance)
        self.model_values[ident] = (model_value, interval, interval_note)
        self.done[ident] = result = self.record(
            f, claim, printed, judgement, model_value, interval, interval_note, model_error, auto
        )
        return result

    def judge_constant(
        self, claim: Claim, printed: Printed, key: str
    ) -> tuple[Judgement, float, str | None]:
        const = constants()[key]
        factor = unit_factor(claim.unit)
        editions = const.editions
        current = editions[0]
        extra = Fraction(2 * current.uncertainty / factor)
        value = current.value / factor
        if claim.relation != "=":
            return self._judge_real(claim, printed, exact(value), None), value, None
        # an exact whole-number datum printed whole (a date, 5,280 feet) admits no rounding
        whole = current.uncertainty == 0 and float(value).is_integer()
        exact_only = whole and printed.value.denominator == 1 and printed.quantum == 1
        judgement = judge_equal(printed, exact(value), extra=extra, exact_only=exact_only)
        auto = None
        if judgement.verdict == "erratum":
            matching = [
                old
                for old in editions[1:]
                if judge_equal(
                    printed,
                    exact(old.value / factor),
                    extra=Fraction(2 * old.uncertainty / factor),
                ).verdict
                in ("verified", "rounding")
            ]
            if matching:
                # the edition the book most likely used: the closest value among those matching
                best = min(matching, key=lambda e: abs(exact(e.value / factor) - printed.value))
                auto = f"dated: matches {best.edition} ({best.value:g} {const.unit})"
        return judgement, value, auto

    def record(
        self,
        f: ChapterFile,
        claim: Claim,
        printed: Printed,
        judgement: Judgement,
        model_value: Any,
        interval: list[Fraction] | None,
        interval_note: str | None,
        model_error: Any,
        auto: str | None,
    ) -> EvaluatedClaim:
        correct_agrees = None
        if claim.correct is not None and model_value is not None:
            correct = parse_number(claim.correct, sigfigs=claim.sigfigs)
            m = exact(model_value.real if isinstance(model_value, complex) else model_value)
            correct_agrees = abs(m - correct.value) <= correct.tolerance * (1 + Fraction(1, 10**9))
        diagnosis = None
        if judgement.verdict == "erratum" or claim.expect == "erratum":
            if auto is None and model_value is not None and not isinstance(model_value, complex):
                target = claim.correct or _correct_string(printed, exact(model_value))
                if target is not None:
                    found = diagnose(printed, parse_number(target))
                    auto = f"{found.kind}: {found.detail}" if found else None
            diagnosis = {
                "kind": claim.diagnosis.kind if claim.diagnosis else None,
                "note": claim.diagnosis.note if claim.diagnosis else None,
                "auto": auto,
            }
        tol = judgement.tolerance
        wide = bool(interval and tol and (interval[1] - interval[0]) > WIDE_INTERVAL * tol)
        return EvaluatedClaim(
            id=claim.id,
            chapter=f.meta.chapter,
            file=f.name,
            line=claim.line,
            line_end=claim.line_end,
            occurrence=claim.occurrence,
            quote=claim.quote,
            printed=claim.printed,
            means=claim.means,
            garble=claim.garble,
            value=_as_json_number(printed.value),
            model_value=_as_json_number(model_value),
            interval=[float(interval[0]), float(interval[1])] if interval else None,
            interval_note=interval_note,
            interval_wide=wide,
            tolerance=None if tol is None else float(tol),
            rounding_reason=judgement.reason,
            relation=claim.relation,
            unit=claim.unit,
            kind=claim.kind,
            verdict=judgement.verdict,
            expect=claim.expect,
            correct=claim.correct,
            correct_agrees=correct_agrees,
            diagnosis=diagnosis,
            quantity=claim.quantity,
            model=claim.model,
            args=claim.model_dump(mode="json")["args"],
            pick=claim.pick,
            model_error=None if model_error is None else float(model_error),
            assumptions=dict(claim.assumptions),
            precision_reason=claim.precision_reason,
            rel_tol=claim.rel_tol,
            sigfigs=claim.sigfigs,
            restates=claim.restates,
            figure=claim.figure,
            equation=claim.equation,
            note=claim.note,
        )


def evaluate_catalog(
    catalog: Catalog, book: Book, chapters: Sequence[str] | None = None, progress: bool = False
) -> Evaluation:
    """Evaluate the claims of ``chapters`` (default: all) of a validated ``catalog``."""
    evaluator = _Evaluator(catalog)
    wanted = set(chapters) if chapters is not None else None
    selected = [c.id for f, c in catalog.claims() if wanted is None or f.meta.chapter in wanted]
    out = []
    for i, ident in enumerate(selected, start=1):
        out.append(evaluator.evaluate(ident))
        if progress and (i % 200 == 0 or i == len(selected)):
            print(f"bangcheck: evaluated {i}/{len(selected)} claims", file=sys.stderr)
    return Evaluation(tuple(out), catalog, book, evaluator.cache.calls)


def evaluate(
    book: str | None = None, chapters: str | None = None, progress: bool = False
) -> Evaluation:
    """Evaluate the catalog against the book at ``book`` (else ``$BANGCHECK_BOOK``).

    ``chapters`` is a chapter spec ("8", "0-3", "4,5", "A1"). Raises ``BookError`` for a missing
    or wrong book, ``CatalogError`` for an invalid catalog and ``ModelCallError`` where a model
    cannot be called as catalogued.
    """
    the_book = load_book(book_path(book))
    catalog = checked_catalog(the_book)
    return evaluate_catalog(catalog, the_book, chapter_keys(chapters), progress)
