"""The catalog's rules for each entry on its own: a claim's fields, its model and its quote.

``ClaimRules`` checks each catalog file's header against book.toml, each claim's fields
(values, kind, relation, a formula's expression, the error fields, a ``correct`` value written
to the printed precision, design 2a), that its model resolves and takes its arguments, and,
with the book, that its quote and printed token stand on its line; also each hand exclusion
and slip. ``parsed`` gives the value a claim states. ``reference.validate`` adds the rules
across claims (references, cycles, errors) and runs them all.
"""

from __future__ import annotations

import re
from fractions import Fraction

from reference.book import Book, identity
from reference.catalog import Catalog, ChapterFile
from reference.formulas import CONSTANTS, FUNCTIONS, FormulaError, make_symbol, parse_formula
from reference.locate import find, line_tokens, matches, pick_occurrence
from reference.models import check_signature, pick_steps, resolve
from reference.numbers import NumberFormatError, Printed, parse_number, significant_digits
from reference.schema import HAND_REASONS, Assumption, Claim, Excluded, Problem, Slip
from reference.tables import NO_CONVERSION, constants, units
from reference.tokens import normalize

HEDGES = (
    "about", "~", "nearly", "some", "roughly", "approximately", "almost", "around", "≈",
    "order", "over", "under", "less than", "more than", "or so", "estimate",
)  # fmt: skip


def occurrences(text: str, quote: str) -> int:
    """How many times ``quote`` occurs in ``text``, overlapping matches included ("1 1" occurs
    twice in "1 1 1")."""
    count, pos = 0, text.find(quote)
    while pos != -1:
        count += 1
        pos = text.find(quote, pos + 1)
    return count


def parsed(claim: Claim) -> Printed:
    """The value a claim states: ``means`` where given, else ``printed``, with its sigfigs; a
    historical date (a constant with ``date = true``) at the precision of its last non-zero
    digit (design 2a: "1700" is good to 50 years, "1620" to 5)."""
    text = claim.means or claim.printed
    if text is None:
        raise NumberFormatError(f"{claim.id} states no number (no printed or means)")
    sigfigs = claim.sigfigs
    if sigfigs is None and claim.constant is not None and _is_date(claim.constant):
        digits = significant_digits(text).rstrip("0")
        sigfigs = max(len(digits), 1)
    return parse_number(text, sigfigs=sigfigs, exact=claim.exact)


def short_exact(text: str, stated: Printed) -> bool:
    """Whether a ``correct`` value is exact and short (design 2a): a terminating decimal with
    at most two more decimals than printed ("-0.25" for a printed "-0.5"), or a p/q, root or
    pi form of at most 8 characters."""
    try:
        correct = parse_number(text)
    except NumberFormatError:
        return False
    if correct.exact:
        return len(text.strip()) <= 8
    if stated.quantum is None or correct.quantum is None:
        return False
    return correct.quantum >= stated.quantum / 100


def _editions(key: str) -> set[str]:
    entry = constants().get(key)
    return {e.edition for e in entry.older} if entry is not None else set()


def _is_date(key: str) -> bool:
    entry = constants().get(key)
    return entry is not None and entry.date


def superscript_ok(printed: str, means: str) -> bool:
    """Whether some split of the printed digits into base and exponent gives ``means``.

    "1040" can be 10^40, "602" 60^2, "6·1024" 6·10^24, "10-25" 10^-25: the mantissa before a
    multiplication dot is kept, the rest is split at every place.
    """
    target = parse_number(means).value
    s = normalize(printed).strip()
    if scale := re.search(r" ?E([-+]?\d+)$", s):  # "6.282 E6": a power of ten after the split
        target /= Fraction(10) ** int(scale[1])
        s = s[: scale.start()]
    sign = -1 if s.startswith("-") else 1
    s = s.lstrip("-+")
    mantissa = Fraction(1)
    for dot in "·⋅":
        if dot in s:
            head, _, s = s.partition(dot)
            mantissa = parse_number(head).value
    for i in range(1, len(s)):
        base, exp = s[:i], s[i:]
        readable = re.fullmatch(r"\d+(?:\.\d+)?", base) and re.fullmatch(r"-?\d+", exp)
        if readable and sign * mantissa * Fraction(base) ** int(exp) == target:
            return True
    return False


