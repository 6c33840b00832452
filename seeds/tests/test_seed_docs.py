"""The seed pages stay true: README names every seed command that exists
and links every page, and the pages' pictures are what the tools draw."""
from __future__ import annotations

import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

from harness.tests.helpers import assert_session, doc_sessions
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
    found = doc_sessions((ROOT / "docs" / page).read_text(), "python -m seeds ")
    assert found or page != "SEED002-URAL1.md"
    for i, (command, want) in enumerate(found):
        here = tmp_path / str(i)
        here.mkdir()
        assert_session(_seeds(here, command), want, (page, command))


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


#: The rows of SEED004-TAPE-CODES.md's table of deviations: (method, size,
#: fixed ratio) of each value of a cell ("a / b": two sizes).
_DEVIATION_ROWS = {
    "binary, 14 bits (16 384)": [("binary", None, False)],
    "decimal, 4 decades (10 000)": [("decimal", None, False)],
    "integrator, 16 384 / 10 000": [("integrator", None, False), ("integrator", 10000, False)],
    "counter, 16 384 / 10 000": [("counter", None, False), ("counter", 10000, False)],
    "counter `--fixed-ratio`, 16 384 / 10 000": [("counter", None, True),
                                                 ("counter", 10000, True)],
}


def test_tape_codes_page_deviation_table_is_what_dda_computes() -> None:
    """Every cell of the table (the first frame; the long move split at 9999)."""
    text = (ROOT / "docs" / "SEED004-TAPE-CODES.md").read_text()
    rows = {}
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip("|").split("|")]
        if len(cells) == 3 and cells[0] in _DEVIATION_ROWS:
            rows[cells[0]] = (cells[1].split(" / "), cells[2].split(" / "))
    assert rows.keys() == _DEVIATION_ROWS.keys()
    for label, runs in _DEVIATION_ROWS.items():
        for k, (method, size, fixed) in enumerate(runs):
            first = seed004.interpolate(*seed004.DOCUMENT_TABLE[0], method, size,
                                        fixed_ratio=fixed)
            split = seed004.interpolate(*seed004.DOCUMENT_MOVE, method, size, max_pulses=9999,
                                        fixed_ratio=fixed)
            assert (rows[label][0][k], rows[label][1][k]) == \
                (f"{first.max_deviation:.3f}", f"{split.max_deviation:.3f}"), label


def test_quoted_messages_are_the_tools(tmp_path) -> None:
    """The messages SEED001-DXF.md, SEED002-URAL1.md and SEED003-CNC-LINK.md
    quote, and README's split | punch5121 pipeline's ten frames."""
    dxf = " ".join((ROOT / "docs" / "SEED001-DXF.md").read_text().split())
    (tmp_path / "board.dxf").symlink_to(ROOT / "examples" / "dxf" / "board.dxf")
    got = subprocess.run([sys.executable, "-m", "seeds", "dxf2deck", "board.dxf", "-o", "b.crd"],
                         cwd=tmp_path, capture_output=True, text=True, timeout=120).stderr
    quoted = re.search(r"`(dxf2deck: board\.dxf: ELLIPSE [^`]*)`", dxf)[1]
    assert quoted in got.splitlines(), (quoted, got)

    cnc = " ".join((ROOT / "docs" / "SEED003-CNC-LINK.md").read_text().split())
    quoted = re.search(r"paper's `(ошибка вывода [^`]*)`", cnc)[1]
    got = subprocess.run([sys.executable, "-m", "seeds", "cnclink", "examples/flange.crd",
                          "--corrupt", "1"], cwd=ROOT, capture_output=True, text=True,
                         timeout=120).stderr.splitlines()[-1]
    pattern = re.escape(quoted).replace("N", r"\d+").replace("M", r"\d+")
    assert re.fullmatch("cnclink: " + pattern, got), (quoted, got)

    ural = " ".join((ROOT / "docs" / "SEED002-URAL1.md").read_text().split())
    quoted = re.search(r"`(package NOTCH: [^`]*)`", ural)[1]
    from seeds.tests.test_seed002 import NOTCH     # its card 7 the slot's floor, 1 mm
    (tmp_path / "notch.crd").write_text(NOTCH)
    got = subprocess.run([sys.executable, "-m", "seeds", "equidistant", "notch.crd", "--cutter",
                          "4"], cwd=tmp_path, capture_output=True, text=True, timeout=120).stderr
    assert got == f"equidistant: notch.crd: {quoted}\n", (quoted, got)

    readme = " ".join((ROOT / "README.md").read_text().split())
    assert "split --max 9999 98132 87647 | python -m seeds punch5121 - -o out/move.ptp` splits " \
           "seed 004's long move into its ten frames" in readme
    split = subprocess.run([sys.executable, "-m", "seeds", "split", "--max", "9999", "98132",
                            "87647"], capture_output=True, text=True, timeout=120)
    (tmp_path / "out").mkdir()
    punch = subprocess.run([sys.executable, "-m", "seeds", "punch5121", "-", "-o",
                            "out/move.ptp"],
                           input=split.stdout, cwd=tmp_path, capture_output=True, text=True,
                           timeout=120)
    assert punch.returncode == 0, punch.stderr
    back = subprocess.run([sys.executable, "-m", "seeds", "punch5121", "--decode",
                           "out/move.ptp"],
                          cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert len(back.stdout.splitlines()) == 10, back.stdout


def test_readmes_table_gives_only_options_the_commands_have() -> None:
    """Each option README's table of the neighbouring systems gives a command
    (`--drop/--noise/--corrupt N,...` is three) is one its parser takes."""
    from seeds.__main__ import build_parser
    readme = (ROOT / "README.md").read_text()
    section = readme.split("## The neighbouring systems", 1)[1].split("\n## ", 1)[0]
    sub = next(a for a in build_parser()._actions if a.choices and "dxf2deck" in a.choices)
    checked = 0
    for row in (line for line in section.splitlines() if line.startswith("| ")):
        for usage in re.findall(r"`([a-z0-9]+ [^`]*)`", row):
            name = usage.split()[0]
            if name not in sub.choices:
                continue
            have = {o for a in sub.choices[name]._actions for o in a.option_strings}
            for option in re.findall(r"--[a-z0-9-]+", usage):
                assert option in have, (name, option, sorted(have))
                checked += 1
    assert checked >= 25, checked


def test_command_lines_on_the_pages_run_as_written() -> None:
    """A command line shown on a seed page is run with `python -m seeds`
    (GERBER.md showed `gerber2deck COPPER.gbr ...`, which is no program on
    the PATH of a checkout)."""
    for page in PAGES + ["GERBER.md"]:
        text = (ROOT / "docs" / page).read_text()
        for block in re.findall(r"```sh\n(.*?)```", text, re.S):
            for line in block.splitlines():
                first = line.split()[0] if line.strip() else ""
                assert first not in SUBCOMMANDS, (page, line)
