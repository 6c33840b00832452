"""Shared pieces of the em703 suites (test_em703_*.py): the built command,
the tapes and job sheets TENZOR punches for every deck in examples/, random
frame lists for hypothesis, and a runner.  The fixtures are imported into
each suite's namespace (pytest finds them there); nothing here imports the
Fortran, only runs it."""

from __future__ import annotations

import math
import os
import subprocess
from dataclasses import dataclass
from pathlib import Path

import pytest
from hypothesis import assume
from hypothesis import strategies as st

from harness.conftest import ROOT, _fpm_binary
from harness.tape import Frame, on_circle

DECKS: list[Path] = sorted((ROOT / "examples").rglob("*.crd"))


@pytest.fixture(scope="session")
def em703_exe() -> Path:
    """Path of the `em703` executable: $EM703_EXE when set (CI's pass with
    gfortran's run-time checks), else the one fpm builds."""
    given = os.environ.get("EM703_EXE")
    if given:
        path = Path(given).resolve()
        assert path.is_file(), f"EM703_EXE={given} is not a file"
        return path
    return _fpm_binary("em703")


@dataclass(frozen=True)
class Example:
    """The output of TENZOR for one example deck."""

    deck: Path
    out: Path

    @property
    def tapes(self) -> list[Path]:
        return sorted(self.out.glob("*.ptp"))

    @property
    def jobs(self) -> list[Path]:
        return sorted(self.out.glob("*.job"))


@pytest.fixture(scope="session")
def examples(tenzor_exe: Path, tmp_path_factory: pytest.TempPathFactory) -> list[Example]:
    """TENZOR run on every deck of examples/, each into its own directory."""
    base = tmp_path_factory.mktemp("em703_examples")
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
    tapes = [t for e in examples for t in e.tapes]
    assert len(tapes) == 3 * len(DECKS)
    return tapes


@pytest.fixture(scope="session")
def example_jobs(examples: list[Example]) -> list[Path]:
    return [j for e in examples for j in e.jobs]


def run(exe: Path, *args: str | Path, check: int | None = None) -> subprocess.CompletedProcess:
    """Run em703; with ``check``, assert the exit status."""
    proc = subprocess.run([str(exe), *map(str, args)], capture_output=True, timeout=120)
    if check is not None:
        assert proc.returncode == check, (args, proc.returncode, proc.stdout[-2000:],
                                          proc.stderr.decode("latin-1"))
    return proc


def keys(text: str) -> dict[str, str]:
    """`key = value` lines as a dict."""
    out: dict[str, str] = {}
    for line in text.splitlines():
        if not line or line.startswith("#"):
            continue
        key, sep, value = line.partition(" = ")
        assert sep, line
        out[key] = value
    return out


def write_job(directory: Path, name: str, tapes: dict[str, bytes],
              tools: dict[str, str], code: str = "8") -> Path:
    """A job sheet and its three tapes (missing tapes are GM GM)."""
    empty = bytes([0] * 20 + [0o37, 0o37] + [0] * 20)
    lines = ["# written by the em703 tests", f"name = {name}", f"code = {code}",
             "scale = 1:1", "start_x_mm = 600.00", "start_y_mm = 600.00"]
    for key in ("small", "large", "cond"):
        (directory / f"{name}-{key}.ptp").write_bytes(tapes.get(key, empty))
        lines += [f"{key}.tape = {name}-{key}.ptp", f"{key}.tool_mm = {tools.get(key, '0.50')}"]
    path = directory / f"{name}.job"
    path.write_text("\n".join(lines) + "\n")
    return path


# ---------------------------------------------------------------------------
# Random frame lists: lines, travel, dots, circles, arcs whose ends lie on
# their circle (checked with the harness's own rule), cycles of small counts,
# so that a tape stays within a few hundred mm and a few hundred frames.
# ---------------------------------------------------------------------------
steps = st.integers(-6000, 6000)


@st.composite
def circle_start(draw: st.DrawFn) -> tuple[int, int]:
    x = draw(st.integers(-3000, 3000))
    y = draw(st.integers(-3000, 3000))
    assume(x or y)
    return x, y


@st.composite
def arc_frame(draw: st.DrawFn) -> Frame:
    x, y = draw(circle_start())
    k = draw(st.sampled_from([11, 13]))
    r, a0 = math.hypot(x, y), math.atan2(y, x)
    theta = draw(st.floats(0.05, 2 * math.pi - 0.05))
    ex, ey = round(r * math.cos(a0 + theta)), round(r * math.sin(a0 + theta))
    assume((ex, ey) != (x, y) and on_circle(x, y, ex - x, ey - y))
    return Frame(x=x, y=y, dx=ex - x, dy=ey - y, k=k)


def single_frame() -> st.SearchStrategy[Frame]:
    lines = st.builds(Frame, dx=steps, dy=steps, k=st.sampled_from([10, 20]))
    circles = st.builds(lambda xy, k: Frame(x=xy[0], y=xy[1], k=k),
                        circle_start(), st.sampled_from([11, 13]))
    dots = st.just(Frame(k=10))
    return st.one_of(lines, lines, circles, arc_frame(), dots)


@st.composite
def frame_lists(draw: st.DrawFn, max_items: int = 8) -> list[Frame]:
    frames: list[Frame] = []
    for _ in range(draw(st.integers(1, max_items))):
        first = draw(single_frame())
        if draw(st.integers(0, 3)) == 0:                   # a cycle pair
            frames += [Frame(first.x, first.y, first.dx, first.dy,
                             draw(st.integers(2, 12)), first.k), draw(single_frame())]
        else:
            frames.append(first)
    return frames
