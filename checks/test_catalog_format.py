"""``bangcheck fmt``: the catalog's canonical form (docs/catalog.md, "Layout")."""

from __future__ import annotations

import json
import re
import stat
from pathlib import Path

import pytest

from reference.book import Book
from reference.catalog_format import CLAIM_KEYS, format_text
from reports.cli import main

pytestmark = pytest.mark.integrity
CLAIMS = Path(__file__).parents[1] / "reference" / "claims"

SCRAMBLED = """# Catalog of chapter 8 (a test copy)
[meta]
schema = 1
chapter = "8"
title = "t"
lines = [6400, 6900]
complete = false

# --- a section comment, kept with the section it opens

[[claim]]
expect = "given"
kind = "given"
unit = "1"
quantity = "q"
# a comment inside an entry stays with it
printed = "100"
quote = "m1 = 100"
line = 6500
id = "ch08.t.a"
relation = "="
"""


def test_keys_are_ordered_defaults_dropped_and_comments_kept() -> None:
    out = format_text(SCRAMBLED)
    claim = out.split("[[claim]]")[1]
    keys = [line.split(" = ")[0] for line in claim.splitlines() if " = " in line]
    assert keys == sorted(keys, key=CLAIM_KEYS.index)
    assert 'unit = "1"' not in out  # the schema's defaults
    assert 'relation = "="' not in out
    assert "# a comment inside an entry stays with it" in claim
    assert "# --- a section comment, kept with the section it opens\n\n[[claim]]" in out
    assert out.startswith("# Catalog of chapter 8 (a test copy)\n[meta]\nchapter = ")


def test_formatting_a_draft_reaches_a_fixed_point(tmp_path: Path) -> None:
    """Formatting is idempotent: a draft out of canonical order changes once, then no more (the
    packaged files, canonical already, are their own fixed point: the test below)."""
    draft = _draft(tmp_path).read_text(encoding="utf-8")
    once = format_text(draft)
    assert once != draft
    assert format_text(once) == once


def test_the_packaged_catalog_is_in_canonical_form(
    book: Book, capsys: pytest.CaptureFixture[str]
) -> None:
    code = main(["fmt", "--check", "--book", str(book.path)])
    out = capsys.readouterr()[0]
    assert code == 0, f"run `bangcheck fmt`:\n{out[:3000]}"
    assert out == ""


def _draft(tmp_path: Path) -> Path:
    """Chapter 8 with its first claim's id written after its line."""
    text = (CLAIMS / "ch08.toml").read_text(encoding="utf-8")
    draft = re.sub(r"\[\[claim\]\]\n(id = .*\n)(line = .*\n)", r"[[claim]]\n\2\1", text, count=1)
    assert draft != text
    (tmp_path / "ch08.toml").write_text(draft, encoding="utf-8")
    return tmp_path / "ch08.toml"


def test_check_shows_a_diff_exits_one_and_writes_nothing(
    book: Book, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    draft = _draft(tmp_path)
    before = draft.read_bytes()
    code = main(["fmt", "--check", "--book", str(book.path), "--catalog", str(tmp_path)])
    out, err = capsys.readouterr()
    assert code == 1
    assert f"--- {draft}" in out
    assert re.search(r"\n[-+](id|line) = ", out)
    assert "1 catalog file(s) not in canonical form" in err
    assert draft.read_bytes() == before


def test_fmt_rewrites_in_place_and_the_verdicts_do_not_change(
    book: Book, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    draft = _draft(tmp_path)
    draft.chmod(0o640)
    claims = ["claims", "--json", "--book", str(book.path), "--catalog", str(tmp_path)]
    assert main(claims) == 0
    before = [json.loads(line) for line in capsys.readouterr()[0].splitlines()]
    assert main(["fmt", "--book", str(book.path), "--catalog", str(tmp_path)]) == 0
    assert "formatted" in capsys.readouterr()[1]
    assert "[[claim]]\nid = " in draft.read_text(encoding="utf-8")
    assert stat.S_IMODE(draft.stat().st_mode) == 0o640  # the file's mode is kept
    assert sorted(p.name for p in tmp_path.iterdir()) == ["ch08.toml"]  # no temporary left
    assert main(claims) == 0
    assert [json.loads(line) for line in capsys.readouterr()[0].splitlines()] == before
    # a second run, or a check, finds nothing to do and says so (not a silent wait)
    check = ["fmt", "--check", "--book", str(book.path), "--catalog", str(tmp_path)]
    assert main(check) == 0
    assert capsys.readouterr() == ("", "bangcheck: 1 catalog file(s) already in canonical form\n")


def test_an_invalid_catalog_is_not_formatted(
    book: Book, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    draft = _draft(tmp_path)
    broken = draft.read_text(encoding="utf-8").replace('kind = "derived"', 'kind = "derivd"', 1)
    assert broken != draft.read_text(encoding="utf-8")
    draft.write_text(broken, encoding="utf-8")
    code = main(["fmt", "--book", str(book.path), "--catalog", str(tmp_path)])
    err = capsys.readouterr()[1]
    assert code == 2
    assert "ch08.toml: ch08." in err
    assert "'kind'" in err
    assert draft.read_text(encoding="utf-8") == broken
