"""Evaluating the catalog: every claim's model value, interval, tolerance and verdict.

``evaluate()`` is the Python entry point (design section 4): it reads and validates the catalog
against the book, calls each claim's model once (cached on model and arguments), and returns an
``Evaluation`` of ``EvaluatedClaim`` dataclasses (``reference.evaluated``); ``.to_frame()`` gives a
pandas DataFrame. Here are the judging and the assembling: which inputs are exact (design 3a),
each claim's judging context (a model value, a constant, a restated claim's value converted),
formula claims (design 2a), the verdict, and the ``EvaluatedClaim`` with its diagnosis, section
and error class; ``reference.modelling`` calls the models.
"""

from __future__ import annotations

import dataclasses
import math
import sys
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction

from reference.book import Book, book_path, chapter_keys, load_book
from reference.calls import ModelCache, ModelCallError
from reference.catalog import Catalog
from reference.compare import Context, Edition, Judgement, Verdict, exact, inside, judge
from reference.diagnose import diagnose
from reference.errata import errors
from reference.evaluated import EvaluatedClaim, Evaluation
from reference.formulas import FormulaError, compare, generic_points, make_symbol, parse_formula
from reference.modelling import ModelCalls, Modelled, ModelValue, real_part
from reference.numbers import EXACT_ULPS, Printed, parse_number, significant_digits
from reference.power import Outcome, catches, judge_misprints, measured
from reference.schema import Assumption, Claim
from reference.tables import constants, unit_factor
from reference.validate import checked_catalog, claim_refs, parsed

__all__ = [
    "WIDE_INTERVAL",
    "EvaluatedClaim",
    "Evaluation",
    "FormulaResult",
    "evaluate",
    "evaluate_catalog",
]

WIDE_INTERVAL = 10  # an interval wider than this many h is flagged in the report


def _as_json_number(value: ModelValue | None) -> float | list[float] | None:
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


@dataclass(frozen=True)
class FormulaResult:
    """A formula claim's verdict, the model's formula as text (None where the model is
    numeric), and whether the catalog's ``correct`` formula agrees with the model."""

    judgement: Judgement
    model_expression: str | None
    correct_agrees: bool | None


