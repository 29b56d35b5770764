"""The ``bangcheck`` command: outputs, streams and exit codes (design section 4)."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from collections.abc import Callable
from pathlib import Path

import pytest

from reference.book import Book, chapter_keys
from reference.evaluation import Evaluation, evaluate_catalog
from reference.validate import checked_catalog
from reports.cli import main
from reports.errata_sheet import errata_markdown

pytestmark = pytest.mark.integrity


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


CLAIMS = Path(__file__).parents[1] / "reference" / "claims"


def draft_of(tmp_path: Path, *names: str) -> Path:
    """A ``--catalog`` draft directory holding copies of the packaged chapter files ``names``."""
    draft = tmp_path / "draft"
    draft.mkdir()
    for name in names:
        shutil.copy(CLAIMS / name, draft)
    return draft


def test_claims_json_lists_every_claim(book: Book, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, "claims", "--json", "--chapter", "8-9", "--book", str(book.path))
    rows = [json.loads(line) for line in out.splitlines()]
    assert code == 0
    assert {r["id"] for r in rows} >= {"ch08.tower-100-30-10.v3", "ch09.tunnel-time"}
    assert all(r["verdict"] == r["expect"] for r in rows if r["verdict"] != "unmodeled")
    assert "claims:" in err  # the summary goes to stderr, data to stdout


def test_claims_verdict_filter_and_chapter(book: Book, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(
        capsys,
        "claims",
        "--json",
        "--verdict",
        "erratum",
        "--chapter",
        "8",
        "--book",
        str(book.path),
    )
    rows = {r["id"]: r for r in map(json.loads, out.splitlines())}
    assert code == 0
    assert {r["verdict"] for r in rows.values()} == {"erratum"}
    assert {r["chapter"] for r in rows.values()} == {"8"}
    assert rows["ch08.tower-100-30-10.v1"]["diagnosis"]["auto"].startswith("decimal-shift")


def test_claims_exit_one_when_a_verdict_differs(
    book: Book, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    source = CLAIMS / "ch08.toml"
    text = source.read_text(encoding="utf-8")
    wrong = text.replace(
        'pick = "velocities[2]"\nexpect = "verified"', 'pick = "velocities[1]"\nexpect = "verified"'
    )
    assert wrong != text
    (tmp_path / "ch08.toml").write_text(wrong, encoding="utf-8")
    code, _, err = run(
        capsys, "claims", "--book", str(book.path), "--catalog", str(tmp_path), "--chapter", "8"
    )
    assert code == 1
    assert "ch08.tower-100-30-10.v3" in err


def test_scan_counts_and_exit_code(book: Book, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "scan", "--json", "--chapter", "8", "--book", str(book.path))
    data = json.loads(out)
    counts = data["chapters"]["8"]
    assert counts["tokens"] == len(data["tokens"])
    parts = ("catalogued", "excluded_rule", "excluded_hand", "missing")
    assert counts["tokens"] == sum(counts[k] for k in parts)
    assert code == (1 if counts["missing"] else 0)
    v3 = [t for t in data["tokens"] if t["by"] == "ch08.tower-100-30-10.v3"]
    assert [(t["line"], t["text"], t["status"]) for t in v3] == [(6562, "3.62", "catalogued")]


def test_scan_text_ends_with_the_totals(book: Book, capsys: pytest.CaptureFixture[str]) -> None:
    _, out, _ = run(capsys, "scan", "--chapter", "8", "--missing", "--book", str(book.path))
    assert out.rstrip().splitlines()[-1].startswith("total: ")
    assert "missing tokens:" in out


def test_a_wrong_book_exits_two_with_one_line(
    book: Book, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    wrong = tmp_path / "book.txt"
    wrong.write_text("not the book", encoding="utf-8")
    code, out, err = run(capsys, "claims", "--book", str(wrong))
    assert (code, out) == (2, "")
    assert err.count("\n") == 1
    assert "not the book the catalog cites" in err


def test_no_book_exits_two(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.delenv("BANGCHECK_BOOK", raising=False)
    code, _, err = run(capsys, "scan")
    assert code == 2
    assert "--book PATH or set BANGCHECK_BOOK" in err


def test_bad_chapter_spec_is_a_usage_error(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exit_info:
        main(["claims", "--chapter", "13"])
    assert exit_info.value.code == 2
    assert "unknown chapter" in capsys.readouterr().err


def test_the_console_command_is_installed(book: Book) -> None:
    command = shutil.which("bangcheck")
    assert command, "the console command bangcheck is not on PATH: pip install -e '.[test]'"
    done = subprocess.run(
        [command, "claims", "--chapter", "A1", "--book", str(book.path)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    assert "chA1.products.dot-polar" in done.stdout


def test_report_exits_one_and_marks_claims_that_differ_from_expect(
    book: Book, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A claim whose verdict is not its ``expect`` (a catalog or model bug) fails ``report`` as
    it fails ``claims``; the report is still written, and says so on the page."""
    source = CLAIMS / "ch00.toml"
    text = source.read_text(encoding="utf-8")
    draft = text.replace(
        'constant = "principia-later-editions-century"\nexpect = "verified"',
        'constant = "principia-later-editions-century"\nexpect = "rounding"',
    )
    assert draft != text
    (tmp_path / "draft").mkdir()
    (tmp_path / "draft" / "ch00.toml").write_text(draft, encoding="utf-8")
    out = tmp_path / "out"
    code, _, err = run(
        capsys,
        "report",
        "--book",
        str(book.path),
        "--catalog",
        str(tmp_path / "draft"),
        "--out",
        str(out),
    )
    assert code == 1
    assert (
        "1 claim(s) differ from the catalog:\n"
        "  ch00.principia-century (line 75): verdict verified, expected rounding\n" in err
    )
    html = (out / "index.html").read_text(encoding="utf-8")
    assert 'id="failing"' in html
    assert re.search(
        r'<tr class="claim differs" data-verdict="verified" data-search="[^"]*" '
        r'id="claim-ch00.principia-century">',
        html,
    )
    code, _, _ = run(
        capsys, "report", "--book", str(book.path), "--chapter", "0", "--out", str(out)
    )
    assert code == 0
    assert 'id="failing"' not in (out / "index.html").read_text(encoding="utf-8")


