"""What the tests of ``bangcheck report --out`` (``checks/test_output_dir_*.py``) share: a
report's files, a directory's tree, the command run on the front matter, a user's directory."""

from __future__ import annotations

from pathlib import Path

import pytest

from reference.book import Book
from reports.cli import main

FILES = {"index.html": "<p>report</p>\n", "errata.csv": "id\n", "claims.json": "{}\n"}


def tree(directory: Path) -> dict[str, str]:
    """Every file under ``directory`` (relative path to text)."""
    return {
        str(p.relative_to(directory)): p.read_text(encoding="utf-8")
        for p in sorted(directory.rglob("*"))
        if p.is_file()
    }


def report(
    capsys: pytest.CaptureFixture[str], book: Book, out: Path | str, *extra: str
) -> tuple[int, str]:
    """Run ``bangcheck report`` on the front matter into ``out``: exit code, stderr. (Chapter 0
    has no figure to draw: these tests are about where the report goes, 0.2 s a run instead of
    the appendix's 0.5 s.)"""
    code = main(["report", "--book", str(book.path), "--chapter", "0", "--out", str(out), *extra])
    return code, capsys.readouterr().err


def a_user_directory(root: Path) -> dict[str, str]:
    """A directory of the user's: a thesis and a sub-directory with notes."""
    (root / "sub").mkdir(parents=True)
    (root / "thesis.txt").write_text("t\n", encoding="utf-8")
    (root / "sub" / "notes.md").write_text("n\n", encoding="utf-8")
    return tree(root)
