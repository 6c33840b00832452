"""The seed pages stay true: README names every seed command that exists
and links every page, and the pages' pictures are what the tools draw."""
from __future__ import annotations

import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

from seeds import seed003, seed004
from seeds.__main__ import SUBCOMMANDS

ROOT = Path(__file__).resolve().parents[2]
PAGES = ["SEED001-DXF.md", "SEED002-URAL1.md", "SEED003-CNC-LINK.md", "SEED004-TAPE-CODES.md"]


def test_readme_links_the_pages_and_names_real_commands() -> None:
    readme = (ROOT / "README.md").read_text()
    section = readme.split("## The neighbouring systems", 1)[1].split("\n## ", 1)[0]
    for page in PAGES:
        assert f"(docs/{page})" in section and (ROOT / "docs" / page).exists()
    rows = "\n".join(line for line in section.splitlines() if line.startswith("| 00"))
    named = set(re.findall(r"`([a-z0-9]+)[ `]", rows))
    assert named and named <= set(SUBCOMMANDS), named - set(SUBCOMMANDS)
    assert {"dxf2deck", "profile", "equidistant", "punch5121", "cnclink", "split",
            "dda"} <= named


def test_pages_pictures_exist() -> None:
    for page in PAGES:
        for img in re.findall(r"\]\((img/[^)]+)\)", (ROOT / "docs" / page).read_text()):
            assert (ROOT / "docs" / img).exists(), (page, img)


def test_dda_picture_is_current() -> None:
    run = seed004.interpolate(9813, 8765, "decimal")
    assert (ROOT / "docs" / "img" / "dda-decimal.svg").read_text() == seed004.svg_plot(run)


def test_cnc_link_page_gives_the_parameter_buffers_sizes() -> None:
    """docs/SEED003-CNC-LINK.md's sizes of the parameter buffer and of its
    message, for three, four and two axes."""
    text = " ".join((ROOT / "docs" / "SEED003-CNC-LINK.md").read_text().split())
    sizes = {}
    for axes in (3, 4, 2):
        values = {**seed003.defaults(), "axes": axes}
        sizes[axes] = (len(seed003.param_buffer(values)), len(seed003.param_message(values)))
    assert (f"little-endian: {sizes[3][0]} bytes for three axes, {sizes[4][0]} for four, "
            f"{sizes[2][0]} for two.") in text
    assert (f"`parameters: {sizes[3][1]} bytes` for three axes, {sizes[4][1]} for four, "
            f"{sizes[2][1]} for two.") in text


def _sessions(text: str) -> list[tuple[str, list[str]]]:
    """(command, the lines shown after it) of each `$ python -m seeds` line."""
    out: list[tuple[str, list[str]]] = []
    fenced = session = False
    for line in text.splitlines():
        if line.startswith("```"):
            fenced, session = not fenced, False
        elif fenced and line.startswith("$ "):
            out.append((line[2:], []))
            session = True
        elif session:
            out[-1][1].append(line)
    return [s for s in out if s[0].startswith("python -m seeds ")]


def _seeds(tmp_path: Path, command: str) -> list[str]:
    """What ``python -m seeds ...`` prints (standard output, then standard
    error), run where examples/ is the project's."""
    (tmp_path / "examples").symlink_to(ROOT / "examples")
    proc = subprocess.run([sys.executable, *shlex.split(command)[1:]], cwd=tmp_path,
                          capture_output=True, text=True, timeout=120)
    return (proc.stdout + proc.stderr).splitlines()


@pytest.mark.parametrize("page", PAGES + ["GERBER.md"])
def test_the_seed_sessions_on_the_page_are_what_the_tools_print(tmp_path, page) -> None:
    """Every `$ python -m seeds ...` session of a page prints what the page
    shows (`...` stands for lines left out)."""
    found = _sessions((ROOT / "docs" / page).read_text())
    assert found or page != "SEED002-URAL1.md"
    for i, (command, want) in enumerate(found):
        here = tmp_path / str(i)
        here.mkdir()
        got = _seeds(here, command)
        if "..." in want:
            cut = want.index("...")
            head, tail = want[:cut], want[cut + 1:]
            assert got[:len(head)] == head and got[len(got) - len(tail):] == tail, \
                (page, command, got)
        else:
            assert got == want, (page, command, got)


def test_ural1_page_gives_the_contour_runs_figures(tmp_path) -> None:
    """docs/SEED002-URAL1.md's figures of Table 5 read as the contour."""
    got = "\n".join(_seeds(tmp_path, "python -m seeds ural1 examples/flange.crd -o f.5121"))
    text = " ".join((ROOT / "docs" / "SEED002-URAL1.md").read_text().split())
    sections = re.search(r": (\d+) sections", got)[1]
    path_mm, path_s = re.search(r"^path ([\d.]+) mm, ([\d.]+) s", got, re.M).groups()
    frames, rows, metres, minutes = re.search(
        r"^tape: (\d+) frames, (\d+) rows .*?, ([\d.]+) m; .*: ([\d.]+) min$", got, re.M).groups()
    assert (f"the same deck gives {sections} sections, {path_mm} mm, {path_s} s, {frames} "
            f"frames, {rows} rows, {metres} m and {minutes} minutes of punching") in text
