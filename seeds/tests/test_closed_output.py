"""Every Python command of the project stops quietly when the reader of its
standard output goes away (``python -m seeds cnclink ... | head -1``): exit
status 2, an I/O failure, with nothing on standard error but what the
command said itself, and never a BrokenPipeError traceback or Python's
"Exception ignored" line."""
from __future__ import annotations

import importlib
import os
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from harness import tape
from seeds.tests.test_gerber2deck import BOARD

ROOT = Path(__file__).resolve().parents[2]


def _clean(err: str) -> None:
    assert "Traceback" not in err and "BrokenPipeError" not in err, err
    assert "Exception ignored" not in err, err


def test_a_long_output_into_a_reader_that_stops_after_one_line(tmp_path) -> None:
    # 20 000 lines of --view, printed one at a time: the reader takes the
    # first and goes, as head -1 does
    src = tmp_path / "long.txt"
    src.write_text("".join(f"{k} {k % 7}\n" for k in range(20000)))
    proc = subprocess.Popen([sys.executable, "-m", "seeds", "cnclink", str(src), "--view"],
                            cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    first = proc.stdout.readline()
    proc.stdout.close()
    err = proc.stderr.read().decode("utf-8")
    proc.wait(timeout=120)
    assert first.decode().split() == ["1", "1000", "z", "layer", "0"]
    _clean(err)
    assert proc.returncode == 2 and err == "", (proc.returncode, err)


def _argv(name: str, tmp_path: Path) -> list[str]:
    """A command of each Python entry point that prints to standard output."""
    script = "import sys; from seeds.{} import main; sys.exit(main())"
    if name == "harness":
        (tmp_path / "t.ptp").write_bytes(tape.encode([tape.Frame(dx=300, dy=400)] * 50))
        return ["-m", "harness", "decode", str(tmp_path / "t.ptp")]
    if name == "gerber2deck":
        (tmp_path / "b.gbr").write_text(BOARD)
        return ["-c", script.format("gerber"), str(tmp_path / "b.gbr")]
    return {
        "seeds": ["-m", "seeds", "split", "--max", "2", "98132", "87647"],
        "cnclink": ["-m", "seeds", "cnclink", "examples/flange.crd", "--view"],
        "bench": ["-m", "bench", "--report", "bench/results/bench.csv", "--out",
                  str(tmp_path / "bench")],
        "dxf2deck": ["-c", script.format("seed001"), "examples/dxf/board.dxf"],
        "dxf2dmc": ["-c", script.format("seed001_dmc"), "examples/dxf/board.dxf"],
    }[name]


@pytest.mark.parametrize("name", ["seeds", "cnclink", "harness", "bench", "dxf2deck",
                                  "dxf2dmc", "gerber2deck"])
def test_a_reader_gone_before_the_first_line(tmp_path, name) -> None:
    argv = _argv(name, tmp_path)
    read, write = os.pipe()
    os.close(read)                     # nobody will ever read: the first write fails
    try:
        proc = subprocess.run([sys.executable, *argv], cwd=ROOT, stdout=write,
                              stderr=subprocess.PIPE, timeout=300)
    finally:
        os.close(write)
    err = proc.stderr.decode("utf-8")
    _clean(err)
    assert proc.returncode == 2, (proc.returncode, err)


def _entry_points() -> list[str]:
    """The modules a user runs: those of harness/, seeds/ and bench/ with a
    ``__main__`` block, and the console scripts pyproject.toml names."""
    found = []
    for package in ("harness", "seeds", "bench"):
        for path in sorted((ROOT / package).glob("*.py")):
            if 'if __name__ == "__main__":' in path.read_text(encoding="utf-8"):
                found.append(f"{package}.{path.stem}")
    scripts = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["scripts"]
    found += [target.split(":")[0] for target in scripts.values()]
    return sorted(set(found))


@pytest.mark.parametrize("module", _entry_points())
def test_every_entry_point_stops_quietly(module) -> None:
    # the guard is the same for all (harness.files.quiet_when_output_closes,
    # tested above on one command of each kind): a main without it would
    # print BrokenPipeError's traceback under `| head`
    main = importlib.import_module(module).main
    assert main.__code__.co_qualname.startswith("quiet_when_output_closes."), \
        f"{module}.main is not guarded"
