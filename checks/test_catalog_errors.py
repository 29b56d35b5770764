"""Malformed catalog entries are rejected with one clear line each: file, claim id and field.

A small valid catalog (the 100/30/10 tower of chapter 8) is written to a temporary directory;
each test spoils it in one way and checks the one problem reported.
"""

from __future__ import annotations

import subprocess
import sys
import warnings
from pathlib import Path

import pytest

from reference.book import Book
from reference.schema import CatalogError, Problem
from reference.validate import checked_catalog
from reports.cli import main

pytestmark = pytest.mark.integrity

META = """[meta]
chapter = "8"
title = "N-body collisions"
lines = [6510, 6935]
complete = false
schema = 1
"""
GIVENS = """
[[claim]]
id = "ch08.t.drop"
line = 6526
occurrence = 1
quote = "(Vn(0)=1 for"
printed = "1"
quantity = "drop speed"
kind = "given"
unit = "scaled"
expect = "given"

[[claim]]
id = "ch08.t.m1"
line = 6558
quote = "m1=100"
printed = "100"
quantity = "bottom mass"
kind = "given"
expect = "given"

[[claim]]
id = "ch08.t.m2"
line = 6559
quote = "m2=30"
printed = "30"
quantity = "middle mass"
kind = "given"
expect = "given"

[[claim]]
id = "ch08.t.m3"
line = 6561
quote = "m3=10"
printed = "10"
quantity = "top mass"
kind = "given"
expect = "given"
"""
V3 = """
[[claim]]
id = "ch08.t.v3"
line = 6562
occurrence = 2
quote = "velocity V3=3.62."
printed = "3.62"
quantity = "top ball velocity"
kind = "derived"
model = "towers.independent_tower"
pick = "velocities[2]"
expect = "verified"

[claim.args]
masses = [{ claim = "ch08.t.m1" }, { claim = "ch08.t.m2" }, { claim = "ch08.t.m3" }]
v_drop = { claim = "ch08.t.drop" }
"""


def problems_of(tmp_path: Path, book: Book, text: str) -> list[Problem]:
    (tmp_path / "ch08.toml").write_text(text, encoding="utf-8")
    try:
        checked_catalog(book, tmp_path)
    except CatalogError as err:
        return err.problems
    return []


def one_problem(tmp_path: Path, book: Book, text: str) -> Problem:
    found = problems_of(tmp_path, book, text)
    assert len(found) == 1, "\n".join(map(str, found))
    assert found[0].file == str(tmp_path / "ch08.toml")  # the draft's own path
    return found[0]


def test_the_base_catalog_is_valid(tmp_path: Path, book: Book) -> None:
    assert problems_of(tmp_path, book, META + GIVENS + V3) == []


