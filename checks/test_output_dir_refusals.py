"""``bangcheck report --out``: a user's files are never lost (``reports/outdir.py``).

The report refuses a directory that is not missing, empty or a previous report (files, devices,
symlinks to a user's directory, mount points, the root included), touching nothing, and checks
again under the lock.
"""

from __future__ import annotations

import contextlib
import os
import re
import stat
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from checks._output_dir_helpers import FILES, a_user_directory, report, tree
from reference.book import Book
from reports import outdir
from reports.outdir import MANIFEST, OutputError, check_target, manifest_text, write_report_dir

pytestmark = pytest.mark.integrity


# -- refusals: nothing of the user's is touched --------------------------------------------


def test_a_users_directory_survives(
    tmp_path: Path, book: Book, capsys: pytest.CaptureFixture[str]
) -> None:
    d = tmp_path / "d"
    before = a_user_directory(d)
    code, err = report(capsys, book, d)
    assert code == 2
    assert tree(d) == before
    assert err.count("\n") == 1
    assert "holds files the report did not write (sub, thesis.txt)" in err
    assert "nothing was changed" in err
    assert sorted(os.listdir(tmp_path)) == ["d"]  # no staging or old directory beside it


def test_out_dot_does_not_wipe_the_working_directory(
    tmp_path: Path, book: Book, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    before = a_user_directory(tmp_path / "work")
    monkeypatch.chdir(tmp_path / "work")
    code, err = report(capsys, book, ".")
    assert code == 2
    assert tree(tmp_path / "work") == before
    assert "refused" in err


def test_a_refusal_names_three_entries_and_counts_the_rest(tmp_path: Path) -> None:
    for name in ("a", "b", "c", "d", "e"):
        (tmp_path / name).write_text("x", encoding="utf-8")
    with pytest.raises(OutputError, match=r"\(a, b, c and 2 more\)"):
        check_target(tmp_path)


@pytest.mark.parametrize("added", ["notes.txt", ".git"])
def test_a_previous_report_with_something_added_is_refused(tmp_path: Path, added: str) -> None:
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    (out / added).mkdir() if added == ".git" else (out / added).write_text("n", encoding="utf-8")
    before = tree(out)
    with pytest.raises(OutputError, match=rf"\({re.escape(added)}\)"):
        write_report_dir(out, FILES, log=lambda m: None)
    assert tree(out) == before


@pytest.mark.parametrize(
    ("manifest", "users_file"),
    [
        ("index.html\nthesis.txt\n", "thesis.txt"),  # no header at all
        ("# my notes\nthesis.txt\n", "thesis.txt"),  # another header
        (manifest_text(["../thesis.txt"]), None),  # ours in form, naming a path outside
    ],
    ids=["headerless", "another-header", "path-outside"],
)
def test_a_manifest_that_is_not_ours_vouches_for_nothing(
    tmp_path: Path, manifest: str, users_file: str | None
) -> None:
    out = tmp_path / "out"
    out.mkdir()
    (out / MANIFEST).write_text(manifest, encoding="utf-8")
    if users_file is not None:
        (out / users_file).write_text("t", encoding="utf-8")
    with pytest.raises(OutputError, match="did not write"):
        check_target(out)


def test_a_file_target_is_refused_and_kept(
    tmp_path: Path, book: Book, capsys: pytest.CaptureFixture[str]
) -> None:
    target = tmp_path / "thesis.txt"
    target.write_text("t\n", encoding="utf-8")
    code, err = report(capsys, book, target)
    assert code == 2
    assert target.read_text(encoding="utf-8") == "t\n"
    assert sorted(os.listdir(tmp_path)) == ["thesis.txt"]
    assert "is a file: refused, nothing was changed" in err


def test_a_device_target_is_refused_and_kept(
    book: Book, capsys: pytest.CaptureFixture[str]
) -> None:
    before = os.stat("/dev/null")
    code, err = report(capsys, book, "/dev/null")
    after = os.stat("/dev/null")
    assert code == 2
    assert "/dev/null is a character device: refused" in err
    assert stat.S_ISCHR(after.st_mode)
    assert (after.st_ino, after.st_rdev) == (before.st_ino, before.st_rdev)


def test_a_symlink_to_a_users_directory_is_refused(
    tmp_path: Path, book: Book, capsys: pytest.CaptureFixture[str]
) -> None:
    before = a_user_directory(tmp_path / "d")
    (tmp_path / "link").symlink_to(tmp_path / "d")
    with pytest.raises(OutputError, match="not a directory"):
        write_report_dir(tmp_path / "link", FILES, log=lambda m: None)  # never the link itself
    code, err = report(capsys, book, tmp_path / "link")  # the command follows it
    assert code == 2
    assert f"--out {tmp_path / 'd'} holds files the report did not write" in err
    assert tree(tmp_path / "d") == before
    assert (tmp_path / "link").is_symlink()


def test_a_symlink_to_a_previous_report_writes_the_report_there(
    tmp_path: Path, book: Book, capsys: pytest.CaptureFixture[str]
) -> None:
    write_report_dir(tmp_path / "real", FILES, log=lambda m: None)
    (tmp_path / "link").symlink_to(tmp_path / "real")
    assert report(capsys, book, tmp_path / "link")[0] == 0
    assert (tmp_path / "link").is_symlink()
    assert "<title>bangcheck" in (tmp_path / "real" / "index.html").read_text(encoding="utf-8")


def test_a_symlink_loop_is_one_line(
    tmp_path: Path, book: Book, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "loop").symlink_to(tmp_path / "loop")
    code, err = report(capsys, book, tmp_path / "loop" / "x")
    assert code == 2
    assert err.count("\n") == 1
    assert "cannot follow its links" in err


def test_an_empty_out_is_a_usage_error(book: Book, capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exit_info:
        report(capsys, book, "")
    assert exit_info.value.code == 2
    assert "argument --out: give a directory, not an empty string" in capsys.readouterr().err


def test_a_refusal_comes_before_the_work(
    tmp_path: Path, book: Book, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    def no_evaluation(*args: object, **kwargs: object) -> None:
        raise AssertionError("the catalog was evaluated before the refusal")

    monkeypatch.setattr("reports.cli.evaluate_catalog", no_evaluation)
    a_user_directory(tmp_path / "d")
    assert report(capsys, book, tmp_path / "d")[0] == 2


@pytest.mark.parametrize(
    "spoil",
    [
        lambda d: (d / "index.html").write_text("<h1>my own page</h1>\n", encoding="utf-8"),
        lambda d: (d / "claims.json").mkdir(),
        lambda d: (d / "errata.csv").symlink_to(d.parent / "elsewhere.csv"),
    ],
    ids=["a-users-index", "a-directory", "a-symlink"],
)
def test_report_like_names_are_not_enough(tmp_path: Path, spoil: Callable[[Path], object]) -> None:
    """A folder of files with the report's names is the user's unless their content is a
    report's: a GitHub Pages ``index.html``, a directory named ``claims.json``."""
    out = tmp_path / "site"
    out.mkdir()
    spoil(out)
    with pytest.raises(OutputError, match="did not write"):
        check_target(out)


def test_a_listed_name_that_is_a_directory_is_foreign(tmp_path: Path) -> None:
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    (out / "errata.csv").unlink()
    (out / "errata.csv").mkdir()
    (out / "errata.csv" / "mine.txt").write_text("m", encoding="utf-8")
    with pytest.raises(OutputError, match=r"\(errata.csv\)"):
        write_report_dir(out, FILES, log=lambda m: None)
    assert (out / "errata.csv" / "mine.txt").read_text(encoding="utf-8") == "m"


def test_a_file_saved_into_the_report_while_it_is_written_survives(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    real = outdir._write_staging

    def meanwhile(staging: Path, files: dict[str, str]) -> None:
        real(staging, files)
        (out / "notes.txt").write_text("written during the run", encoding="utf-8")

    monkeypatch.setattr(outdir, "_write_staging", meanwhile)
    with pytest.raises(OutputError, match=r"received files while the report was written"):
        write_report_dir(out, {"index.html": "new"}, log=lambda m: None)
    assert (out / "notes.txt").read_text(encoding="utf-8") == "written during the run"
    assert sorted(os.listdir(tmp_path)) == ["out"]


def test_the_check_is_made_again_under_the_lock(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Another process may write into the directory between the first check and the lock."""
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    real = outdir.locked

    @contextlib.contextmanager
    def late(directory: Path, log: object) -> Iterator[None]:
        (out / "thesis.txt").write_text("t", encoding="utf-8")
        with real(directory, lambda m: None):
            yield

    monkeypatch.setattr(outdir, "locked", late)
    written = []
    monkeypatch.setattr(outdir, "_write_staging", lambda *args: written.append(args))
    with pytest.raises(OutputError, match=r"holds files the report did not write \(thesis.txt\)"):
        write_report_dir(out, {"index.html": "new"}, log=lambda m: None)
    assert (out / "thesis.txt").exists()
    assert written == []  # refused before any file was written


def test_a_refusal_leaves_an_earlier_runs_leftovers_too(tmp_path: Path) -> None:
    """A refused target is judged before the clean-up of what a crashed run left beside it:
    "nothing was changed" holds for those leftovers as well."""
    out = tmp_path / "out"
    before = a_user_directory(out)
    (tmp_path / ".out.new-abc").mkdir()  # an empty staging directory, a crash's
    with pytest.raises(OutputError, match="nothing was changed"):
        write_report_dir(out, FILES, log=lambda m: None)
    assert sorted(os.listdir(tmp_path)) == [".out.new-abc", "out"]
    assert tree(out) == before


def test_the_root_is_refused() -> None:
    with pytest.raises(OutputError, match="root directory"):
        check_target(Path("/"))


def test_names_that_would_break_a_message_are_quoted(tmp_path: Path) -> None:
    (tmp_path / "evil\nbangcheck: wrote fine").write_text("x", encoding="utf-8")
    with pytest.raises(OutputError) as raised:
        check_target(tmp_path)
    assert "\n" not in str(raised.value)
    assert "'evil\\nbangcheck: wrote fine'" in str(raised.value)


def test_a_read_only_report_is_refused_before_the_work(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    monkeypatch.setattr(outdir.os, "access", lambda path, mode: Path(path) != out)
    with pytest.raises(OutputError, match="is not writable, so the previous report cannot"):
        check_target(out)


def test_a_mount_point_is_refused(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(outdir.os.path, "ismount", lambda path: Path(path) == tmp_path)
    with pytest.raises(OutputError, match="is a mount point"):
        check_target(tmp_path)