@pytest.mark.parametrize(
    ("make", "message"),
    [
        (lambda d: d, "holds no catalog files"),
        (lambda d: d / "absent", "not a directory"),
        (lambda d: d.parent / "ch08.toml", "not a directory"),
    ],
    ids=["empty", "missing", "a-file"],
)
def test_a_catalog_directory_without_catalog_files_is_a_usage_error(
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    make: Callable[[Path], Path],
    message: str,
) -> None:
    (tmp_path / "empty").mkdir()
    (tmp_path / "ch08.toml").write_text("", encoding="utf-8")
    with pytest.raises(SystemExit) as exit_info:
        main(["claims", "--catalog", str(make(tmp_path / "empty"))])
    assert exit_info.value.code == 2
    assert message in capsys.readouterr().err


def test_a_catalog_directory_one_level_up_gets_a_hint(capsys: pytest.CaptureFixture[str]) -> None:
    reference = Path(__file__).parents[1] / "reference"
    with pytest.raises(SystemExit):
        main(["scan", "--catalog", str(reference)])
    assert f"did you mean {reference / 'claims'}?" in capsys.readouterr().err


def test_an_erratum_whose_model_misses_its_correct_value_says_so(
    book: Book, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The verdict is the expected erratum, but the model disagrees with the catalog's
    ``correct``: ``claims`` exits 1 and names that cause, not a verdict mismatch."""
    text = (CLAIMS / "ch08.toml").read_text("utf-8")
    draft = text.replace('correct = "0.077"', 'correct = "0.09"', 1)
    assert draft != text
    (tmp_path / "draft").mkdir()
    (tmp_path / "draft" / "ch08.toml").write_text(draft, encoding="utf-8")
    code, _, err = run(
        capsys, "claims", "--catalog", str(tmp_path / "draft"), "--book", str(book.path)
    )
    assert code == 1
    assert re.search(
        r"1 claim\(s\) differ from the catalog:\n  ch08\.[\w.-]+ \(line \d+\): the model "
        r"gives 0\.0769\d+, not the catalog's correct value 0\.09\n",
        err,
    )
    # the errata sheet, what a publisher reads, does not print the correction as confirmed
    evaluation = evaluate_catalog(checked_catalog(book, tmp_path / "draft"), book, ("8",))
    sheet = errata_markdown(evaluation)
    assert re.search(r"\n  NOT CONFIRMED: ch08\.[\w.-]+: the model gives 0\.0769", sheet)


def test_a_draft_of_some_chapters_says_which_and_refuses_the_others(
    book: Book, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A ``--catalog`` directory of one chapter's file is a draft of that chapter: the whole
    run says so on stderr; asking for a chapter it has no file for is an error (exit 2), not
    a report of no claims."""
    draft = draft_of(tmp_path, "ch08.toml")
    code, _, err = run(capsys, "claims", "--catalog", str(draft), "--book", str(book.path))
    assert code == 0
    assert f"the catalog directory {draft} holds chapter 8 only" in err
    assert "bangcheck: 120 claims" in err
    code, _, err = run(
        capsys, "claims", "--catalog", str(draft), "--chapter", "7,8", "--book", str(book.path)
    )
    assert code == 2
    assert (
        f"error: the catalog directory {draft} has no file for chapter 7 (it holds chapter 8)"
        in err
    )
    code, _, err = run(
        capsys, "claims", "--catalog", str(draft), "--chapter", "8", "--book", str(book.path)
    )
    assert code == 0
    assert "holds chapter" not in err


def test_a_draft_is_scanned_judged_and_reported_as_the_chapters_it_holds(
    book: Book, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Without ``--chapter``, a draft of chapters 0 and A1 is what ``--chapter 0,A1`` is: its
    scan counts those chapters' tokens, ``power`` does not judge it by the whole book's
    targets, and its report says whose it is."""
    draft = draft_of(tmp_path, "ch00.toml", "chA1.toml")
    common = ["--book", str(book.path), "--catalog", str(draft)]
    code, scanned, _ = run(capsys, "scan", *common)
    assert code == 0
    assert (code, scanned) == run(capsys, "scan", *common, "--chapter", "0,A1")[:2]
    code, out, err = run(capsys, "power", *common)
    assert code == 0
    assert "(the targets are the whole book's" in out
    assert "holds chapters 0 and A1 only" in err
    assert run(capsys, "report", *common, "--out", str(tmp_path / "out"))[0] == 0
    page = (tmp_path / "out" / "index.html").read_text(encoding="utf-8")
    assert 'id="selection"><strong>Chapters 0 and A1 only</strong>' in page
    assert "<strong>Below target:</strong>" not in page
    meta = json.loads((tmp_path / "out" / "claims.json").read_text(encoding="utf-8"))["meta"]
    assert meta["chapters"] == ["0", "A1"]
    assert sorted(meta["coverage"]) == ["0", "A1"]


def test_a_draft_that_refers_to_a_chapter_it_lacks_says_which_file_to_add(
    book: Book, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    draft = draft_of(tmp_path, "ch03.toml")
    code, _, err = run(capsys, "claims", "--book", str(book.path), "--catalog", str(draft))
    assert code == 2
    assert "of ch02.toml, a file this catalog directory does not hold" in err
    assert "copy ch02.toml too" in err


def test_an_evaluation_knows_whether_it_is_of_some_chapters(
    book: Book, tmp_path: Path, evaluation: Evaluation
) -> None:
    """What a report of some chapters names (``Evaluation.chapters``): the chapters evaluated,
    those asked for that the catalog holds, in book order; None when that is every chapter,
    as for the session's evaluation of the whole catalog."""
    assert evaluation.chapters is None
    draft = draft_of(tmp_path, "ch00.toml", "chA1.toml")
    catalog = checked_catalog(book, draft)
    assert evaluate_catalog(catalog, book, chapter_keys(None)).chapters == ("0", "A1")
    assert evaluate_catalog(catalog, book, chapter_keys("A1,8")).chapters == ("A1",)


def test_the_common_options_may_come_before_the_command(
    book: Book, capsys: pytest.CaptureFixture[str]
) -> None:
    """``bangcheck --book X claims`` as ``bangcheck claims --book X``; given on both sides,
    the one after the command wins."""
    code, _, err = run(capsys, "--book", str(book.path), "--chapter", "A1", "claims")
    assert code == 0
    assert "bangcheck: 14 claims" in err
    code, _, err = run(
        capsys, "--book", "/no/such/book", "claims", "--book", str(book.path), "--chapter", "A1"
    )
    assert code == 0
    assert "bangcheck: 14 claims" in err


@pytest.mark.parametrize("spec", ["", " ", ",", "4,"])
def test_an_empty_chapter_spec_is_a_usage_error(
    spec: str, capsys: pytest.CaptureFixture[str]
) -> None:
    with pytest.raises(SystemExit) as exit_info:
        main(["claims", "--chapter", spec])
    assert exit_info.value.code == 2
    assert "chapter" in capsys.readouterr().err


@pytest.mark.parametrize(("spec", "chapter"), [("a1", "A1"), ("04", "4"), ("08-09", "9")])
def test_chapter_specs_as_people_type_them(
    book: Book, capsys: pytest.CaptureFixture[str], spec: str, chapter: str
) -> None:
    code, out, _ = run(capsys, "claims", "--json", "--chapter", spec, "--book", str(book.path))
    assert code == 0
    assert chapter in {json.loads(line)["chapter"] for line in out.splitlines()}


def test_version(capsys: pytest.CaptureFixture[str]) -> None:
    from importlib.metadata import version

    with pytest.raises(SystemExit) as exit_info:
        main(["--version"])
    assert exit_info.value.code == 0
    assert capsys.readouterr().out == f"bangcheck {version('bangcheck')}\n"


@pytest.mark.parametrize(
    ("spoil", "says"),
    [
        (lambda b: b"", "the file is empty"),
        (lambda b: b.replace(b"\n", b"\r\n"), "the book with Windows (CRLF) line ends"),
        (lambda b: b + b"\n", "newline(s) added at the end"),
        (lambda b: b.replace(b"V3=3.62", b"V3=3.65", 1), "line 6527 differs from the book's"),
        (lambda b: b.replace(b"\n", b"\n\n", 1), "it has 16,965 lines, the book 16,964"),
        (
            lambda b: b"".join(b.splitlines(keepends=True)[:16000]),
            "it has 16,000 lines, the book 16,964; they are the book's first 16,000: the rest is "
            "missing",
        ),
        (
            lambda b: b.replace(b"V3=3.62", b"V3=3.65").replace(b"m1=100", b"m1=101"),
            "lines differ from the book's: ",
        ),
    ],
    ids=["empty", "crlf", "final-newline", "one-line", "line-count", "cut", "lines"],
)
def test_a_different_book_says_how_it_differs(
    book: Book,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    spoil: Callable[[bytes], bytes],
    says: str,
) -> None:
    wrong = tmp_path / "book.txt"
    wrong.write_bytes(spoil(book.path.read_bytes()))
    code, out, err = run(capsys, "scan", "--book", str(wrong))
    assert (code, out) == (2, "")
    assert err.count("\n") == 1
    assert f"{wrong} is not the book the catalog cites: " in err
    assert says in err


def test_an_interrupt_is_one_line_and_exit_130(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    def interrupted(book: object) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr("reports.cli.load_book", interrupted)
    code, out, err = run(capsys, "scan", "--book", "book.txt")
    assert (code, out, err) == (130, "", "bangcheck: interrupted\n")
