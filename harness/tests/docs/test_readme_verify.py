"""README's session with `verify` is true as written: the demo's tapes punched,
copied, two rows damaged with dd, and the verdict printed word for word.

The session is replayed from README.md itself: `make demo` runs the tenzor
under test on the demo deck, `cp -r` copies, `rm` removes, each `printf '\\OOO' | dd ...`
line writes its one byte at its offset, and the `verify` line runs the
oracle; what it prints must be the lines that follow in README.md.
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]

pytestmark = pytest.mark.tenzor


def _session() -> tuple[list[str], list[str]]:
    """The commands (without `$ `) and the printed lines of README's session."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    block = re.search(r"```\n(\$ make demo\n.*?)```", text, re.S)
    assert block, "README.md has no shell session starting with `$ make demo`"
    lines = block.group(1).splitlines()
    commands = [line[2:] for line in lines if line.startswith("$ ")]
    printed = [line for line in lines if not line.startswith("$ ")]
    return commands, printed


def test_readme_verify_session_prints_what_readme_says(tenzor_exe, tmp_path):
    commands, printed = _session()
    shutil.copytree(ROOT / "examples", tmp_path / "examples")
    result = None
    for command in commands:
        if command == "make demo":
            subprocess.run([str(tenzor_exe), "examples/demo.crd", "-o", "out"],
                           cwd=tmp_path, check=True, capture_output=True)
        elif m := re.fullmatch(r"cp -r (\S+) (\S+)", command):
            shutil.copytree(tmp_path / m[1], tmp_path / m[2])
        elif m := re.fullmatch(r"rm (\S+)", command):
            (tmp_path / m[1]).unlink()
        elif m := re.fullmatch(r"printf '\\([0-7]{3})' \| dd of=(\S+) bs=1 "
                               r"seek=([0-9]+) conv=notrunc status=none", command):
            path = tmp_path / m[2]
            data = bytearray(path.read_bytes())
            data[int(m[3])] = int(m[1], 8)
            path.write_bytes(bytes(data))
        elif command.startswith("python -m harness verify "):
            env = dict(os.environ, PYTHONPATH=str(ROOT))
            result = subprocess.run([sys.executable, "-m", "harness", *command.split()[3:]],
                                    cwd=tmp_path, env=env, capture_output=True, text=True)
        else:
            pytest.fail(f"README's session has a command this test cannot replay: {command}")
    assert result is not None, "README's session never runs verify"
    assert result.returncode == 1, result.stderr
    assert result.stdout.splitlines() == printed
