"""The fixtures of every test suite (harness/, seeds/, bench/), in one place.

The tests check the project's programs from the outside: they run the built
executables as a user would and read the files they write; nothing here
links or imports the Fortran.  ``tenzor_exe`` and ``em703_exe`` are the
programs under test: $TENZOR_EXE and $EM703_EXE when set (CI's second pass
runs the suites against a build with gfortran's run-time checks), else the
ones fpm builds with its default flags.  A test that uses one of them is
marked ``tenzor`` or ``em703`` (``pytest -m "tenzor or em703"``).
"""
from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest
from hypothesis import HealthCheck, settings

from harness.tests.helpers import DECKS, ROOT, Example

# `make test` gives the same verdict on every run and every machine: the
# default profile is derandomised and keeps no example database (a failure
# found once is not replayed into later runs; it becomes an @example). New
# cases are explored only by `make fuzz` (the "long" profile: random, 2500
# examples a property in the fuzz suites, the blob of every failure printed
# so that it can be pinned as a regression example); "dev" is a quick random run.
settings.register_profile(
    "ci", derandomize=True, database=None, deadline=None, print_blob=True,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile("dev", deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("long", deadline=None, print_blob=True,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


def _program(variable: str, name: str) -> Path:
    """The program named by $VARIABLE, else the one fpm builds (a no-op when
    it is up to date)."""
    given = os.environ.get(variable)
    if given:
        path = Path(given).resolve()
        assert path.is_file(), f"{variable}={given} is not a file"
        return path
    fpm = shutil.which("fpm")
    if fpm is None:
        # a failure, not a skip: a run that silently skipped every test of the
        # programs would look like a pass
        pytest.fail(f"fpm is not on PATH: run the tests with `make test` "
                    f"(or set {variable} to a built program)", pytrace=False)
    subprocess.run([fpm, "build"], cwd=ROOT, check=True, capture_output=True)
    out = subprocess.run([fpm, "run", "--runner", "echo", name], cwd=ROOT, check=True,
                         capture_output=True, text=True).stdout.split()
    path = ROOT / out[-1]
    assert path.exists(), f"fpm did not build {name}: {path}"
    return path


@pytest.fixture(scope="session")
def tenzor_exe() -> Path:
    """Path of the `tenzor` program under test."""
    return _program("TENZOR_EXE", "tenzor")


@pytest.fixture(scope="session")
def em703_exe() -> Path:
    """Path of the `em703` program under test."""
    return _program("EM703_EXE", "em703")


def pytest_collection_modifyitems(config, items) -> None:
    """Mark every test that runs TENZOR with ``tenzor``, every test that runs
    em703 with ``em703`` (CI's pass against the build with run-time checks
    selects them)."""
    _hostile_total_last(items)
    for item in items:
        names = getattr(item, "fixturenames", ())
        if "tenzor_exe" in names:
            item.add_marker(pytest.mark.tenzor)
        if "em703_exe" in names:
            item.add_marker(pytest.mark.em703)


@pytest.fixture
def run_tenzor(tenzor_exe: Path, tmp_path: Path):
    """Run tenzor on a deck (text or path) into a fresh directory.

    Returns a function deck -> (CompletedProcess, output directory).
    """
    counter = iter(range(10**6))

    def run(deck: str | bytes | Path, *args: str, out: Path | None = None):
        n = next(counter)
        out = out or tmp_path / f"out{n}"
        if not isinstance(deck, Path):
            path = tmp_path / f"deck{n}.crd"
            path.write_bytes(deck.encode("utf-8") if isinstance(deck, str) else deck)
            deck = path
        cmd = [str(tenzor_exe), str(deck), "-o", str(out), *args]
        return subprocess.run(cmd, capture_output=True, timeout=120), out

    return run


@pytest.fixture(scope="session")
def examples(tenzor_exe: Path, tmp_path_factory: pytest.TempPathFactory) -> list[Example]:
    """TENZOR run on every deck of examples/, each into its own directory."""
    base = tmp_path_factory.mktemp("examples")
    done: list[Example] = []
    for n, deck in enumerate(DECKS):
        out = base / f"{n:02d}-{deck.stem}"
        proc = subprocess.run([str(tenzor_exe), str(deck), "-o", str(out)],
                              capture_output=True, timeout=120)
        assert proc.returncode == 0, (deck, proc.stderr.decode("latin-1"))
        done.append(Example(deck, out))
    return done


@pytest.fixture(scope="session")
def example_tapes(examples: list[Example]) -> list[Path]:
    """Every tape TENZOR punches for the decks of examples/."""
    tapes = [t for e in examples for t in e.tapes]
    assert len(tapes) == 3 * len(DECKS)
    return tapes


@pytest.fixture(scope="session")
def example_jobs(examples: list[Example]) -> list[Path]:
    """Every job sheet TENZOR writes for the decks of examples/."""
    return [j for e in examples for j in e.jobs]


def _hostile_total_last(items) -> None:
    """harness/tests/test_hostile_total.py checks the whole run's count of
    hostile inputs: it must run after every batch suite."""
    last = [i for i in items if i.nodeid.endswith("test_hostile_total.py::test_a_ci_run_makes_"
                                                  "at_least_10000_hostile_inputs")]
    for item in last:
        items.remove(item)
        items.append(item)


def pytest_terminal_summary(terminalreporter, exitstatus, config) -> None:
    """The hostile inputs the batch fuzz suites gave each program in this run
    (harness/tests/hostile.py)."""
    from harness.tests.hostile import COUNTS
    if COUNTS:
        terminalreporter.section("hostile inputs (batch fuzz suites)")
        for program, n in sorted(COUNTS.items(), key=lambda kv: -kv[1]):
            terminalreporter.write_line(f"{program:16s} {n:6d}")
        terminalreporter.write_line(f"{'total':16s} {sum(COUNTS.values()):6d}")
