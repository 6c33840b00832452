"""The em703 examples of docs/TOOLS.md and docs/TAPE.md stay true: every
`$ em703 ...` line is run in a directory holding TENZOR's output for every
deck of examples/ in `out/`, and what it prints (standard output, then
standard error) is what the page shows; a line `...` stands for lines left
out. The sizes of seed 004's three kinds of frame that TOOLS.md,
SEED004-TAPE-CODES.md and README.md quote are what `em703 gcode --dialect
iso-1970s` writes for the example jobs."""

from __future__ import annotations

import re
import shlex
import shutil
import subprocess
from pathlib import Path

import pytest

from harness.tests.helpers import ROOT, assert_session, doc_sessions, iso_programs
from harness.tape import Frame, encode


PAGES = ["docs/TOOLS.md", "docs/TAPE.md"]


@pytest.fixture(scope="module")
def workdir(examples, tmp_path_factory) -> Path:
    work = tmp_path_factory.mktemp("docs")
    (work / "out").mkdir()
    for ex in examples:
        for f in ex.out.iterdir():
            shutil.copy(f, work / "out" / f.name)
    # TOOLS.md's bad tape: DX500 K10 KK, DX-500 K20 KK with the second K punched 12
    data = bytearray(encode([Frame(dx=500, k=10), Frame(dx=-500, k=20)]))
    k = data.index(0o16, 30)
    data[k + 1:k + 3] = bytes([1, 2])
    (work / "bad.ptp").write_bytes(bytes(data))
    return work


@pytest.mark.parametrize("page", PAGES)
def test_the_examples_on_the_page_are_what_em703_prints(em703_exe, workdir, page) -> None:
    found = doc_sessions((ROOT / page).read_text(), "em703 ")
    if page.endswith("TOOLS.md"):
        assert len(found) >= 10
    for command, want in found:
        args = shlex.split(command)
        proc = subprocess.run([str(em703_exe), *args[1:]], cwd=workdir, capture_output=True,
                              timeout=120)
        assert_session((proc.stdout + proc.stderr).decode("utf-8").splitlines(), want,
                       (page, command))