@pytest.mark.parametrize(
    ("old", "new", "ident", "field"),
    [
        ('quantity = "top ball velocity"\n', "", "ch08.t.v3", "quantity"),
        ('quote = "velocity V3=3.62."', 'quote = "velocity V3=3.26."', "ch08.t.v3", "quote"),
        ('model = "towers.independent_tower"', 'model = "towers.tall_tower"', "ch08.t.v3", "model"),
        ('model = "towers.independent_tower"', 'model = "rockets.tower"', "ch08.t.v3", "model"),
        ('pick = "velocities[2]"', 'pick = "velocities[2]"\nqoute = "x"', "ch08.t.v3", "qoute"),
        ('id = "ch08.t.v3"', 'id = "ch09.t.v3"', "ch09.t.v3", "id"),
        ("line = 6562", "line = 7000", "ch08.t.v3", "line"),
        ('printed = "3.62"', 'printed = "3.6"', "ch08.t.v3", "printed"),
        ("occurrence = 2\n", "", "ch08.t.v3", "occurrence"),
        ("occurrence = 2", "occurrence = 3", "ch08.t.v3", "occurrence"),
        (
            '{ claim = "ch08.t.m3" }',
            '{ claim = "ch08.t.m3" }, { claim = "ch08.t.m4" }',
            "ch08.t.v3",
            "args",
        ),
        ("v_drop =", "drop_speed =", "ch08.t.v3", "args"),
        ('expect = "verified"', 'expect = "unmodeled"', "ch08.t.v3", "expect"),
        (
            'expect = "verified"',
            'expect = "erratum"\ncorrect = "3.62"\nsummary = "s"',
            "ch08.t.v3",
            "diagnosis",
        ),
        (
            'expect = "verified"',
            'expect = "erratum"\ncorrect = "3.62"\ndiagnosis = { kind = "other", note = "n" }',
            "ch08.t.v3",
            "summary",
        ),
        ('pick = "velocities[2]"', 'pick = "velocities[two]"', "ch08.t.v3", "pick"),
        ('expect = "verified"', 'expect = "verified"\nunit = "furlong"', "ch08.t.v3", "unit"),
        (
            'expect = "verified"',
            'expect = "verified"\nrelation = "~"\nrel_tol = 0.01',
            "ch08.t.v3",
            "precision_reason",
        ),
        (
            'expect = "verified"',
            'expect = "verified"\nsigfigs = 2\nprecision_reason = "x"',
            "ch08.t.v3",
            "sigfigs",
        ),
        (
            'expect = "verified"',
            'expect = "verified"\nmeans = "3.62"\nnote = "n"',
            "ch08.t.v3",
            "garble",
        ),
        (
            'kind = "derived"',
            'kind = "constant"\nconstant = "standard-gravity"',
            "ch08.t.v3",
            "model",
        ),
    ],
)
def test_one_spoilt_field_gives_one_line(
    tmp_path: Path, book: Book, old: str, new: str, ident: str, field: str
) -> None:
    text = META + GIVENS + V3
    assert old in text
    found = one_problem(tmp_path, book, text.replace(old, new, 1))
    assert (found.id, found.field) == (ident, field)
    line = str(found)
    assert line.startswith(f"{tmp_path / 'ch08.toml'}: {ident}: field '{field}': ")


def test_an_unreferenced_given_is_an_error(tmp_path: Path, book: Book) -> None:
    found = problems_of(tmp_path, book, META + GIVENS)
    assert [(p.id, p.field) for p in found] == [
        (f"ch08.t.{name}", "kind") for name in ("drop", "m1", "m2", "m3")
    ]


ERRATUM = 'expect = "erratum"\ncorrect = "3.62"\ndiagnosis = { kind = "other", note = "n" }\n'


@pytest.mark.parametrize(
    ("extra", "field"),
    [
        ('summary = "s"\nsame_error = "ch08.t.m1"', "summary"),
        ('same_error = "ch08.t.nope"', "same_error"),
        ('same_error = "ch08.t.m1"', "same_error"),
        ('summary = "s"\nedition = "CODATA 1973"', "edition"),
        ('summary = "s"\nreads = "velocity V3=3.62."', "reads"),  # the quote as it stands
    ],
)
def test_error_fields(tmp_path: Path, book: Book, extra: str, field: str) -> None:
    """summary on the first claim only; same_error names another erratum; edition only on a
    dated claim; reads differs from the quote."""
    text = (META + GIVENS + V3).replace('expect = "verified"', ERRATUM + extra)
    found = problems_of(tmp_path, book, text)
    assert ("ch08.t.v3", field) in [(p.id, p.field) for p in found], found


def test_a_dated_claim_names_an_edition_of_its_constant(tmp_path: Path, book: Book) -> None:
    dated = """
[[claim]]
id = "ch08.t.g"
line = 6558
quote = "m1=100"
printed = "100"
quantity = "a constant"
kind = "constant"
unit = "1"
constant = "gravitational-constant"
expect = "dated"
"""
    found = problems_of(tmp_path, book, META + GIVENS + V3 + dated)
    assert [(p.id, p.field) for p in found] == [("ch08.t.g", "edition")]
    named = dated + 'edition = "CODATA 1900"\n'
    found = problems_of(tmp_path, book, META + GIVENS + V3 + named)
    assert [(p.id, p.field, "no older edition" in p.message) for p in found] == [
        ("ch08.t.g", "edition", True)
    ]


def test_an_erratum_needs_the_printed_precision(tmp_path: Path, book: Book) -> None:
    text = (META + GIVENS + V3).replace(
        'expect = "verified"',
        'expect = "erratum"\ncorrect = "3.61538"\nsummary = "s"\n'
        'diagnosis = { kind = "arithmetic", note = "test" }',
    )
    found = one_problem(tmp_path, book, text)
    assert (found.id, found.field) == ("ch08.t.v3", "correct")