class _Evaluator:
    def __init__(self, catalog: Catalog) -> None:
        self.claims = catalog.by_id()
        self.files = catalog.file_of()
        self.cache = ModelCache()
        self.models = ModelCalls(self.cache, self.lookup, self.is_rounded_input)
        self.done: dict[str, EvaluatedClaim] = {}
        self.modelled: dict[str, Modelled] = {}
        self.contexts: dict[str, Context] = {}
        self.exact_inputs: dict[str, bool] = {}

    # -- inputs --------------------------------------------------------------------------
    def lookup(self, ident: str) -> tuple[Claim, Printed]:
        claim = self.claims[ident]
        return claim, parsed(claim)

    def root(self, claim: Claim) -> Claim:
        """The claim a restatement restates (itself if it restates none)."""
        while claim.restates is not None:
            claim = self.claims[claim.restates]
        return claim

    def is_rounded_input(self, ident: str) -> bool:
        """Whether a referenced claim's printed value is a rounded input (design 3a)."""
        return not self.is_exact_input(ident)

    def is_exact_input(self, ident: str) -> bool:
        """A given is exact unless ``rounded = true``; a constant is exact as printed; another
        claim is exact when ``exact = true``, or when its model value equals its stated value,
        with no input interval, no declared error, and only exact inputs of its own."""
        if ident not in self.exact_inputs:
            claim = self.claims[ident]
            root = self.root(claim)
            if root.kind == "given":
                exact_input = not (claim.rounded or root.rounded)
            elif root.kind == "constant" or claim.exact:
                exact_input = True
            else:
                self.evaluate(ident)
                exact_input = self._equals_its_model(claim) and all(
                    self.is_exact_input(ref) for ref in self._arg_refs(root)
                )
                exact_input = exact_input and not any(
                    isinstance(a, Assumption) and a.rounded for a in root.assumptions.values()
                )
            self.exact_inputs[ident] = exact_input
        return self.exact_inputs[ident]

    @staticmethod
    def _arg_refs(claim: Claim) -> list[str]:
        return [ref for value in claim.args.values() for ref in claim_refs(value)]

    def _equals_its_model(self, claim: Claim) -> bool:
        modelled = self.modelled.get(claim.id)
        if modelled is None or modelled.value is None:
            return False
        if modelled.interval is not None or modelled.error:
            return False
        value = modelled.value
        if isinstance(value, complex):  # never with a zero imaginary part: made real when read
            return False
        stated = parsed(claim).value
        if isinstance(value, int | Fraction):
            return Fraction(value) == stated
        return abs(exact(value) - stated) <= Fraction(EXACT_ULPS * math.ulp(float(value) or 1e-300))

    # -- contexts --------------------------------------------------------------------------
    @staticmethod
    def context(claim: Claim, modelled: Modelled, scale: Fraction = Fraction(1)) -> Context:
        """The claim's judging context from what the model said (``scale`` converts a restated
        claim's value to this claim's unit)."""
        value = modelled.value
        assert value is not None  # a claim the model (or the claim it restates) gave a value
        imag = Fraction(0)
        if isinstance(value, complex):
            imag = exact(value.imag) * scale
            value = value.real
        interval = modelled.interval
        if interval is not None:
            low, high = sorted((interval[0] * scale, interval[1] * scale))
            interval = (low, high)
        bounds = None
        if claim.bounds is not None:
            bounds = (parse_number(claim.bounds[0]), parse_number(claim.bounds[1]))
        return Context(
            model=exact(value) * scale,
            relation=claim.relation,
            imag=imag,
            interval=interval,
            error=None if modelled.error is None else modelled.error * abs(scale),
            exact_only=claim.kind == "count",
            truncation=claim.rounding == "truncation",
            rel_tol=None if claim.rel_tol is None else Fraction(claim.rel_tol),
            bounds=bounds,
        )

    def constant_context(self, claim: Claim, printed: Printed, key: str) -> Context:
        """A constant claim's context: today's value within h plus twice its uncertainty; an
        exact whole-number datum printed whole (a date, 5,280 feet) admits no rounding."""
        const = constants()[key]
        factor = unit_factor(claim.unit)
        value = exact(const.value / factor)
        whole = const.uncertainty == 0 and value.denominator == 1
        editions = tuple(
            Edition(old.edition, exact(old.value / factor), exact(2 * old.uncertainty / factor))
            for old in const.older
        )
        return Context(
            model=value,
            relation=claim.relation,
            extra=exact(2 * const.uncertainty / factor),
            exact_only=whole and printed.value.denominator == 1 and printed.quantum == 1,
            truncation=claim.rounding == "truncation",
            rel_tol=None if claim.rel_tol is None else Fraction(claim.rel_tol),
            editions=editions,
        )

    # -- formula claims --------------------------------------------------------------------
    def judge_formula(self, claim: Claim) -> FormulaResult:
        """A formula claim: the book's expression against the model's formula, symbolically or
        at generic points (design 2a); ``correct`` is checked against the model the same way."""
        assert claim.expression is not None
        assert claim.model is not None
        symbols = {
            name: make_symbol(name, spec.model_dump(exclude_none=True))
            for name, spec in claim.symbols.items()
        }
        domains = {name: spec.domain for name, spec in claim.symbols.items() if spec.domain}
        points = generic_points(symbols, domains)
        try:
            book = parse_formula(claim.expression, symbols)
            model, shown = self.models.formula_model(claim, symbols)
            comparison = compare(book, model, points)
            agrees = None
            if claim.correct is not None:
                agrees = compare(parse_formula(claim.correct, symbols), model, points).agrees
        except FormulaError as err:
            raise ModelCallError(claim.id, "expression", str(err)) from err
        verdict: Verdict = "verified" if comparison.agrees else "erratum"
        return FormulaResult(Judgement(verdict, None, None), shown, agrees)

    # -- verdicts ------------------------------------------------------------------------
    def evaluate(self, ident: str) -> EvaluatedClaim:
        if ident in self.done:
            return self.done[ident]
        claim = self.claims[ident]
        root = self.root(claim)
        printed = parsed(claim) if claim.kind != "formula" else None
        modelled = Modelled()
        auto: str | None = None
        ctx: Context | None = None
        formula: FormulaResult | None = None
        if printed is None:  # a formula claim
            formula = self.judge_formula(claim)
            judgement = formula.judgement
        elif root.kind == "given":
            judgement = Judgement("given", None, None)
        elif root.kind == "constant":
            assert root.constant is not None
            ctx = self.constant_context(claim, printed, root.constant)
            modelled = Modelled(float(ctx.model))
            judgement = judge(printed, ctx)
            if judgement.verdict == "dated":
                auto = f"dated: matches {judgement.edition}"
        elif claim.restates:
            self.evaluate(claim.restates)
            source = self.modelled[claim.restates]
            # a restatement may print the quantity in another physical unit (7 mile/s for
            # 11.3 km/s): convert the restated model value
            scale = exact(unit_factor(self.claims[claim.restates].unit) / unit_factor(claim.unit))
            if source.value is None:
                judgement = Judgement("unmodeled", None, None)
            else:
                ctx = self.context(claim, source, scale)
                value = source.value * float(scale) if scale != 1 else source.value
                centre = None if source.centre is None else source.centre * scale
                modelled = Modelled(value, ctx.interval, source.interval_note, ctx.error, centre)
                judgement = judge(printed, ctx)
        elif claim.model is None:
            judgement = Judgement("unmodeled", None, None)
        else:
            modelled = self.models.call_model(claim)
            ctx = self.context(claim, modelled)
            judgement = judge(printed, ctx)
        self.modelled[ident] = modelled
        if ctx is not None:
            self.contexts[ident] = ctx
        self.done[ident] = result = self.record(claim, printed, judgement, modelled, auto, formula)
        return result

    def record(
        self,
        claim: Claim,
        printed: Printed | None,
        judgement: Judgement,
        modelled: Modelled,
        auto: str | None,
        formula: FormulaResult | None = None,
    ) -> EvaluatedClaim:
        model_value = modelled.value
        interval = modelled.interval
        correct_agrees = None
        if formula is not None:
            correct_agrees = formula.correct_agrees
        elif claim.correct is not None and model_value is not None:
            correct = parse_number(claim.correct, sigfigs=claim.sigfigs)
            tolerance = correct.tolerance
            if printed is not None and _finer(claim.correct, correct, printed):
                # more decimals and more figures than printed: the exact value (design 2a)
                tolerance = Fraction(EXACT_ULPS * math.ulp(float(correct.value) or 1e-300))
            correct_agrees = inside(abs(real_part(model_value) - correct.value), tolerance)
        diagnosis = None
        if judgement.verdict in ("erratum", "dated") or claim.expect in ("erratum", "dated"):
            if (
                auto is None
                and printed is not None
                and model_value is not None
                and not isinstance(model_value, complex)
            ):
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
        f = self.files[claim.id]
        dumped = claim.model_dump(mode="json")
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
            value=None if printed is None else float(printed.value),
            model_value=_as_json_number(model_value),
            interval=[float(interval[0]), float(interval[1])] if interval else None,
            interval_note=modelled.interval_note,
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
            args=dumped["args"],
            pick=claim.pick,
            model_error=None if modelled.error is None else float(modelled.error),
            assumptions={
                k: v["value"] if isinstance(v, dict) else v
                for k, v in dumped["assumptions"].items()
            },
            rounded_assumptions=sorted(
                k for k, v in claim.assumptions.items() if isinstance(v, Assumption) and v.rounded
            ),
            precision_reason=claim.precision_reason,
            rel_tol=claim.rel_tol,
            sigfigs=claim.sigfigs,
            rounding=claim.rounding,
            exact=claim.exact,
            monotonic=claim.monotonic,
            restates=claim.restates,
            figure=claim.figure,
            equation=claim.equation,
            note=claim.note,
            expression=claim.expression,
            model_expression=None if formula is None else formula.model_expression,
            symbols=dumped["symbols"] or None,
            tokens=dumped["tokens"] or None,
            edition=claim.edition,
            matched_edition=judgement.edition,
            same_error=claim.same_error,
            summary=claim.summary,
            error_class=None,
            section=None,
            catches=None,
            reads=claim.reads,
        )


