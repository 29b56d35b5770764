"""The ``bangcheck`` command: outputs, streams and exit codes (design section 4)."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest

from reference.book import Book
from reports.cli import main

pytestmark = pytest.mark.integrity


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


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
    source = Path(__file__).parents[1] / "reference" / "claims" / "ch08.toml"
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
        [command, "claims", "--chapter", "9", "--book", str(book.path)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    assert "ch09.tunnel-time" in done.stdout