def test_a_complete_chapter_has_no_unmodeled_claim(tmp_path: Path, book: Book) -> None:
    text = (META + GIVENS + V3).replace("complete = false", "complete = true")
    text = text.replace('model = "towers.independent_tower"\n', "")
    text = text.replace('pick = "velocities[2]"\n', "")
    text = text[: text.index("[claim.args]")]
    found = problems_of(tmp_path, book, text)
    assert ("ch08.t.v3", "model") in {(p.id, p.field) for p in found}


def test_circular_references(tmp_path: Path, book: Book) -> None:
    loop = V3.replace('id = "ch08.t.v3"', 'id = "ch08.t.a"').replace(
        'v_drop = { claim = "ch08.t.drop" }', 'v_drop = { claim = "ch08.t.b" }'
    )
    loop += (
        V3.replace('id = "ch08.t.v3"', 'id = "ch08.t.b"')
        .replace('v_drop = { claim = "ch08.t.drop" }', 'v_drop = { claim = "ch08.t.a" }')
        .replace('quote = "velocity V3=3.62."', 'quote = "(V2=0.54,V3=3.62)"')
        .replace("occurrence = 2", "occurrence = 1")
    )
    found = problems_of(tmp_path, book, META + GIVENS + loop)
    assert any("circular" in p.message for p in found), found


def test_a_restatement_of_an_unknown_claim(tmp_path: Path, book: Book) -> None:
    restated = """
[[claim]]
id = "ch08.t.v3-intro"
line = 6527
quote = "V3=3.62 is had"
printed = "3.62"
quantity = "top ball velocity"
kind = "derived"
restates = "ch08.t.v9"
expect = "verified"
"""
    found = one_problem(tmp_path, book, META + GIVENS + V3 + restated)
    assert (found.id, found.field) == ("ch08.t.v3-intro", "restates")


def test_duplicate_ids(tmp_path: Path, book: Book) -> None:
    found = problems_of(tmp_path, book, META + GIVENS + V3 + V3)
    assert [(p.id, p.field) for p in found] == [("ch08.t.v3", "id")]
    assert (
        found[0].message
        == f"duplicate id (also the claim of book line 6562 in {tmp_path / 'ch08.toml'})"
    )


def test_the_packaged_catalog_is_named_by_its_place_in_the_project(book: Book) -> None:
    from reference.catalog import default_directory, display_name

    path = default_directory().joinpath("ch08.toml")
    assert display_name(path, packaged=True) == "reference/claims/ch08.toml"


@pytest.mark.parametrize("name", ["ch4.toml", "ch08-old.toml"])
def test_a_file_no_chapter_is_named_by_is_one_problem(
    tmp_path: Path, book: Book, name: str
) -> None:
    """A typo in a draft's file name, or a backup copy beside the file, is the one problem
    of that file: not one 'must start with' or 'duplicate id' per entry."""
    (tmp_path / "ch08.toml").write_text(META + GIVENS + V3, encoding="utf-8")
    (tmp_path / name).write_text(META + GIVENS + V3, encoding="utf-8")
    with pytest.raises(CatalogError) as error:
        checked_catalog(book, tmp_path)
    assert [str(p) for p in error.value.problems] == [
        f"{tmp_path / name}: not a chapter's file name (they are ch00.toml ... chA1.toml): "
        "rename it, or move it out of the catalog directory"
    ]


def test_bad_toml_names_the_file(tmp_path: Path, book: Book) -> None:
    found = one_problem(tmp_path, book, META + "[[claim]\nid = ")
    assert "not valid TOML" in found.message
    # a problem of the whole file names no claim or field: no "-: field '-':" filler
    assert str(found).startswith(f"{found.file}: not valid TOML: ")


def test_meta_must_match_the_book(tmp_path: Path, book: Book) -> None:
    text = (META + GIVENS + V3).replace("lines = [6510, 6935]", "lines = [6510, 6900]")
    found = one_problem(tmp_path, book, text)
    assert (found.id, found.field) == ("meta", "lines")


