"""em703 on thousands of hostile inputs a CI run (docs/ROBUSTNESS.md).

em703 reads one tape (or one job sheet, or one text) a run, so a hostile
input here is one process start per subcommand; a start costs about a
millisecond, and the inputs come from ``random.Random(seed)``, not from
hypothesis, so a chunk of a hundred inputs takes about a second. Every run
is held to the promises of test_fuzz_em703.em: exit 0, 1 or 2, never a
signal, no Fortran run-time message, a message for every non-zero exit,
no temporary or partial file.

Inputs (each counted once, whatever number of subcommands read it):
random bytes and mutated valid tapes (the examples' tapes and random frame
lists, both codes) through list, list --code K, view, sim --svg and gcode -o;
mutated job sheets through svg, gerber and gcode; random texts through
punch --code iso and eia; random argument lists through split.
"""
from __future__ import annotations

import random

import pytest

from harness.tests import hostile
from harness.tests.em703.test_fuzz_em703 import em, fresh
from harness.tests.helpers import write_job

CHUNK = 100
#: chunks (of CHUNK inputs) of each kind
CHUNKS = {"tape-bytes": 5, "tape-mutated": 9, "job": 4, "punch": 4, "split": 3}
PLAN = [(kind, n) for kind, k in CHUNKS.items() for n in range(k)]


def _seed(kind: str, n: int) -> int:
    return 2000 + 100 * list(CHUNKS).index(kind) + n


def tape_users(exe, here, data: bytes, where: str) -> None:
    (here / "t.ptp").write_bytes(data)
    try:
        for args in (["list", "t.ptp"], ["list", "--code", "K", "t.ptp"], ["view", "t.ptp"]):
            em(exe, here, *args)
        em(exe, here, "sim", "t.ptp", "--svg", "t.svg", out="t.svg")
        em(exe, here, "gcode", "t.ptp", "-o", "t.ngc", out="t.ngc")
    except AssertionError as exc:
        raise AssertionError(f"{where}: {exc}") from None


@pytest.mark.hostile
@pytest.mark.parametrize("kind,n", PLAN, ids=[f"{k}-{n}" for k, n in PLAN])
def test_hostile_inputs(em703_exe, example_tapes, tmp_path, kind, n):
    seed = _seed(kind, n)
    r = random.Random(seed)
    bases = [p.read_bytes() for p in example_tapes]
    for i in range(CHUNK):
        here = fresh(tmp_path)
        where = f"seed {seed}, input {i}"
        if kind == "tape-bytes":
            data = hostile.random_bytes(r, 1500)
            if r.random() < 0.5:                 # mostly rows of the 5-track code
                data = bytes(b & 31 for b in data)
            tape_users(em703_exe, here, data, where)
        elif kind == "tape-mutated":
            base = r.choice(bases) if r.random() < 0.5 else hostile.valid_tape(r)
            tape_users(em703_exe, here, hostile.mutated_tape(r, base), where)
        elif kind == "job":
            tapes = {k: hostile.valid_tape(r) for k in ("small", "cond")}
            job = write_job(here, "T", tapes, {"small": "0.40"}, code=r.choice("8K"))
            job.write_bytes(hostile.mutated_job(r, job.read_text()))
            for sub, ext in (("svg", "svg"), ("gerber", "gbr"), ("gcode", "ngc")):
                try:
                    em(em703_exe, here, sub, "T.job", "-o", f"out.{ext}", out=f"out.{ext}")
                except AssertionError as exc:
                    raise AssertionError(f"{where}: {exc}") from None
        elif kind == "punch":
            if r.random() < 0.5:
                text = hostile.random_bytes(r, 2000)
            else:                                # G-code-like lines, now and then broken
                text = "".join(f"N{k} G0{r.randint(0, 3)} X{r.uniform(-1e3, 1e3):.3f}"
                               f"{hostile.random_text(r, 3) if r.random() < 0.2 else ''}\n"
                               for k in range(r.randint(0, 40))).encode("utf-8")
            (here / "p.txt").write_bytes(text)
            code = r.choice(["iso", "eia"])
            try:
                em(em703_exe, here, "punch", "--code", code, "-o", "p.ptp", "p.txt", out="p.ptp")
            except AssertionError as exc:
                raise AssertionError(f"{where}: {exc}") from None
        else:
            args = [hostile.number_word(r) for _ in range(r.randint(0, 4))]
            if r.random() < 0.6:
                args[r.randint(0, len(args)):r.randint(0, len(args))] = ["--max",
                                                                        hostile.number_word(r)]
            try:
                em(em703_exe, here, "split", *args)
            except AssertionError as exc:
                raise AssertionError(f"{where}: {exc}") from None
    hostile.count("em703", CHUNK)
