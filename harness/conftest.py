"""Fixtures shared by every harness suite.

The harness checks the project's programs from the outside: it runs the built
executables as a user would and reads the files they write. It never links or
imports project code (the oracle stays independent).
"""
from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest
from hypothesis import HealthCheck, settings

ROOT = Path(__file__).resolve().parent.parent

settings.register_profile(
    "ci", derandomize=True, deadline=None, print_blob=True,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile("dev", deadline=None, suppress_health_check=[HealthCheck.too_slow])
# The long fuzzing run of docs/ROBUSTNESS.md: random (not derandomised); the
# fuzz suites read the profile's name and run 2500 examples per property.
settings.register_profile("long", deadline=None, print_blob=True,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci" if os.environ.get("CI") else "dev"))


def _fpm_binary(name: str) -> Path:
    """Build with fpm (a no-op when up to date) and return the path of executable `name`."""
    fpm = shutil.which("fpm")
    if fpm is None:
        # a failure, not a skip: a run that silently skipped every test of the
        # programs would look like a pass
        pytest.fail("fpm is not on PATH: run the tests with `make test` "
                    "(or set TENZOR_EXE / EM703_EXE to built programs)", pytrace=False)
    subprocess.run([fpm, "build"], cwd=ROOT, check=True, capture_output=True)
    out = subprocess.run([fpm, "run", "--runner", "echo", name], cwd=ROOT, check=True,
                         capture_output=True, text=True).stdout.split()
    path = ROOT / out[-1]
    assert path.exists(), f"fpm did not build {name}: {path}"
    return path


@pytest.fixture(scope="session")
def tenzor_exe() -> Path:
    """Path of the `tenzor` executable: $TENZOR_EXE when set (CI's second
    pass runs the suites against a build with gfortran's run-time checks),
    else the one fpm builds with its default flags."""
    given = os.environ.get("TENZOR_EXE")
    if given:
        path = Path(given).resolve()
        assert path.is_file(), f"TENZOR_EXE={given} is not a file"
        return path
    return _fpm_binary("tenzor")


def pytest_collection_modifyitems(config, items) -> None:
    """Mark every test that runs TENZOR with ``tenzor``, every test that runs
    em703 with ``em703`` (``pytest -m "tenzor or em703"`` selects them: CI's
    pass against the build with run-time checks)."""
    for item in items:
        names = getattr(item, "fixturenames", ())
        if "tenzor_exe" in names:
            item.add_marker(pytest.mark.tenzor)
        if "em703_exe" in names:
            item.add_marker(pytest.mark.em703)


def pytest_configure(config) -> None:
    config.addinivalue_line("markers", "tenzor: the test runs the tenzor executable")
    config.addinivalue_line("markers", "em703: the test runs the em703 executable")


@pytest.fixture
def run_tenzor(tenzor_exe: Path, tmp_path: Path):
    """Run tenzor on a deck (text or path) into a fresh directory.

    Returns a function deck -> (CompletedProcess, output directory).
    """
    counter = iter(range(10**6))

    def run(deck: str | bytes | Path, *args: str, out: Path | None = None):
        n = next(counter)
        out = out or tmp_path / f"out{n}"
        if isinstance(deck, Path):
            cmd = [str(tenzor_exe), str(deck), "-o", str(out), *args]
            proc = subprocess.run(cmd, capture_output=True, timeout=120)
        else:
            path = tmp_path / f"deck{n}.crd"
            path.write_bytes(deck.encode("utf-8") if isinstance(deck, str) else deck)
            cmd = [str(tenzor_exe), str(path), "-o", str(out), *args]
            proc = subprocess.run(cmd, capture_output=True, timeout=120)
        return proc, out

    return run
