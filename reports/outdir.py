"""The report's output directory: written only when it is the report's own, and swapped whole.

A directory is the report's own when it is missing, empty, or holds nothing but a previous
report: every entry other than the manifest ``.bangcheck-report`` is named in that manifest, or,
for a report written before the manifest existed, every entry is one of ``LEGACY_NAMES``. Any
other directory, and a file or device, is refused and left untouched: the report never deletes
what it did not write.

The files are written into ``.NAME.new-*`` beside the target (the manifest first), which then
replaces the target in two renames (the old one moved to ``.NAME.old-*`` and removed). All of it
happens under an exclusive ``flock`` on the parent directory, so that two runs into one place
take turns; under the lock, what a run that crashed left is cleaned up first (``recover``).
Every failure is an ``OutputError`` with a one-line message, and leaves the previous report as
it was.
"""

from __future__ import annotations

import contextlib
import errno
import fcntl
import os
import secrets
import shutil
import stat
import sys
import tempfile
from collections.abc import Callable, Iterator, Mapping
from pathlib import Path

MANIFEST = ".bangcheck-report"
MANIFEST_HEADER = (
    "# bangcheck report: the files below were written by `bangcheck report`, "
    "which replaces this directory on its next run"
)
LEGACY_NAMES = frozenset({"index.html", "errata.csv", "claims.json", "properties.json"})
SHOWN_FOREIGN = 3  # foreign entries named in a refusal

Log = Callable[[str], None]


class OutputError(Exception):
    """The report cannot be written where asked; the message is one line for the user."""


def _stderr(message: str) -> None:
    print(f"bangcheck: {message}", file=sys.stderr)


def manifest_text(names: list[str]) -> str:
    """The manifest listing ``names``, the files a report wrote."""
    return "\n".join([MANIFEST_HEADER, *names]) + "\n"


def manifest_names(directory: Path) -> frozenset[str] | None:
    """The names ``directory``'s manifest lists, or None where it has no readable manifest of
    ours (a file of that name that bangcheck did not write counts as none)."""
    try:
        text = (directory / MANIFEST).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return None
    first, _, rest = text.partition("\n")
    if first != MANIFEST_HEADER:
        return None
    names = frozenset(line for line in rest.splitlines() if line)
    if any("/" in n or n in (".", "..", MANIFEST) for n in names):
        return None
    return names


def foreign_entries(directory: Path) -> list[str]:
    """The entries of an existing ``directory`` that no report wrote, sorted; empty when the
    directory is empty or holds only a previous report. ``OSError`` if it cannot be listed."""
    entries = set(os.listdir(directory))
    if MANIFEST in entries:
        listed = manifest_names(directory)
        if listed is None:
            return sorted(entries)  # a manifest we cannot read vouches for nothing
        return sorted(entries - listed - {MANIFEST})
    return sorted(entries - LEGACY_NAMES)


def carries_manifest(directory: Path) -> bool:
    """Whether ``directory`` holds a manifest of ours and nothing it does not list."""
    try:
        return manifest_names(directory) is not None and not foreign_entries(directory)
    except OSError:
        return False


def _kind(mode: int) -> str:
    if stat.S_ISREG(mode):
        return "a file"
    if stat.S_ISCHR(mode):
        return "a character device"
    if stat.S_ISBLK(mode):
        return "a block device"
    if stat.S_ISFIFO(mode):
        return "a named pipe"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "not a directory"


def _nearest_existing(path: Path) -> Path:
    while not os.path.lexists(path) and path != path.parent:
        path = path.parent
    return path


def check_target(out: Path) -> None:
    """Raise ``OutputError`` unless the report may write ``out`` (an absolute path): missing
    with a parent that can be made, empty, or a previous report. Touches nothing."""
    if out == out.parent:
        raise OutputError(f"--out {out}: the root directory is not an output directory")
    try:
        mode = out.stat().st_mode
    except (FileNotFoundError, NotADirectoryError):
        ancestor = _nearest_existing(out.parent)
        if not ancestor.is_dir():
            raise OutputError(
                f"--out {out}: cannot be made, {ancestor} is {_kind(ancestor.lstat().st_mode)}"
            ) from None
        if not os.access(ancestor, os.W_OK | os.X_OK):
            raise OutputError(f"--out {out}: cannot be made, {ancestor} is not writable") from None
        return
    except OSError as err:
        raise OutputError(f"--out {out}: {err.strerror}") from err
    if not stat.S_ISDIR(mode):
        raise OutputError(
            f"--out {out} is {_kind(mode)}: refused, nothing was changed; "
            "give a new or empty directory"
        )
    try:
        foreign = foreign_entries(out)
    except OSError as err:
        raise OutputError(f"--out {out}: cannot list it: {err.strerror}") from err
    if foreign:
        shown = ", ".join(foreign[:SHOWN_FOREIGN])
        more = len(foreign) - SHOWN_FOREIGN
        if more > 0:
            shown += f" and {more} more"
        raise OutputError(
            f"--out {out} holds files the report did not write ({shown}): refused, nothing "
            "was changed; give a new or empty directory, or move those files elsewhere"
        )


