"""``bangcheck report --out``: a user's files are never lost (``reports/outdir.py``).

The report writes a directory only when it is missing, empty or a previous report; it refuses
anything else, files and devices included, touching nothing; two runs at once take turns under
a lock and leave no debris; a run that died is cleaned up after; an unwritable place is one line
and exit 2, with the previous report intact.
"""

from __future__ import annotations

import contextlib
import errno
import multiprocessing
import os
import re
import stat
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from reference.book import Book
from reports import outdir
from reports.cli import main
from reports.outdir import (
    MANIFEST,
    OutputError,
    check_target,
    manifest_text,
    recover,
    write_report_dir,
)

pytestmark = pytest.mark.integrity

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
    """Run ``bangcheck report`` on the appendix (six claims) into ``out``: exit code, stderr."""
    code = main(["report", "--book", str(book.path), "--chapter", "A1", "--out", str(out), *extra])
    return code, capsys.readouterr().err


def a_user_directory(root: Path) -> dict[str, str]:
    """A directory of the user's: a thesis and a sub-directory with notes."""
    (root / "sub").mkdir(parents=True)
    (root / "thesis.txt").write_text("t\n", encoding="utf-8")
    (root / "sub" / "notes.md").write_text("n\n", encoding="utf-8")
    return tree(root)


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