def _frame_sizes(em703_exe, job: Path, frame: str) -> tuple[int, int, int]:
    """(programs, blocks, rows of tape for the blocks) of a job's seed 004
    program in frames of a kind: a row a character and one for the end of
    block; comments and % lines aside."""
    proc = subprocess.run([str(em703_exe), "gcode", "--dialect", "iso-1970s", "--frame", frame,
                           str(job)], capture_output=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    progs = iso_programs(proc.stdout.decode("ascii"))
    blocks = [b for prog in progs for b in prog]
    return len(progs), len(blocks), sum(len(b) + 1 for b in blocks)


def _number(text: str) -> int:
    return int(text.replace(" ", ""))


def test_the_sizes_of_the_three_frames_are_what_em703_writes(em703_exe, example_jobs) -> None:
    jobs = {j.stem: j for j in example_jobs}
    sizes = {name: {frame: _frame_sizes(em703_exe, jobs[name], frame)
                    for frame in ("address", "fixed", "variable")}
             for name in jobs}

    def row(name: str) -> list[int]:
        """blocks, then the rows in address, fixed and variable frames"""
        got = sizes[name]
        assert got["address"][:2] == got["fixed"][:2] == got["variable"][:2], name
        return [got["address"][1]] + [got[f][2] for f in ("address", "fixed", "variable")]

    # SEED004-TAPE-CODES.md: the table of sizes, a job named in its first cell
    page = (ROOT / "docs" / "SEED004-TAPE-CODES.md").read_text()
    head = "| program | blocks | address | fixed | variable |\n|---|---|---|---|---|\n"
    assert page.count(head) == 1
    table = page.split(head, 1)[1].split("\n\n", 1)[0].splitlines()
    assert len(table) >= 4
    for line in table:
        cells = [c.strip() for c in line.strip("|").split("|")]
        name = re.search(r"[A-Z][A-Z0-9-]*[A-Z0-9]", cells[0]).group()
        assert [_number(c) for c in cells[1:]] == row(name), (line, row(name))
    # TOOLS.md: the demo board's blocks and programs, then the same sizes in prose
    tools = re.sub(r"\s+", " ", (ROOT / "docs" / "TOOLS.md").read_text())
    m = re.search(r"The demo board's job \(([A-Z0-9-]+)\) runs (\d+) blocks: (\w+) programs", tools)
    assert m, "TOOLS.md no longer names the demo board's blocks"
    demo = m.group(1)
    words = ["one", "two", "three", "four", "five"]
    assert (_number(m.group(2)), words.index(m.group(3)) + 1) == \
        (row(demo)[0], sizes[demo]["address"][0])
    m = re.search(r"On the demo board \((\d+) blocks\), the blocks take ([\d ]+) rows of tape in "
                  r"address frames, ([\d ]+) in fixed frames, ([\d ]+) in variable ones; on "
                  r"`([A-Z0-9-]+)`, (\d+), (\d+) and (\d+)", tools)
    assert m, "TOOLS.md no longer gives the sizes of the three frames"
    assert [_number(g) for g in m.groups()[:4]] == row(demo)
    assert [_number(g) for g in m.groups()[5:]] == row(m.group(5))[1:]
    # README: a fixed frame's characters and rows
    m = re.search(r"--frame fixed: (\d+) characters \+ end of block, (\d+) rows\)",
                  (ROOT / "README.md").read_text())
    assert m, "README.md no longer gives the fixed frame's length"
    assert (int(m.group(2)) - 1, int(m.group(2))) == (int(m.group(1)), row(demo)[2] // row(demo)[0])
    assert row(demo)[2] % row(demo)[0] == 0


def test_tools_md_quotes_the_punchs_refusal(em703_exe, tmp_path) -> None:
    """The message TOOLS.md quotes for a character EIA RS-244 has not."""
    text = " ".join((ROOT / "docs" / "TOOLS.md").read_text().split())
    quoted = re.search(r"stops the punch: `(prog\.ngc: [^`]*)`", text)[1]
    (tmp_path / "prog.ngc").write_text("G00 X1\nG01 #1\n")
    proc = subprocess.run([str(em703_exe), "punch", "--code", "eia", "prog.ngc"], cwd=tmp_path,
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 1 and not list(tmp_path.glob("*.ptp"))
    assert proc.stderr.splitlines() == [quoted], proc.stderr


def test_tools_md_variable_frames_are_what_em703_writes(em703_exe, workdir) -> None:
    """TOOLS.md's EXAMPLE3 tape in variable frames (a TAB shown as an arrow):
    the numbered blocks em703 writes."""
    text = (ROOT / "docs" / "TOOLS.md").read_text()
    block = text.split("The same tape in variable frames", 1)[1].split("\n\n", 2)[1]
    quoted = [line.strip() for line in block.splitlines()]
    assert len(quoted) == 6, block
    proc = subprocess.run([str(em703_exe), "gcode", "--dialect", "iso-1970s", "--frame",
                           "variable", "out/EXAMPLE3-cond.ptp"], cwd=workdir,
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    blocks = [line.replace("\t", "\u2192") for line in proc.stdout.splitlines()
              if line[:1].isdigit()]
    assert blocks == quoted


def test_readmes_em703_commands_run(em703_exe, workdir, tmp_path) -> None:
    """Every `fpm run em703 -- ...` line of README.md's block of em703
    commands runs, in order, on the demo's files, and exits 0."""
    readme = (ROOT / "README.md").read_text()
    block = readme.split("## The em703 tools", 1)[1].split("```sh\n", 1)[1].split("```", 1)[0]
    lines = [line.split("#", 1)[0].split() for line in block.splitlines()
             if line.startswith("fpm run em703 -- ")]
    assert len(lines) >= 15, block
    here = tmp_path / "readme"
    shutil.copytree(workdir, here)
    for words in lines:
        proc = subprocess.run([str(em703_exe), *words[4:]], cwd=here, capture_output=True,
                              timeout=120)
        assert proc.returncode == 0, (" ".join(words), proc.stderr.decode("utf-8", "replace"))


def test_tools_md_headings_are_the_usage_lines(em703_exe) -> None:
    """Each `## em703 SUB ...` heading of docs/TOOLS.md is the usage line
    `em703 SUB --help` prints (its continuation lines joined), and every
    subcommand `em703 --help` lists has one."""
    text = (ROOT / "docs" / "TOOLS.md").read_text()
    headings = [line[3:] for line in text.splitlines() if line.startswith("## em703 ")]
    top = subprocess.run([str(em703_exe), "--help"], capture_output=True, text=True,
                         timeout=60).stdout
    subs = sorted({m for m in re.findall(r"^  ([a-z]+) ", top, re.M)})
    assert len(subs) >= 11 and sorted(h.split()[1] for h in headings) == subs, (subs, headings)
    # the list's entries name the same options as the headings
    entries = re.split(r"\n(?=  [a-z-])", top.split("\n\n", 2)[2].split("\n\n")[0])
    for entry in entries:
        heading = next((h for h in headings if h.split()[1] == entry.split()[0]), None)
        if heading is not None:
            options = set(re.findall(r"(?<![\w-])--?[a-z][a-z0-9-]*", entry))
            assert options == set(re.findall(r"(?<![\w-])--?[a-z][a-z0-9-]*", heading)), entry
    for heading in headings:
        got = subprocess.run([str(em703_exe), heading.split()[1], "--help"],
                             capture_output=True, text=True, timeout=60).stdout
        usage = got.split("\n\n", 1)[0]
        assert usage.startswith("usage: "), got
        assert " ".join(usage[len("usage: "):].split()) == heading
