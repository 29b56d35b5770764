"""A report built in a forked process while its caller goes on with other work.

The test session uses it when run serially: one core runs the tests while the other builds the
report, its figures drawn one after another, at a low priority (nice 10); the report and
browser tests, which run late, then only collect it. The child is forked, so it starts from the
caller's evaluation and scan as they are, with nothing pickled on the way in; it sends back the
report's files (about 6 MB of text) or the traceback of what failed.
"""

from __future__ import annotations

import multiprocessing
import os
import traceback
from multiprocessing.connection import Connection
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from multiprocessing.process import BaseProcess

    from reference.catalog import Catalog
    from reference.evaluation import Evaluation
    from reference.scan import ScanResult


class BackgroundReportError(RuntimeError):
    """The report build failed in the forked process (its traceback is the message)."""


class BackgroundReport:
    """``reports.page.build_report`` running in a forked process; ``files()`` waits for it."""

    def __init__(self, evaluation: Evaluation, scan: ScanResult, catalog: Catalog) -> None:
        receiving, sending = multiprocessing.Pipe(duplex=False)
        context = multiprocessing.get_context("fork")
        self._connection: Connection = receiving
        self._process: BaseProcess = context.Process(
            target=_build, args=(sending, evaluation, scan, catalog), name="bangcheck-report"
        )
        self._process.start()
        sending.close()  # the child's end: the parent keeps only its own
        self._files: dict[str, str] | None = None
        self._error: BackgroundReportError | None = None

    @staticmethod
    def available() -> bool:
        """Whether this platform can fork (the build needs the caller's objects as they are)."""
        return "fork" in multiprocessing.get_all_start_methods()

    @property
    def running(self) -> bool:
        """Whether the forked process is still alive."""
        return self._process.is_alive()

    def files(self) -> dict[str, str]:
        """The report's files by name, once built; ``BackgroundReportError`` (every time) if
        the build failed or the process died."""
        if self._files is None and self._error is None:
            try:
                status, payload = self._connection.recv()
            except EOFError:
                status, payload = "died", None
            finally:
                self._connection.close()
            self._process.join()
            if status == "ok":
                self._files = payload
            elif status == "died":
                self._error = BackgroundReportError(
                    f"the report process ended (exit code {self._process.exitcode}) "
                    "without sending the report"
                )
            else:
                self._error = BackgroundReportError(f"the report build failed:\n{payload}")
        if self._error is not None:
            raise self._error
        assert self._files is not None
        return self._files

    def stop(self) -> None:
        """End the process if it still runs (the session ended before the report was needed)."""
        if self._process.is_alive():
            self._process.terminate()
        self._process.join()
        self._connection.close()


def _build(sending: Connection, evaluation: Evaluation, scan: ScanResult, catalog: Catalog) -> None:
    """The child: build the report on one core at a low priority, and send ("ok", files) or
    ("error", traceback)."""
    from reports.page import build_report

    os.nice(10)  # should anything else want the CPU, the caller's tests come first
    message: tuple[str, dict[str, str] | str]
    try:
        message = ("ok", build_report(evaluation, scan, catalog, None, figure_workers=1))
    except Exception:  # any failure goes back to the caller, whose test reports it
        message = ("error", traceback.format_exc())
    sending.send(message)
    sending.close()
