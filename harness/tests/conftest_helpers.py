"""Small helpers shared by the TENZOR test suites."""
from __future__ import annotations

from pathlib import Path


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