class ClaimRules:
    """The rules for each catalog entry on its own; ``problems`` collects what they find."""

    def __init__(self, catalog: Catalog, book: Book | None) -> None:
        self.catalog = catalog
        self.book = book
        self.problems: list[Problem] = []
        self.ids: dict[str, str] = {}

    def add(self, f: ChapterFile, ident: str, field: str, message: str) -> None:
        self.problems.append(Problem(f.name, ident, field, message))

    # -- files -------------------------------------------------------------------------
    def check_file(self, f: ChapterFile) -> bool:
        """The file's name and ``[meta]``; False for a file no chapter is named by (a typo, a
        backup copy), whose entries are then not checked: the name is the one problem."""
        ident = identity()
        keys = {c.file_stem: c for c in ident.chapters}
        chapter = keys.get(f.stem)
        if chapter is None:
            names = f"{ident.chapters[0].file_stem}.toml ... {ident.chapters[-1].file_stem}.toml"
            self.add(
                f,
                "-",
                "-",
                f"not a chapter's file name (they are {names}): rename it, or move it out of "
                "the catalog directory",
            )
            return False
        if f.meta.chapter != chapter.key:
            self.add(
                f, "meta", "chapter", f"is {f.meta.chapter!r}, the file is chapter {chapter.key!r}"
            )
        if f.meta.lines != [chapter.start, chapter.end]:
            self.add(
                f,
                "meta",
                "lines",
                f"is {f.meta.lines}, the chapter is [{chapter.start}, {chapter.end}] (book.toml)",
            )
        return True

    # -- claims ------------------------------------------------------------------------
    def check_claim(self, f: ChapterFile, c: Claim) -> None:
        add = lambda field, msg: self.add(f, c.id, field, msg)  # noqa: E731
        if not c.id.startswith(f.stem + "."):
            add("id", f"must start with {f.stem}. (its file)")
        if c.id in self.ids:
            add("id", f"duplicate id (also {self.ids[c.id]})")
        self.ids.setdefault(c.id, f"the claim of book line {c.line} in {f.name}")
        lo, hi = f.meta.lines
        if not lo <= c.line <= hi:
            add("line", f"{c.line} is outside the chapter's lines [{lo}, {hi}]")
        if c.line_end is not None and not c.line < c.line_end <= hi:
            add("line_end", f"{c.line_end} must be after line {c.line} and inside the chapter")
        if c.kind == "formula":
            self.check_formula(f, c)
        else:
            self.check_values(f, c)
        self.check_kind(f, c)
        self.check_model(f, c)
        self.check_relation(f, c)
        self.check_error_fields(f, c)
        if self.book is not None and lo <= c.line <= hi:
            self.check_text(f, c)

    def check_formula(self, f: ChapterFile, c: Claim) -> None:
        """A formula claim (design 2a): a readable expression over declared symbols, a model
        for the correct formula, a readable ``correct``, the tokens it covers."""
        add = lambda field, msg: self.add(f, c.id, field, msg)  # noqa: E731
        symbols = {}
        for name, spec in c.symbols.items():
            if not name.isidentifier() or name in CONSTANTS or name in FUNCTIONS:
                add(f"symbols.{name}", "a symbol is a plain name, not a constant or a function")
            if spec.domain is not None and not spec.domain[0] < spec.domain[1]:
                add(f"symbols.{name}.domain", f"{spec.domain} is not an interval lo < hi")
            symbols[name] = make_symbol(name, spec.model_dump(exclude_none=True))
        if c.expression is None:
            add("expression", "a formula claim states the book's formula in 'expression'")
        else:
            try:
                parse_formula(c.expression, symbols)
            except FormulaError as err:
                add("expression", str(err))
        if c.model is None:
            add("model", "a formula claim needs the model of the correct formula")
        if c.correct is not None:
            try:
                parse_formula(c.correct, symbols)
            except FormulaError as err:
                add("correct", str(err))
        for field in ("means", "garble", "sigfigs", "rounding", "constant"):
            if getattr(c, field) not in (None, False):
                add(field, "does not apply to a formula claim")
        if c.unit != "1" or c.relation != "=":
            add("unit" if c.unit != "1" else "relation", "a formula has no unit and relation =")
        if c.printed is not None and not c.tokens:
            add("tokens", "list the tokens the formula covers (printed alone is not enough)")
        if c.expect not in ("verified", "erratum"):
            add("expect", "a formula is verified or an erratum")

    def check_error_fields(self, f: ChapterFile, c: Claim) -> None:
        """``same_error``, ``summary``, ``reads``, ``edition``, ``tokens`` and a missing
        ``printed``."""
        add = lambda field, msg: self.add(f, c.id, field, msg)  # noqa: E731
        if c.tokens and c.kind != "formula":
            add("tokens", "only a formula claim lists the tokens it covers")
        if c.printed is None and c.kind != "formula" and (c.expect != "erratum" or not c.means):
            add(
                "printed",
                "required, except for a formula or an erratum with no token (then 'means' "
                "gives the value the text states)",
            )
        if c.same_error is not None:
            if c.expect != "erratum":
                add("same_error", "only an erratum is part of an error")
            if c.summary is not None:
                add("summary", "the error's first claim carries the summary, not this one")
        elif c.expect == "erratum" and c.summary is None and not self.restates_erratum(c):
            add("summary", "the first claim of an error needs a one-sentence summary")
        if c.summary is not None and c.expect != "erratum":
            add("summary", "only an erratum carries a summary")
        if c.reads is not None and (c.expect != "erratum" or c.reads == c.quote):
            add("reads", "an erratum's quote as it should read: differs from the quote")
        if c.expect == "dated":
            if c.edition is None:
                add("edition", "a dated claim names the edition it matches")
            elif c.kind != "constant" and not c.restates:
                add("expect", "only a claim judged through a constant can be dated")
            elif c.constant is not None and c.edition not in _editions(c.constant):
                add("edition", f"{c.edition!r} is no older edition of {c.constant!r}")
        elif c.edition is not None:
            add("edition", "only a dated claim names an edition")

    def restates_erratum(self, c: Claim) -> bool:
        restated = self.catalog.by_id().get(c.restates or "")
        return restated is not None and restated.expect == "erratum"

    def check_values(self, f: ChapterFile, c: Claim) -> None:
        add = lambda field, msg: self.add(f, c.id, field, msg)  # noqa: E731
        if c.printed is not None:
            try:
                parse_number(c.printed)
            except NumberFormatError as err:
                if c.means is None:
                    add("printed", f"{err}; a garbled number needs 'means' and 'garble'")
        if (c.means is None) != (c.garble is None) and c.printed is not None:
            add("garble" if c.means else "means", "'means' and 'garble' go together")
        if c.printed is None and c.garble is not None:
            add("garble", "an error with no number token has nothing garbled: 'means' alone")
        if c.means is not None:
            if c.note is None:
                add("note", "a 'means' needs a note citing the evidence")
            try:
                parse_number(c.means)
            except NumberFormatError as err:
                add("means", str(err))
            else:
                if (
                    c.garble == "superscript"
                    and c.printed is not None
                    and not superscript_ok(c.printed, c.means)
                ):
                    add(
                        "means",
                        f"no split of {c.printed!r} into base and exponent gives {c.means!r}",
                    )
        if c.sigfigs is not None:
            if c.precision_reason is None:
                add("precision_reason", "reduced 'sigfigs' needs a precision_reason")
            if not any(h in c.quote.lower() for h in HEDGES):
                add("sigfigs", f"the quote has no word that hedges precision {HEDGES}")
            try:
                parsed(c)
            except NumberFormatError as err:
                add("sigfigs", str(err))
        if c.unit not in NO_CONVERSION and c.unit not in units():
            add("unit", f"unknown unit {c.unit!r} (see reference/units.toml)")
        mark = (c.printed or "").strip()[-1:]
        if mark == "%" and c.unit != "percent":
            add("unit", 'a printed percent needs unit = "percent"')
        if mark == "°" and c.unit != "deg":
            add("unit", 'a printed degree mark needs unit = "deg"')
        if c.assumptions and c.precision_reason is None:
            add("precision_reason", "assumptions need a precision_reason")
        for name, assumed in c.assumptions.items():
            if isinstance(assumed, Assumption) and isinstance(assumed.value, str):
                try:
                    parse_number(assumed.value)
                except NumberFormatError as err:
                    add(f"assumptions.{name}.value", str(err))
        if c.rounding is not None and c.precision_reason is None:
            add("precision_reason", "a declared truncation cites the text's evidence")
        if c.exact:
            if c.precision_reason is None:
                add("precision_reason", "exact = true says why the integer is an exact amount")
            if c.kind == "given":
                add("exact", "a given is exact as printed already (rounded = true says not)")
            try:
                parsed(c)
            except NumberFormatError as err:
                add("exact", str(err))

    def check_kind(self, f: ChapterFile, c: Claim) -> None:
        add = lambda field, msg: self.add(f, c.id, field, msg)  # noqa: E731
        if (c.kind == "given") != (c.expect == "given"):
            add("expect", 'a given (and only a given) expects "given"')
        if c.kind in ("given", "constant") and (c.model or c.args or c.pick):
            add("model", f"a {c.kind} claim has no model, args or pick")
        if c.rounded and c.kind != "given":
            add("rounded", "only a given may be marked rounded")
        if c.kind == "constant":
            if c.constant is None:
                add("constant", "a constant claim names its entry of constants.toml")
            elif c.constant not in constants():
                add("constant", f"no entry {c.constant!r} in reference/constants.toml")
        elif c.constant is not None:
            add("constant", "only a constant claim names a constants.toml entry")
        if c.expect == "erratum":
            if c.correct is None:
                add("correct", "an erratum needs the correct value")
            if c.diagnosis is None:
                add("diagnosis", "an erratum needs a diagnosis { kind, note }")
            if c.correct is not None:
                self.check_correct(f, c)
        elif c.expect == "dated":  # today's value and a diagnosis are allowed
            if c.correct is not None:
                self.check_correct(f, c)
        else:
            if c.correct is not None:
                add("correct", "only an erratum or a dated value has a correct value")
            if c.diagnosis is not None:
                add("diagnosis", "only an erratum or a dated value has a diagnosis")
        if c.restates is not None and (c.model or c.args):
            add("restates", "a restatement is not modelled again: no model or args")
        if c.monotonic is not None and c.model is None:
            add("monotonic", "monotonic speaks of a model: the claim has none")

    def check_correct(self, f: ChapterFile, c: Claim) -> None:
        assert c.correct is not None
        if c.kind == "formula":
            return  # read by check_formula
        if c.constant is not None and _is_date(c.constant):
            try:
                parse_number(c.correct)
            except NumberFormatError as err:
                self.add(f, c.id, "correct", str(err))
            return  # a date's correction is the year its source gives
        try:
            correct = parse_number(c.correct, sigfigs=c.sigfigs)
            stated = parsed(c)
        except NumberFormatError as err:
            self.add(f, c.id, "correct", str(err))
            return
        same_decimals = correct.quantum == stated.quantum
        same_figures = len(significant_digits(c.correct)) == len(
            significant_digits(c.means or c.printed or "")
        )
        if not stated.exact and not (
            same_decimals or same_figures or short_exact(c.correct, stated)
        ):
            self.add(
                f,
                c.id,
                "correct",
                "write it to the printed number of decimals or of significant figures, or exact "
                "where short (two more decimals at most, or a p/q, root or pi form of 8 "
                "characters at most)",
            )

    def check_model(self, f: ChapterFile, c: Claim) -> None:
        add = lambda field, msg: self.add(f, c.id, field, msg)  # noqa: E731
        if c.model is None:
            if c.args or c.pick:
                add("model", "args or pick without a model")
            return
        try:
            func = resolve(c.model)
        except LookupError as err:
            add("model", f"{c.model!r} does not resolve: {err}")
            return
        why = check_signature(func, [*c.args, *c.assumptions])
        if why:
            add("args", f"cannot call {c.model}: {why}")
        try:
            pick_steps(c.pick)
        except ValueError as err:
            add("pick", str(err))

    def check_relation(self, f: ChapterFile, c: Claim) -> None:
        add = lambda field, msg: self.add(f, c.id, field, msg)  # noqa: E731
        if c.relation == "~":
            if c.rel_tol is None:
                add("rel_tol", "relation '~' needs rel_tol")
            if c.precision_reason is None:
                add("precision_reason", "relation '~' needs a precision_reason")
        elif c.rel_tol is not None:
            add("rel_tol", "rel_tol goes only with relation '~'")
        if c.relation == "between":
            if c.bounds is None:
                add("bounds", "relation 'between' needs bounds = [lo, hi]")
            else:
                try:
                    lo, hi = (parse_number(b).value for b in c.bounds)
                except NumberFormatError as err:
                    add("bounds", str(err))
                else:
                    if lo > hi:
                        add("bounds", "lower bound above upper bound")
        elif c.bounds is not None:
            add("bounds", "bounds go only with relation 'between'")
        if c.kind == "given" and c.relation != "=":
            add("relation", "a given states its value: relation '='")

    def check_text(self, f: ChapterFile, c: Claim) -> None:
        assert self.book is not None
        add = lambda field, msg: self.add(f, c.id, field, msg)  # noqa: E731
        text = self.book.line(c.line)
        count = occurrences(text, c.quote)
        if count != 1:
            where = "is not on" if count == 0 else f"occurs {count} times on"
            add("quote", f"{where} line {c.line}: {text.strip()[:80]!r}")
            return
        lo, hi = f.meta.lines
        for i, tok in enumerate(c.tokens):
            if not lo <= tok.line <= hi:
                add(f"tokens[{i}]", f"line {tok.line} is outside the chapter")
                continue
            match, why = find(self.book, tok.line, tok.token, tok.occurrence)
            if match is None:
                add(f"tokens[{i}]", f"{tok.token!r} on line {tok.line} {why}")
        if c.printed is None:
            return
        q_start = text.index(c.quote)
        q_end = q_start + len(c.quote)
        found = matches(text, line_tokens(self.book, c.line), c.printed)
        match, why = pick_occurrence(found, c.occurrence)
        field = "occurrence" if found else "printed"
        if match is None:
            tokens = [t.text for t in line_tokens(self.book, c.line)]
            add(field, f"{c.printed!r} {why}; tokens of line {c.line}: {tokens}")
            return
        if c.occurrence is not None and len(found) == 1:
            add("occurrence", "only one such token on the line: drop 'occurrence'")
        if not (q_start <= match.start and match.end <= q_end):
            add("quote", f"does not cover {c.printed!r} at occurrence {c.occurrence or 1}")

    # -- exclusions and slips ------------------------------------------------------------
    def check_excluded(self, f: ChapterFile, e: Excluded) -> None:
        ident = f"excluded (line {e.line or e.lines})"
        add = lambda field, msg: self.add(f, ident, field, msg)  # noqa: E731
        lo, hi = f.meta.lines
        word = e.reason.split(":")[0].split()[0] if e.reason.strip() else ""
        if word not in HAND_REASONS:
            add("reason", f"must start with one of {HAND_REASONS}")
        if word in ("restates", "part-of"):
            target = e.reason.split(maxsplit=1)[1:] or [""]
            if target[0] not in self.catalog.by_id() and target[0] not in self.catalog.rejected:
                add("reason", f"{word} an unknown claim {target[0]!r}")
        elif e.unit is not None or e.means is not None:
            add("unit" if e.unit is not None else "means", "only restates and part-of take it")
        if e.unit is not None and e.unit not in NO_CONVERSION and e.unit not in units():
            add("unit", f"unknown unit {e.unit!r} (see reference/units.toml)")
        if e.means is not None:
            try:
                parse_number(e.means)
            except NumberFormatError as err:
                add("means", str(err))
        if word == "not-a-claim" and not e.reason.partition(":")[2].strip():
            add("reason", "not-a-claim needs its words: 'not-a-claim: why'")
        if e.lines is not None:
            if e.line is not None or e.token is not None or e.occurrence is not None:
                add("lines", "a range exclusion has only lines and reason")
            a, b = e.lines
            if not lo <= a <= b <= hi:
                add("lines", f"{e.lines} must be an ordered range inside [{lo}, {hi}]")
            return
        if e.line is None or e.token is None:
            add("line" if e.line is None else "token", "a token exclusion needs line and token")
            return
        if not lo <= e.line <= hi:
            add("line", f"{e.line} is outside the chapter's lines [{lo}, {hi}]")
            return
        if self.book is not None:
            match, why = find(self.book, e.line, e.token, e.occurrence)
            if match is None:
                add("token", f"{e.token!r} {why}")

    def check_slip(self, f: ChapterFile, s: Slip) -> None:
        lo, hi = f.meta.lines
        if not s.id.startswith(f.stem + "."):
            self.add(f, s.id, "id", f"must start with {f.stem}.")
        if s.id in self.ids:
            self.add(f, s.id, "id", f"duplicate id (also {self.ids[s.id]})")
        self.ids.setdefault(s.id, f"the slip of book line {s.line} in {f.name}")
        if not lo <= s.line <= hi:
            self.add(f, s.id, "line", f"{s.line} is outside [{lo}, {hi}]")
        elif self.book is not None and occurrences(self.book.line(s.line), s.quote) != 1:
            self.add(f, s.id, "quote", f"must occur exactly once on line {s.line}")