@pytest.mark.parametrize(
    ("entry", "field"),
    [
        ('[[excluded]]\nline = 6562\ntoken = "30/10"\nreason = "because"\n', "reason"),
        ('[[excluded]]\nline = 6562\ntoken = "31/10"\nreason = "notation"\n', "token"),
        ('[[excluded]]\nline = 6562\ntoken = "3"\nreason = "notation"\n', "token"),
        ('[[excluded]]\nlines = [6600, 6500]\nreason = "symbolic-matrix"\n', "lines"),
        ('[[excluded]]\nline = 6562\ntoken = "30/10"\nreason = "restates ch08.nope"\n', "reason"),
    ],
)
def test_bad_hand_exclusions(tmp_path: Path, book: Book, entry: str, field: str) -> None:
    found = one_problem(tmp_path, book, META + GIVENS + V3 + "\n" + entry)
    assert found.field == field


def test_cli_rejects_a_malformed_catalog_with_one_line_per_problem(
    tmp_path: Path, book: Book, capsys: pytest.CaptureFixture[str]
) -> None:
    text = (META + GIVENS + V3).replace('quantity = "top ball velocity"\n', "")
    text = text.replace('quote = "m1=100"', 'quote = "m1=1000"')
    (tmp_path / "ch08.toml").write_text(text, encoding="utf-8")
    code = main(["claims", "--book", str(book.path), "--catalog", str(tmp_path)])
    err = capsys.readouterr().err.splitlines()
    where = tmp_path / "ch08.toml"
    assert code == 2
    assert err[0] == "bangcheck: the catalog is invalid (2 problem(s)):"
    assert err[1].startswith(f"{where}: ch08.t.m1: field 'quote': is not on line 6558")
    assert err[2:] == [f"{where}: ch08.t.v3: field 'quantity': required field is missing"]


ROOT = Path(__file__).parents[1]


def run_pytest(
    capsys: pytest.CaptureFixture[str], args: list[str], in_process: bool
) -> tuple[int, str]:
    """pytest run from the project root on ``args``: the exit code and everything it printed.
    In this process (as pytest's own ``pytester`` runs it: the modules are imported already)
    or, for a run with xdist workers, as a command."""
    if in_process:
        # warnings raised inside the inner run belong to it, not to this test (pytest-benchmark,
        # where it is installed, warns there that xdist is active)
        with pytest.MonkeyPatch.context() as patch, warnings.catch_warnings(record=True):
            patch.chdir(ROOT)
            code = pytest.main(args)
        out, err = capsys.readouterr()
        return int(code), out + err
    done = subprocess.run(
        [sys.executable, "-m", "pytest", *args],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=False,
    )
    return done.returncode, done.stdout + done.stderr


@pytest.mark.parametrize("workers", [[], ["-n", "2"]], ids=["serial", "xdist"])
def test_pytest_stops_on_a_malformed_catalog_with_one_line_per_problem(
    tmp_path: Path, book: Book, workers: list[str], capsys: pytest.CaptureFixture[str]
) -> None:
    """``pytest --book=... --catalog=DIR`` with a duplicate id: the usage error that lists the
    problems, one line each, exit 4, nothing run and no traceback, serial and under xdist."""
    draft = tmp_path / "draft"
    draft.mkdir()
    (draft / "ch08.toml").write_text(META + GIVENS + V3 + V3, encoding="utf-8")
    args = [f"--book={book.path}", f"--catalog={draft}", "-p", "no:cacheprovider", "-q"]
    code, output = run_pytest(capsys, [*args, *workers, "checks/test_book.py"], not workers)
    assert code == pytest.ExitCode.USAGE_ERROR, output
    lines = [line for line in output.splitlines() if line.strip()]
    start = lines.index("ERROR: the catalog is invalid:")
    where = draft / "ch08.toml"
    assert lines[start + 1 :] == [
        f"{where}: ch08.t.v3: field 'id': duplicate id "
        f"(also the claim of book line 6562 in {where})"
    ]
    assert "Traceback" not in output
    assert "KeyError" not in output
    assert "passed" not in output


def test_pytest_refuses_a_catalog_directory_without_catalog_files(
    tmp_path: Path, book: Book, capsys: pytest.CaptureFixture[str]
) -> None:
    """As the command does (``checks/test_cli.py`` tries the other wrong directories). The book
    is given as an option: under ``CI=true`` a run without one stops on that first."""
    args = [
        f"--book={book.path}",
        f"--catalog={tmp_path}",
        "-p",
        "no:cacheprovider",
        "-q",
        "checks/test_book.py",
    ]
    code, output = run_pytest(capsys, args, in_process=True)
    assert code == pytest.ExitCode.USAGE_ERROR, output
    assert "holds no catalog files" in output
    assert "Traceback" not in output