def test_a_manifest_that_is_not_ours_vouches_for_nothing(tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    (out / MANIFEST).write_text("index.html\nthesis.txt\n", encoding="utf-8")
    (out / "thesis.txt").write_text("t", encoding="utf-8")
    with pytest.raises(OutputError, match="did not write"):
        check_target(out)


def test_a_manifest_naming_a_path_outside_is_not_ours(tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    (out / MANIFEST).write_text(manifest_text(["../thesis.txt"]), encoding="utf-8")
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


def test_the_root_is_refused() -> None:
    with pytest.raises(OutputError, match="root directory"):
        check_target(Path("/"))


def test_a_manifest_with_another_header_is_not_ours(tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    (out / MANIFEST).write_text("# my notes\nthesis.txt\n", encoding="utf-8")
    (out / "thesis.txt").write_text("t", encoding="utf-8")
    with pytest.raises(OutputError, match="did not write"):
        check_target(out)


def test_names_that_would_break_a_message_are_quoted(tmp_path: Path) -> None:
    (tmp_path / "evil\nbangcheck: wrote fine").write_text("x", encoding="utf-8")
    with pytest.raises(OutputError) as raised:
        check_target(tmp_path)
    assert "\n" not in str(raised.value)
    assert "'evil\\nbangcheck: wrote fine'" in str(raised.value)


# -- what the report may replace --------------------------------------------------------------


def test_a_new_an_empty_and_a_previous_report_directory_are_written(tmp_path: Path) -> None:
    new = tmp_path / "a" / "b" / "new"
    write_report_dir(new, FILES, log=lambda m: None)
    assert tree(new) == {**FILES, MANIFEST: manifest_text(list(FILES))}
    empty = tmp_path / "empty"
    empty.mkdir()
    write_report_dir(empty, FILES, log=lambda m: None)
    assert tree(empty) == tree(new)
    smaller = {"index.html": "<p>second</p>\n"}
    write_report_dir(new, smaller, log=lambda m: None)  # what the first wrote goes
    assert tree(new) == {**smaller, MANIFEST: manifest_text(["index.html"])}


LEGACY = {
    "index.html": "<!doctype html>\n<html>\n<head>\n<title>bangcheck: errata report</title>\n",
    "errata.csv": "id,chapter,line,quantity,printed,correct,model_value,diagnosis_kind\n",
    "claims.json": '{\n "meta": {\n  "bangcheck": "0.1.0",\n',
    "properties.json": '{\n "date": "2026-11-22", "profile": "ci",\n "invariants": []}\n',
}


def test_a_report_written_before_the_manifest_is_replaced(tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    for name, text in LEGACY.items():
        (out / name).write_text(text, encoding="utf-8")
    write_report_dir(out, FILES, log=lambda m: None)
    assert tree(out) == {**FILES, MANIFEST: manifest_text(list(FILES))}


def test_the_directory_keeps_its_permissions(tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    out.chmod(0o750)
    write_report_dir(out, FILES, log=lambda m: None)
    assert stat.S_IMODE(out.stat().st_mode) == 0o750
    fresh = tmp_path / "fresh"
    write_report_dir(fresh, FILES, log=lambda m: None)
    assert stat.S_IMODE(fresh.stat().st_mode) & 0o055 == 0o055 & ~_umask()  # not mkdtemp's 0700


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def test_the_command_writes_the_manifest_and_reads_no_properties_in_its_output(
    tmp_path: Path, book: Book, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """The report's own directory holds only what it wrote: the invariants the tests record
    live in ``.bangcheck/`` (found from the working directory up), not in ``--out``."""
    monkeypatch.chdir(tmp_path)
    code, _ = report(capsys, book, tmp_path / "out")
    assert code == 0
    names = sorted(os.listdir(tmp_path / "out"))
    assert names == sorted([MANIFEST, "index.html", "errata.csv", "errata.md", "claims.json"])
    assert sorted(os.listdir(tmp_path)) == ["out"]


# -- concurrent runs and crashes ----------------------------------------------------------


def _write_many(out: str, tag: int, rounds: int) -> None:
    files = {name: f"{tag}:{name}\n" * 20_000 for name in FILES}
    for _ in range(rounds):
        write_report_dir(Path(out), files, log=lambda m: None)


def test_concurrent_runs_leave_one_good_report_and_no_debris(tmp_path: Path) -> None:
    out = tmp_path / "out"
    context = multiprocessing.get_context("fork")
    workers = [context.Process(target=_write_many, args=(str(out), tag, 15)) for tag in range(4)]
    for w in workers:
        w.start()
    for w in workers:
        w.join(timeout=120)
    assert [w.exitcode for w in workers] == [0, 0, 0, 0]
    assert sorted(os.listdir(tmp_path)) == ["out"]  # no .out.new-* or .out.old-*
    written = tree(out)
    assert set(written) == {*FILES, MANIFEST}
    tags = {text.split(":", 1)[0] for name, text in written.items() if name != MANIFEST}
    assert len(tags) == 1  # all three files from one run, never a mix


def _die_between_the_renames(out: str) -> None:
    def first_rename_only(staging: Path, target: Path, log: object) -> None:
        target.rename(target.parent / f".{target.name}.old-dead")
        os._exit(3)

    outdir._swap_in = first_rename_only  # type: ignore[assignment]
    write_report_dir(Path(out), {"index.html": "new\n"}, log=lambda m: None)


def test_a_crash_between_the_two_renames_is_recovered(tmp_path: Path) -> None:
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    before = tree(out)
    child = multiprocessing.get_context("fork").Process(
        target=_die_between_the_renames, args=(str(out),)
    )
    child.start()
    child.join(timeout=60)
    assert child.exitcode == 3
    left = sorted(os.listdir(tmp_path))
    assert "out" not in left
    assert [n for n in left if n.startswith(".out.new-")]
    assert ".out.old-dead" in left
    said: list[str] = []
    with outdir.locked(tmp_path):
        recover(out, said.append)
    assert tree(out) == before  # the previous report is back
    assert sorted(os.listdir(tmp_path)) == ["out"]
    assert any("restored" in line for line in said)
    assert any("unfinished report" in line for line in said)


def test_recovery_removes_only_what_carries_the_manifest(tmp_path: Path) -> None:
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    ours = tmp_path / ".out.old-1"
    write_report_dir(ours, FILES, log=lambda m: None)
    theirs = tmp_path / ".out.old-2"  # an earlier version's leftover, or the user's
    theirs.mkdir()
    (theirs / "index.html").write_text("x", encoding="utf-8")
    staging = tmp_path / ".out.new-3"
    staging.mkdir()
    (staging / "thesis.txt").write_text("t", encoding="utf-8")
    said: list[str] = []
    recover(out, said.append)
    assert sorted(os.listdir(tmp_path)) == [".out.new-3", ".out.old-2", "out"]
    assert any(".out.old-2" in line and "by hand" in line for line in said)


def test_a_missing_report_is_restored_only_from_a_single_candidate(tmp_path: Path) -> None:
    out = tmp_path / "out"
    for name in (".out.old-1", ".out.old-2"):
        write_report_dir(tmp_path / name, FILES, log=lambda m: None)
    recover(out, lambda m: None)
    assert sorted(os.listdir(tmp_path)) == []  # two candidates: neither is the report


# -- unwritable output ------------------------------------------------------------------------


def test_a_parent_that_cannot_be_made_is_one_line(
    tmp_path: Path, book: Book, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "file.txt").write_text("t", encoding="utf-8")
    code, err = report(capsys, book, tmp_path / "file.txt" / "out")
    assert code == 2
    assert err.splitlines() == [
        f"bangcheck: error: --out {tmp_path / 'file.txt' / 'out'}: cannot be made, "
        f"{tmp_path / 'file.txt'} is a file"
    ]


@pytest.mark.parametrize(
    ("where", "code", "shown"),
    [
        ("mkdtemp", errno.EROFS, "read-only file system"),
        ("mkdtemp", errno.EACCES, "Permission denied"),
        ("write", errno.ENOSPC, "No space left on device"),
        ("rename", errno.EACCES, "Permission denied"),
    ],
)
def test_unwritable_output_is_one_line_and_keeps_the_previous_report(
    tmp_path: Path,
    book: Book,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
    where: str,
    code: int,
    shown: str,
) -> None:
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    before = tree(out)

    def fail(*args: object, **kwargs: object) -> None:
        raise OSError(code, os.strerror(code), str(out))

    if where == "mkdtemp":
        monkeypatch.setattr(tempfile, "mkdtemp", fail)
    elif where == "write":
        monkeypatch.setattr(outdir, "_fsync", fail)
    else:
        monkeypatch.setattr(outdir, "_swap_in", lambda staging, target, log: fail())
    exit_code, err = report(capsys, book, out)
    assert exit_code == 2
    assert err.splitlines()[-1].startswith(f"bangcheck: error: cannot write the report to {out}")
    assert shown in err.splitlines()[-1]
    assert "Traceback" not in err
    assert tree(out) == before
    assert sorted(os.listdir(tmp_path)) == ["out"]


def test_a_failed_second_rename_puts_the_previous_report_back(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    before = tree(out)
    real = Path.rename
    calls = []

    def second_fails(self: Path, target: Path) -> Path:
        calls.append(self.name)
        if len(calls) == 2:
            raise OSError(errno.EIO, "I/O error", str(self))
        return real(self, target)

    monkeypatch.setattr(Path, "rename", second_fails)
    with pytest.raises(OutputError, match="I/O error"):
        write_report_dir(out, {"index.html": "new"}, log=lambda m: None)
    monkeypatch.undo()
    assert tree(out) == before
    assert sorted(os.listdir(tmp_path)) == ["out"]


def test_the_next_run_cleans_up_after_a_crash(tmp_path: Path) -> None:
    """What the crash left is cleaned up by the next ``write_report_dir`` itself."""
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    child = multiprocessing.get_context("fork").Process(
        target=_die_between_the_renames, args=(str(out),)
    )
    child.start()
    child.join(timeout=60)
    assert child.exitcode == 3
    (tmp_path / ".out.new-empty").mkdir()  # a crash before the manifest was written
    said: list[str] = []
    write_report_dir(out, {"index.html": "after\n"}, log=said.append)
    assert tree(out) == {"index.html": "after\n", MANIFEST: manifest_text(["index.html"])}
    assert sorted(os.listdir(tmp_path)) == ["out"]
    assert any("restored" in line for line in said)


def test_recovery_follows_no_symlink(tmp_path: Path) -> None:
    """A ``.out.old-*`` that is a link (to a user's folder holding a forged manifest) is no
    report of an earlier run: neither restored nor removed."""
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / MANIFEST).write_text(manifest_text(["thesis.txt"]), encoding="utf-8")
    (mine / "thesis.txt").write_text("t", encoding="utf-8")
    (tmp_path / ".out.old-1").symlink_to(mine)
    (tmp_path / ".out.new-2").symlink_to(mine)
    recover(tmp_path / "out", lambda m: None)
    assert tree(mine) == {MANIFEST: manifest_text(["thesis.txt"]), "thesis.txt": "t"}
    assert not (tmp_path / "out").exists()


def test_a_report_is_removed_file_by_file(tmp_path: Path) -> None:
    """Only the files a report lists go, the manifest last: anything else stops the removal
    of the directory, and is kept."""
    out = tmp_path / "out"
    write_report_dir(out, FILES, log=lambda m: None)
    (out / "notes.txt").write_text("n", encoding="utf-8")
    assert outdir.remove_report(out) == ["notes.txt"]
    assert sorted(os.listdir(out)) == ["notes.txt"]


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


def test_a_file_system_that_cannot_lock_still_gets_its_report(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """NFS cannot ``flock`` a directory opened for reading: warn and write unlocked."""

    def no_locks(fd: int, operation: int) -> None:
        raise OSError(errno.EBADF, os.strerror(errno.EBADF))

    monkeypatch.setattr(outdir.fcntl, "flock", no_locks)
    said: list[str] = []
    write_report_dir(tmp_path / "out", FILES, log=said.append)
    assert tree(tmp_path / "out")["index.html"] == FILES["index.html"]
    assert any("cannot lock" in line for line in said)


def test_parents_made_for_a_failed_write_are_removed(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    def fail(*args: object, **kwargs: object) -> None:
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(tmp_path))

    monkeypatch.setattr(tempfile, "mkdtemp", fail)
    with pytest.raises(OutputError, match="No space left"):
        write_report_dir(tmp_path / "a" / "b" / "out", FILES, log=lambda m: None)
    assert os.listdir(tmp_path) == []
