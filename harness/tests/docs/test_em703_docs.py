"""The em703 examples of docs/TOOLS.md and docs/TAPE.md stay true: every
`$ em703 ...` line is run in a directory holding TENZOR's output for every
deck of examples/ in `out/`, and what it prints (standard output, then
standard error) is what the page shows; a line `...` stands for lines left
out."""

from __future__ import annotations

import re
import shlex
import shutil
import subprocess
from pathlib import Path

import pytest

from harness.tests.helpers import ROOT
from harness.tape import Frame, encode


PAGES = ["docs/TOOLS.md", "docs/TAPE.md"]


def sessions(text: str) -> list[tuple[str, list[str]]]:
    """(command, expected lines) for each `$ em703` line of the page's blocks."""
    out: list[tuple[str, list[str]]] = []
    for block in re.findall(r"```\n(.*?)```", text, re.S):
        current: tuple[str, list[str]] | None = None
        for line in block.splitlines():
            if line.startswith("$ "):
                current = (line[2:], [])
                out.append(current)
            elif current is not None:
                current[1].append(line)
    return [s for s in out if s[0].startswith("em703 ")]


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
    found = sessions((ROOT / page).read_text())
    if page.endswith("TOOLS.md"):
        assert len(found) >= 10
    for command, want in found:
        args = shlex.split(command)
        proc = subprocess.run([str(em703_exe), *args[1:]], cwd=workdir, capture_output=True,
                              timeout=120)
        got = (proc.stdout + proc.stderr).decode("utf-8").splitlines()
        if "..." in want:
            cut = want.index("...")
            head, tail = want[:cut], want[cut + 1:]
            assert got[:len(head)] == head and got[len(got) - len(tail):] == tail, \
                (page, command, got)
        else:
            assert got == want, (page, command, "\n".join(got))