def _finer(text: str, correct: Printed, printed: Printed) -> bool:
    """Whether a ``correct`` value has more decimals and more significant figures than the
    printed one: then it is written exact, not rounded."""
    if correct.quantum is None or printed.quantum is None:
        return False
    figures = len(significant_digits(text)) > len(significant_digits(printed.text))
    return correct.quantum < printed.quantum and figures


def _located(claims: list[EvaluatedClaim], catalog: Catalog, book: Book) -> list[EvaluatedClaim]:
    """The claims with their section, and the errata with the class of their error."""
    by_id = catalog.by_id()
    found = errors(
        ((by_id[c.id], c.chapter) for c in claims if c.verdict == "erratum"),
        by_id,
        book.lines,
        book.identity,
    )
    classes = {claim.id: e.error_class for e in found for claim in e.claims}
    out = []
    for c in claims:
        section = book.identity.section_of(c.line)
        out.append(
            dataclasses.replace(
                c,
                section=section.heading if section is not None else None,
                error_class=classes.get(c.id),
            )
        )
    return out


def evaluate_catalog(
    catalog: Catalog, book: Book, chapters: Sequence[str] | None = None, progress: bool = False
) -> Evaluation:
    """Evaluate the claims of ``chapters`` (default: all) of a validated ``catalog``."""
    evaluator = _Evaluator(catalog)
    wanted = set(chapters) if chapters is not None else None
    selected = [c.id for f, c in catalog.claims() if wanted is None or f.meta.chapter in wanted]
    out = []
    outcomes: dict[str, list[Outcome]] = {}
    for i, ident in enumerate(selected, start=1):
        evaluated = evaluator.evaluate(ident)
        claim = evaluator.claims[ident]
        ctx = evaluator.contexts.get(ident)
        if ctx is not None and measured(claim):
            outcomes[ident] = judge_misprints(claim, ctx)
            evaluated = dataclasses.replace(evaluated, catches=catches(outcomes[ident]))
        out.append(evaluated)
        if progress and (i % 200 == 0 or i == len(selected)):
            print(f"bangcheck: evaluated {i}/{len(selected)} claims", file=sys.stderr)
    centres = {ident: m.centre for ident, m in evaluator.modelled.items() if m.centre is not None}
    out = _located(out, catalog, book)
    return Evaluation(
        tuple(out),
        catalog,
        book,
        evaluator.cache.calls,
        dict(evaluator.contexts),
        centres,
        outcomes,
        _selection(book, catalog, wanted),
    )


def _selection(book: Book, catalog: Catalog, wanted: set[str] | None) -> tuple[str, ...] | None:
    """The chapters a run evaluated, in book order: those asked for that the catalog holds (a
    draft may hold some only); None when that is every chapter of the book."""
    keys = [c.key for c in book.identity.chapters]
    chosen = [k for k in keys if k in catalog.chapters and (wanted is None or k in wanted)]
    return None if chosen == keys else tuple(chosen)


def evaluate(
    book: str | None = None,
    chapters: str | int | Iterable[str | int] | None = None,
    progress: bool = False,
) -> Evaluation:
    """Evaluate the catalog against the book at ``book`` (else ``$BANGCHECK_BOOK``).

    ``chapters`` is a chapter spec ("8", "0-3", "4,5", "A1") or several (["0", "4", "7"]), or
    chapter numbers (8, [0, 4, 7]); None for the whole book. Raises ``BookError`` for a missing or
    wrong book, ``CatalogError`` for an invalid catalog and ``ModelCallError`` where a model
    cannot be called as catalogued.
    """
    the_book = load_book(book_path(book, given_as="evaluate(book=PATH)"))
    catalog = checked_catalog(the_book)
    return evaluate_catalog(catalog, the_book, chapter_keys(chapters), progress)
