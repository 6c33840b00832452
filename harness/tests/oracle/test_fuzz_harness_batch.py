"""``python -m harness decode`` and ``verify`` on hostile tapes and decks, in
process, in bulk (docs/ROBUSTNESS.md): random bytes, mutated valid tapes of
both codes, and for verify a random board's deck (now and then mutated)
with such tapes. Whatever it is given, the command returns 0, 1 or 2,
raises nothing, and says why on standard error when it returns non-zero
(decode names the row, verify prints FAIL with its reasons).
"""
from __future__ import annotations

import contextlib
import io
import random

import pytest

from harness.__main__ import main
from harness.tests import hostile

#: kind -> (chunks, inputs a chunk); verify rasterises, about 0.1 s an input
KINDS = {"decode": (8, 100), "verify": (1, 60)}
PLAN = [(kind, n) for kind, (k, _) in KINDS.items() for n in range(k)]


def _tape(r: random.Random) -> bytes:
    what = r.random()
    if what < 0.3:
        return bytes(b & 31 for b in hostile.random_bytes(r, 600))
    if what < 0.4:
        return hostile.random_bytes(r, 600)
    if what < 0.5:
        return hostile.valid_tape(r)
    return hostile.mutated_tape(r, hostile.valid_tape(r))


@pytest.mark.hostile
@pytest.mark.parametrize("kind,n", PLAN, ids=[f"{k}-{n}" for k, n in PLAN])
def test_hostile_tapes(tmp_path, kind, n):
    seed = 4000 + 100 * list(KINDS).index(kind) + n
    r = random.Random(seed)
    size = KINDS[kind][1]
    for i in range(size):
        here = tmp_path / f"case{i}"
        here.mkdir()
        if kind == "decode":
            (here / "t.ptp").write_bytes(_tape(r))
            argv = ["decode", str(here / "t.ptp"), "--code", r.choice(["8", "K", "auto"])]
        else:
            body = hostile.random_board(r)
            if r.random() < 0.2:
                body = hostile.guard(hostile.mutated_body(r, body))
            deck = "\n".join(["B", *body, "E"]) + "\n"
            (here / "b.crd").write_text(deck, encoding="latin-1")
            for t in ("small", "large", "cond"):
                if r.random() < 0.9:
                    (here / f"B-{t}.ptp").write_bytes(_tape(r))
            argv = ["verify", str(here / "b.crd"), str(here)]
            if r.random() < 0.2:
                argv += ["--tolerance", r.choice(["0", "-1", "nan", "inf", "1e9", "x", "0.05"])]
        out, err = io.StringIO(), io.StringIO()
        try:
            with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
                status = main(argv)
        except BaseException as exc:               # noqa: BLE001: any escape is the failure
            raise AssertionError(f"seed {seed}, input {i}: {argv} raised "
                                 f"{type(exc).__name__}: {exc}") from exc
        assert status in (0, 1, 2), (seed, i, status)
        if status:
            assert err.getvalue().strip() or "FAIL" in out.getvalue(), \
                f"seed {seed}, input {i}: {argv} returned {status} without a reason"
    hostile.count("harness " + kind, size)
