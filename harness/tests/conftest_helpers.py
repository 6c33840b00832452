"""Small helpers shared by the TENZOR test suites."""
from __future__ import annotations

from pathlib import Path

#: What a program of the project must never print, whatever its input: the
#: Fortran run-time library's error reports and the signals of a crash
#: (the fuzz suites check both streams for these).
FORBIDDEN = ("Fortran runtime", "Backtrace", "Error termination", "Program received signal",
             "SIGSEGV", "SIGFPE", "SIGABRT", "SIGBUS", "Segmentation fault", "core dumped",
             "Aborted")


def read_job(path: Path) -> dict[str, str]:
    """A job sheet as a dict of its `key = value` lines (comments skipped)."""
    job: dict[str, str] = {}
    for line in path.read_text().splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        key, sep, value = line.partition(" = ")
        assert sep, f"{path}: not a key = value line: {line!r}"
        job[key] = value
    return job