@contextlib.contextmanager
def locked(directory: Path, log: Log = _stderr) -> Iterator[None]:
    """An exclusive ``flock`` on ``directory``'s own descriptor for the block: no lock file is
    left behind, and a run that dies releases it."""
    fd = os.open(directory, os.O_RDONLY | os.O_DIRECTORY)
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            log(f"waiting for another report being written in {directory}")
            fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)  # releases the lock


def _debris(parent: Path, name: str, kind: str) -> list[Path]:
    prefix = f".{name}.{kind}-"
    return sorted(parent / e for e in os.listdir(parent) if e.startswith(prefix))


def recover(out: Path, log: Log = _stderr) -> None:
    """Clean up what an interrupted run left beside ``out``; call it under ``locked``.

    A ``.NAME.new-*`` that carries the manifest is an unfinished write: removed. If ``out`` is
    missing and exactly one ``.NAME.old-*`` carries the manifest, the run died between its two
    renames: that previous report is renamed back. Every other ``.NAME.old-*`` carrying the
    manifest is removed; one that does not is left, and named.
    """
    parent, name = out.parent, out.name
    for staging in _debris(parent, name, "new"):
        if staging.is_dir() and not staging.is_symlink() and carries_manifest(staging):
            shutil.rmtree(staging)
            log(f"removed {staging}, an unfinished report of an earlier run")
    olds = [p for p in _debris(parent, name, "old") if p.is_dir() and not p.is_symlink()]
    ours = [p for p in olds if carries_manifest(p)]
    if not os.path.lexists(out) and len(ours) == 1:
        ours.pop().rename(out)
        log(f"restored {out}, the previous report, which an interrupted run had moved aside")
    for old in ours:
        shutil.rmtree(old)
        log(f"removed {old}, a previous report an earlier run had moved aside")
    for old in olds:
        if old.exists() and not carries_manifest(old):
            log(f"left {old}: an earlier run's leftover without a manifest (remove it by hand)")


def _fsync(path: Path) -> None:
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _write_staging(staging: Path, files: Mapping[str, str | bytes]) -> None:
    (staging / MANIFEST).write_text(manifest_text(list(files)), encoding="utf-8")
    for name, content in files.items():
        path = staging / name
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content, encoding="utf-8")
        _fsync(path)
    _fsync(staging / MANIFEST)
    _fsync(staging)


def _default_mode() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return 0o777 & ~mask


def _swap_in(staging: Path, out: Path) -> None:
    """Replace ``out`` (if any) by ``staging``; if the second rename fails, put it back."""
    old = None
    if os.path.lexists(out):
        old = out.parent / f".{out.name}.old-{secrets.token_hex(4)}"
        out.rename(old)
    try:
        staging.rename(out)
    except OSError:
        if old is not None:
            old.rename(out)
        raise
    _fsync(out.parent)
    if old is not None:
        shutil.rmtree(old, ignore_errors=True)  # what stays is ours, and the next run's to clear


def write_report_dir(out: Path, files: Mapping[str, str | bytes], log: Log = _stderr) -> None:
    """Make ``out`` a directory holding exactly ``files`` (name to content) and the manifest.

    Refuses (``OutputError``, nothing touched) unless ``check_target`` admits ``out``; any
    failure while writing is an ``OutputError`` too, and leaves the previous report in place.
    """
    out = Path(os.path.abspath(out))
    if any("/" in name or name in ("", ".", "..", MANIFEST) for name in files):
        raise ValueError(f"report file names must be plain names: {sorted(files)}")
    check_target(out)
    staging: Path | None = None
    try:
        out.parent.mkdir(parents=True, exist_ok=True)
        with locked(out.parent, log):
            recover(out, log)
            check_target(out)  # again, under the lock: another run may have been first
            mode = out.stat().st_mode if out.is_dir() else _default_mode()
            staging = Path(tempfile.mkdtemp(prefix=f".{out.name}.new-", dir=out.parent))
            _write_staging(staging, files)
            staging.chmod(stat.S_IMODE(mode))  # mkdtemp's is private; keep the old one's
            _swap_in(staging, out)
            staging = None
    except OSError as err:
        where = err.filename or out
        reason = err.strerror or str(err)
        if err.errno == errno.EROFS:
            reason = "read-only file system"
        raise OutputError(
            f"cannot write the report to {out}: {reason} ({where}); "
            "the previous report, if any, is unchanged"
        ) from err
    finally:
        if staging is not None and staging.exists():
            shutil.rmtree(staging, ignore_errors=True)
