"""`python -m harness verify DECK TAPEDIR`: PASS on TENZOR's own tapes, and
FAIL with the right reason (and card, frame or row) on tapes broken on
purpose by editing their frames with harness.tape."""
from __future__ import annotations

import math
import os
import shutil
import subprocess
import sys
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from harness import cards, raster, tape, verify
from harness.__main__ import main
from harness.deck import parse_deck
from harness.shapes import ArcBand, Stroke, distinct_strokes
from harness.tape import Frame
from harness.tests.strategies import frame_lists

ROOT = Path(__file__).resolve().parents[3]
EXAMPLES = sorted((ROOT / "examples").glob("**/*.crd"))

# A board with one of everything (cards numbered from 1):
#  3 a round pad, 4 a rectangular pad (large-pad tape), 5 a row of three pads,
#  6-8 a 1.5 mm conductor (two loops of the 0.5 mm tool), 9-10 a 0.5 mm
#  conductor (one pass), 11 a circle, 12 an arc.


def board_deck(code: str = "8") -> str:
    return cards.deck([cards.CardPackage("BOARD", [
        cards.p_card(5000, 5000, 40, 100, 50, 200, None, code, "D"),
        cards.d_card(1000, 1000, 160),
        cards.d_card(2000, 1000, 300, 200),
        cards.d_card(1000, 2000, 160, None, 3, 250, 0),
        cards.l_card(1000, 3000, 150), cards.plus_card(3000, 3000), cards.plus_card(3000, 4000),
        cards.l_card(4000, 1000), cards.plus_card(4000, 3000),
        cards.o_card("+", 2000, 5000, 300),
        cards.a_card("-", 4000, 5000, 4500, 5000, 4000, 5500)])], envelope=False)


BOARD = board_deck()


@pytest.fixture(scope="module")
def board(tenzor_exe, tmp_path_factory) -> Path:
    """TENZOR's tapes of BOARD."""
    base = tmp_path_factory.mktemp("board")
    (base / "board.crd").write_text(BOARD)
    proc = subprocess.run([tenzor_exe, base / "board.crd", "-o", base / "tapes"],
                          capture_output=True, timeout=120)
    assert proc.returncode == 0, proc.stderr.decode()
    return base / "tapes"


# ---------------------------------------------------------------------------
# Editing tapes.
# ---------------------------------------------------------------------------
def starts(frames: list[Frame]) -> list[tuple[int, int]]:
    """The tool position at the start of each frame (first repetition of
    a cycle)."""
    out = []
    x = y = 0
    i = 0
    while i < len(frames):
        f = frames[i]
        out.append((x, y))
        if f.cyc:
            g = frames[i + 1]
            out.append((x + f.dx, y + f.dy))
            x, y = x + f.cyc * (f.dx + g.dx), y + f.cyc * (f.dy + g.dy)
            i += 2
        else:
            x, y = x + f.dx, y + f.dy
            i += 1
    return out


def block(frames: list[Frame], box: tuple[int, int, int, int]) -> list[int]:
    """Indices of the drawing frames (not K20, not in a cycle) that start in
    the box (units: xmin, xmax, ymin, ymax)."""
    cycled = {i + j for i, f in enumerate(frames) if f.cyc for j in (0, 1)}
    return [i for i, (x, y) in enumerate(starts(frames))
            if frames[i].k != 20 and i not in cycled
            and box[0] <= x <= box[1] and box[2] <= y <= box[3]]


def shrink_circle(frames: list[Frame], i: int, by: int) -> None:
    """Make the full circle of frame i smaller by ``by`` units about the same
    centre; the straight frames before and after it take up the shift."""
    f = frames[i]
    r = math.hypot(f.x, f.y)
    nx, ny = round(f.x * (r - by) / r), round(f.y * (r - by) / r)
    sx, sy = nx - f.x, ny - f.y
    before, after = frames[i - 1], frames[i + 1]
    assert before.k in (10, 20) and after.k in (10, 20) and not (before.cyc or after.cyc)
    frames[i - 1] = replace(before, dx=before.dx + sx, dy=before.dy + sy)
    frames[i] = replace(f, x=nx, y=ny)
    frames[i + 1] = replace(after, dx=after.dx - sx, dy=after.dy - sy)


def drop_pad(frames: list[Frame]) -> None:
    """Card 3, the round pad at (10, 10) mm: its frames become one raised move."""
    idx = block(frames, (900, 1100, 900, 1100))
    assert idx and idx == list(range(idx[0], idx[-1] + 1))
    dx = sum(frames[i].dx for i in idx)
    dy = sum(frames[i].dy for i in idx)
    frames[idx[0]:idx[-1] + 1] = [Frame(dx=dx, dy=dy, k=20)]


def outer_pass(frames: list[Frame]) -> int:
    """Card 3's outer circle."""
    idx = [i for i in block(frames, (900, 1100, 900, 1100))
           if frames[i].k in (11, 13) and not (frames[i].dx or frames[i].dy)]
    return max(idx, key=lambda i: math.hypot(frames[i].x, frames[i].y))


def shrink_pad(frames: list[Frame]) -> None:
    shrink_circle(frames, outer_pass(frames), 15)


def grow_pad(frames: list[Frame]) -> None:
    shrink_circle(frames, outer_pass(frames), -15)


def drop_rect(frames: list[Frame]) -> None:
    """Card 4, the 3 x 2 mm pad at (20, 10) mm: its frames go, a raised move
    keeps the rest in place."""
    idx = block(frames, (1850, 2150, 900, 1100))
    assert idx
    dx = sum(frames[i].dx for i in idx)
    dy = sum(frames[i].dy for i in idx)
    frames[idx[0]:idx[-1] + 1] = [Frame(dx=dx, dy=dy, k=20)] if (dx or dy) else []


def drop_outer_loop(frames: list[Frame]) -> None:
    """Card 6, the 1.5 mm conductor drawn in two loops with the 0.5 mm tool:
    the outer loop (its round ends have radius 0.50 mm) is left out."""
    idx = block(frames, (900, 3100, 2900, 4100))
    arcs = [i for i in idx if frames[i].k in (11, 13) and math.hypot(frames[i].x, frames[i].y) == 50]
    loops = [(hi - lo, lo, hi) for lo in range(idx[0], min(arcs) + 1)
             for hi in range(max(arcs), idx[-1] + 1)
             if sum(frames[i].dx for i in range(lo, hi + 1)) == 0
             and sum(frames[i].dy for i in range(lo, hi + 1)) == 0]
    assert loops, "the outer loop does not close"
    _, lo, hi = min(loops)
    del frames[lo:hi + 1]


def break_conductor(frames: list[Frame]) -> None:
    """Card 9, the 0.5 mm conductor from (40, 10) to (40, 30) mm: 1 mm of its
    single pass is travelled raised."""
    (i,) = [i for i, (x, _) in enumerate(starts(frames))
            if frames[i].k == 10 and x == 4000 and abs(frames[i].dy) == 2000]
    s = 1 if frames[i].dy > 0 else -1
    frames[i:i + 1] = [Frame(dy=s * 900, k=10), Frame(dy=s * 100, k=20), Frame(dy=s * 1000, k=10)]


def shrink_o_circle(frames: list[Frame]) -> None:
    """Card 11, the circle of radius 3 mm: drawn 0.15 mm smaller."""
    (i,) = [i for i, f in enumerate(frames) if f.k in (11, 13) and not (f.dx or f.dy)
            and math.hypot(f.x, f.y) == 300]
    shrink_circle(frames, i, 15)


def stray_line(frames: list[Frame]) -> None:
    """A 5 mm line from the start point, where the deck has nothing."""
    frames[0:0] = [Frame(dx=500, k=10), Frame(dx=-500, k=20)]


def drop_return(frames: list[Frame]) -> None:
    assert frames[-1].k == 20
    del frames[-1]


def leave_field(frames: list[Frame]) -> None:
    """Out 60 mm to the left and back, raised: X0 is 50 mm."""
    frames[0:0] = [Frame(dx=-6000, k=20), Frame(dx=6000, k=20)]


# (id, tape, edit, kind, card, frame) -- frame is the 1-based frame named
BROKEN: list[tuple[str, str, Callable[[list[Frame]], None], str, int | None, int | None]] = [
    ("pad-missing", "small", drop_pad, "pad-missing", 3, None),
    ("pad-too-small", "small", shrink_pad, "pad-size", 3, None),
    ("pad-too-large", "small", grow_pad, "pad-size", 3, None),
    ("rect-pad-missing", "large", drop_rect, "pad-missing", 4, None),
    ("conductor-too-narrow", "cond", drop_outer_loop, "conductor-narrow", 6, None),
    ("conductor-broken", "cond", break_conductor, "conductor-broken", 9, None),
    ("stray-line", "cond", stray_line, "excess", None, 1),
    ("no-return-frame", "cond", drop_return, "not-at-start", None, None),
    ("leaves-the-field", "cond", leave_field, "field", None, 1),
]


def edited(board: Path, tmp_path: Path, layer: str,
           edit: Callable[[list[Frame]], bytes | None]) -> Path:
    """A copy of the board's tapes with one tape's frames edited, as another
    program would punch them: without TENZOR's job sheet, whose checksums
    would no longer hold (test_a_tape_that_is_not_the_job_sheets_is_refused)."""
    out = tmp_path / "tapes"
    shutil.copytree(board, out)
    (out / "BOARD.job").unlink()
    path = out / f"BOARD-{layer}.ptp"
    t = tape.decode(path.read_bytes())
    frames = list(t.frames)
    edit(frames)
    path.write_bytes(tape.encode(frames, t.code))
    return out


# ---------------------------------------------------------------------------
# PASS.
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("deck", EXAMPLES, ids=[str(p.relative_to(ROOT)) for p in EXAMPLES])
def test_tenzor_tapes_of_the_examples_pass(run_tenzor, deck: Path) -> None:
    proc, out = run_tenzor(deck)
    assert proc.returncode == 0, proc.stderr.decode()
    v = verify.verify(deck.read_text(), out)
    assert v.passed, v.text()
    assert v.text().endswith("PASS\n")
    assert len(v.packages) >= 1 and all(len(p.tapes) == 3 for p in v.packages)


def test_board_passes_and_the_listing_names_each_tape(board: Path) -> None:
    v = verify.verify(BOARD, board, deck_name="board.crd")
    text = v.text()
    assert v.passed, text
    lines = text.splitlines()
    assert lines[0] == f"verify board.crd against {board} (tolerance 0.05 mm)"
    assert lines[1] == ("package BOARD (card 1): scale 1:1, start point at 50.00, 50.00 mm "
                        "on the field")
    assert lines[2].startswith("  ok   BOARD-small.ptp  (small pads; code 8, ")
    assert lines[2].endswith(" rows, tool 0.40 mm)")
    assert lines[-1] == "PASS"


def test_another_implementations_tape_passes(tmp_path: Path) -> None:
    """The check knows nothing of TENZOR's way of filling: a pad drawn from
    the outside in, with a short leader and no trailer, passes."""
    deck = ("ONE\nP              50.00     50.00    0.40\n"
            "D              10.00     10.00    1.60\nE\n")
    frames = [Frame(dx=1060, dy=1000, k=20), Frame(x=60, k=13), Frame(dx=-20, k=10),
              Frame(x=40, k=13), Frame(dx=-20, k=10), Frame(x=20, k=13),
              Frame(dx=-1020, dy=-1000, k=20)]
    (tmp_path / "ONE-small.ptp").write_bytes(tape.encode(frames, "K", leader=3)[:-3])
    for layer in ("large", "cond"):
        (tmp_path / f"ONE-{layer}.ptp").write_bytes(tape.encode([], "8", leader=0))
    v = verify.verify(deck, tmp_path)
    assert v.passed, v.text()
    # ... and the same tape with its outer circle a little too small fails
    frames[0:3] = [Frame(dx=1045, dy=1000, k=20), Frame(x=45, k=13), Frame(dx=-5, k=10)]
    (tmp_path / "ONE-small.ptp").write_bytes(tape.encode(frames, "K"))
    v = verify.verify(deck, tmp_path)
    assert [(r.kind, r.card) for r in v.reasons] == [("pad-size", 3)], v.text()
    assert "drawn too small" in v.text()


#: A round 1.60 mm pad at (10, 10) mm (card 3) and its tape drawn from the
#: outside in with the 0.40 mm tool, as in the test above.
ONE_FRAMES = [Frame(dx=1060, dy=1000, k=20), Frame(x=60, k=13), Frame(dx=-20, k=10),
              Frame(x=40, k=13), Frame(dx=-20, k=10), Frame(x=20, k=13),
              Frame(dx=-1020, dy=-1000, k=20)]


def one_pad(tmp_path: Path, small: list[Frame], scale: tuple[int, int] | None = None,
            pad: tuple[int, int, int] = (1000, 1000, 160)) -> verify.Verdict:
    """verify of a one-pad deck (start point at 50, 50 mm) against the given
    small-pad tape and empty large-pad and conductor tapes."""
    deck = cards.deck([cards.CardPackage("ONE", [cards.p_card(5000, 5000, 40, scale=scale),
                                                 cards.d_card(*pad)])], envelope=False)
    here = tmp_path / f"v{len(list(tmp_path.iterdir()))}"
    here.mkdir()
    (here / "ONE-small.ptp").write_bytes(tape.encode(small))
    for layer in ("large", "cond"):
        (here / f"ONE-{layer}.ptp").write_bytes(tape.encode([]))
    return verify.verify(deck, here)


def test_a_tape_that_ends_at_its_start_point_with_the_tool_down_fails(tmp_path) -> None:
    """The start point's own pad, 0.40 mm, drawn by one dot of the 0.40 mm
    tool: the drawing is right, but the tape must end raised."""
    at_start = (0, 0, 40)
    v = one_pad(tmp_path, [Frame(k=10)], pad=at_start)
    assert [r.kind for r in v.reasons] == ["not-at-start"], v.text()
    assert v.reasons[0].message == ("does not end raised at its start point: it ends at "
                                    "(0.00, 0.00) mm from it with the tool down")
    v = one_pad(tmp_path, [Frame(k=10), Frame(k=20)], pad=at_start)
    assert v.passed, v.text()


@pytest.mark.parametrize("scale, stray", [(None, 4000), ((1, 2), 9000)])
def test_a_stray_dot_far_from_the_deck_but_on_the_field_is_found(tmp_path, scale,
                                                                  stray) -> None:
    """The start point is 50 mm from the field's left edge: a dot drawn 40 mm
    left of it (90 mm at scale 1:2, 45 mm on the field) is on the field, far
    from the deck's only pad, and is excess, named by its frame."""
    assert one_pad(tmp_path, ONE_FRAMES, scale).passed
    frames = [Frame(dx=-stray, dy=1000, k=20), Frame(k=10), Frame(dx=stray, dy=-1000, k=20),
              *ONE_FRAMES]
    v = one_pad(tmp_path, frames, scale)
    assert [(r.kind, r.frame) for r in v.reasons] == [("excess", 2)], v.text()
    assert f"farthest at (-{stray // 100 + 0.2:.2f}, " in v.reasons[0].message


def test_stray_frames_beyond_the_listed_ones_are_counted(tmp_path) -> None:
    """17 stray dots: 15 are listed, the other 2 counted in the verdict."""
    frames = [Frame(dy=3000, k=20)] + [Frame(k=10), Frame(dx=100, k=20)] * 17 \
        + [Frame(dx=-1700, dy=-3000, k=20)] + ONE_FRAMES
    v = one_pad(tmp_path, frames)
    assert [(r.kind, r.frame) for r in v.reasons] == [("excess", 2 + 2 * i) for i in range(15)]
    assert v.count == 17 and not v.passed
    assert "       ... and 2 more reasons like these\n" in v.text()
    assert v.text().endswith("FAIL: 17 reasons\n")


def test_controlled_code_is_detected(run_tenzor) -> None:
    deck = board_deck("K")
    proc, out = run_tenzor(deck)
    assert proc.returncode == 0
    v = verify.verify(deck, out)
    assert v.passed, v.text()
    assert "code K" in v.text()


# ---------------------------------------------------------------------------
# FAIL, each reason.
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("layer,edit,kind,card,frame", [b[1:] for b in BROKEN],
                         ids=[b[0] for b in BROKEN])
def test_broken_tape_fails_with_its_reason(board, tmp_path, layer, edit, kind, card, frame):
    out = edited(board, tmp_path, layer, edit)
    v = verify.verify(BOARD, out)
    assert not v.passed
    reasons = v.reasons
    assert {r.tape for r in reasons} == {f"BOARD-{layer}.ptp"}, v.text()
    assert [r.kind for r in reasons] == [kind], v.text()
    (r,) = reasons
    assert r.card == card and r.frame == frame, v.text()
    if card:
        assert r.message.startswith(f"card {card} ("), r.message
    if frame:
        assert r.message.startswith(f"frame {frame} (row "), r.message
    assert v.text().endswith("FAIL: 1 reason\n")
    assert f"  FAIL BOARD-{layer}.ptp" in v.text()


@pytest.mark.parametrize("name", ["BOARD-cond.ptp", "BOARD-small.txt", "BOARD.lst"])
def test_a_file_that_is_not_the_job_sheets_is_refused(board, tmp_path, name) -> None:
    """A package whose files are not the ones its job sheet records (two
    runs mixed, a file edited after the run): verify gives no verdict."""
    out = tmp_path / "tapes"
    shutil.copytree(board, out)
    with open(out / name, "ab") as f:
        f.write(b"\0")
    with pytest.raises(verify.VerifyError, match=f"{name}: not the file the job sheet "
                       f".*BOARD.job records .*: the package holds files of different runs"):
        verify.verify(BOARD, out)
    deck = tmp_path / "deck.crd"
    deck.write_text(BOARD)
    assert main(["verify", str(deck), str(out)]) == 2


@pytest.mark.parametrize("text, line, shown", [
    (bytes(range(200, 250)), 1, '"\\xc8\\xc9'),
    (b"# a job sheet\nname = BOARD\nscale: 1:1\n", 3, '"scale: 1:1")'),
])
def test_a_job_sheet_that_cannot_be_read_is_refused(board, tmp_path, text, line,
                                                    shown) -> None:
    """A NAME.job beside the tapes that is no job sheet is not passed over:
    its files could not be checked against it."""
    out = tmp_path / "tapes"
    shutil.copytree(board, out)
    (out / "BOARD.job").write_bytes(text)
    with pytest.raises(verify.VerifyError) as info:
        verify.verify(BOARD, out)
    message = str(info.value)
    assert message.startswith(f"{out / 'BOARD.job'}: line {line}: not a 'key = value' line of "
                              f"a job sheet ({shown}"), message
    assert message.endswith("remove or rename it to verify the tapes alone")


def test_messages_say_what_and_where(board, tmp_path) -> None:
    cases = {
        "small": (drop_pad, "card 3 (D): round 1.60 mm pad at (10.00, 10.00) mm: missing, "
                            "nothing drawn inside it"),
        "cond": (stray_line, "frame 1 (row 22, DX500 K10 KK) draws where the deck holds "
                             "nothing: "),
    }
    for layer, (edit, text) in cases.items():
        out = edited(board, tmp_path / layer, layer, edit)
        (r,) = verify.verify(BOARD, out).reasons
        assert r.message.startswith(text), r.message
    out = edited(board, tmp_path / "ret", "cond", drop_return)
    (r,) = verify.verify(BOARD, out).reasons
    assert "does not end raised at its start point" in r.message
    assert "with the tool down" in r.message


def stray_saw(frames: list[Frame]) -> None:
    """The stray line of :func:`stray_line` drawn 99 999 times over, forth
    and back, in one cycle: about 200 000 strokes on the same 5 mm."""
    frames[0:0] = [Frame(dx=500, cyc=99_999, k=10), Frame(dx=-500, k=10)]


def test_a_cycle_over_one_line_is_scanned_once(board, tmp_path, monkeypatch) -> None:
    """The saw's repeats draw nothing new: verify gives the stray line's one
    reason, with its area, and its coverage scan gets the two strokes of
    the cycle's first turn, not 199 998 (each costs the scan time: the
    saw took minutes before, hours for a saw of 1 m teeth)."""
    once = edited(board, tmp_path / "once", "cond", stray_line)
    (one,) = verify.verify(BOARD, once).reasons
    seen: list[int] = []
    plan = raster.plan
    monkeypatch.setattr(raster, "plan", lambda ideal, drawn, *a, **k:
                        seen.append(len(drawn)) or plan(ideal, drawn, *a, **k))
    saw = edited(board, tmp_path / "saw", "cond", stray_saw)
    (r,) = verify.verify(BOARD, saw).reasons
    assert r.kind == "excess" and r.frame == 1, r.message
    area = one.message.split("nothing: ")[1].split(",")[0]
    assert r.message.startswith("frame 1 (row 22, DX500 CYC99999 K10 KK) draws where the deck "
                                f"holds nothing: {area}, "), r.message
    drawn_once = len([f for f in tape.decode((once / "BOARD-cond.ptp").read_bytes()).frames
                      if f.k != 20])
    assert seen and max(seen) == drawn_once - 1 + 2, seen


def test_distinct_strokes_keep_each_shape_at_its_first_frame() -> None:
    a, b = Stroke(((0, 0), (5, 0)), 25), Stroke(((5, 0), (0, 0)), 25)
    c = ArcBand(0, 0, 100, 0.0, 1.0, 25)
    assert distinct_strokes([a, b, a, c, b, a, c], [0, 1, 0, 3, 1, 5, 6]) == (
        [a, b, c], [0, 1, 3])


def test_an_m_card_saw_is_one_shape_a_stroke(run_tenzor) -> None:
    """The deck's own saw (M cards: 5 mm forth and back, CYC 99 999): the
    ideal layer holds each of its two strokes once, at its card, and
    TENZOR's tape of it passes."""
    deck = cards.deck([cards.CardPackage("MSAW", [
        cards.p_card(5000, 5000, 40), cards.d_card(500, 500, 160),
        cards.m_card("L", dx=500, cyc=99_999), cards.m_card("L", dx=-500),
        cards.l_card(0, 1000), cards.plus_card(1000, 1000)])], envelope=False)
    (pkg,) = parse_deck(deck)
    m = [(o.card, o.item) for o in pkg.layers["cond"].origins if o.kind == "M"]
    assert m == [(4, 0), (5, 1)]
    proc, out = run_tenzor(deck)
    assert proc.returncode == 0, proc.stderr.decode()
    v = verify.verify(deck, out)
    assert v.passed, v.text()


def test_shrunk_circle_is_too_narrow_and_strays(board, tmp_path) -> None:
    """Card 11's circle drawn 0.15 mm smaller: its outer edge is missing and
    its inner side is drawn outside the deck."""
    out = edited(board, tmp_path, "cond", shrink_o_circle)
    kinds = [(r.kind, r.card) for r in verify.verify(BOARD, out).reasons]
    assert kinds[0] == ("conductor-narrow", 11)
    assert [k for k, _ in kinds[1:]] == ["excess"]


def test_start_point_moved_on_the_deck_leaves_the_field(board) -> None:
    """The same tapes with the P card's start point 5 mm from the edge: the
    first frame that goes too far left is named."""
    deck = BOARD.replace("P              50.00     50.00", "P            1170.00     50.00")
    assert deck != BOARD
    v = verify.verify(deck, board)
    assert {r.kind for r in v.reasons} == {"field"}, v.text()
    assert "reaches x = 12" in v.reasons[0].message
    assert all(r.frame and r.row for r in v.reasons)


def test_field_exit_names_the_first_frame_that_leaves() -> None:
    """The tool centre may reach the field's edges, 0 and 1200.00 mm, not
    0.01 mm beyond; every repetition of a cycle, the way an arc turns and
    the scale (a board length v is N*v/D on the field) count."""
    F = 120_000

    def leave(frames: list[Frame], start: tuple[int, int], scale: tuple[int, int] = (1, 1)):
        return verify.field_exit(frames, start, scale)

    assert leave([Frame(dx=F, dy=F, k=20), Frame(dx=-F, dy=-F, k=20)], (0, 0)) is None
    assert leave([Frame(dx=F + 1, k=20)], (0, 0)) == (0, 0, "x = 1200.01 mm")
    assert leave([Frame(dy=F, k=10), Frame(dy=1, k=10)], (0, 0)) == (1, 0, "y = 1200.01 mm")
    assert leave([Frame(dx=-1, k=20)], (0, 0)) == (0, 0, "x = -0.01 mm")
    # the third and last repetition of a cycle goes 0.01 mm too far
    saw = [Frame(dx=1000, cyc=3, k=20), Frame(k=20)]
    assert leave(saw, (F - 3000, 0)) is None
    assert leave(saw, (F - 2999, 0)) == (0, 3, "x = 1200.01 mm")
    # a half circle from the right of its centre: clockwise through the bottom
    assert leave([Frame(x=1000, dx=-2000, k=13)], (F // 2, 999)) == (0, 0, "y = -0.01 mm")
    assert leave([Frame(x=1000, dx=-2000, k=11)], (F // 2, 999)) is None
    assert leave([Frame(x=1000, dx=-2000, k=11)], (F // 2, F - 999)) == (0, 0, "y = 1200.01 mm")
    # 60 mm left of a start point 50 mm from the edge: 30 mm at 1:2, 120 mm at 2:1
    out_and_back = [Frame(dx=-6000, k=20), Frame(dx=6000, k=20)]
    assert leave(out_and_back, (5000, 0), (1, 2)) is None
    assert leave(out_and_back, (5000, 0), (2, 1)) == (0, 0, "x = -70.00 mm")
    assert leave(out_and_back, (5000, 0), (1, 1)) == (0, 0, "x = -10.00 mm")


def test_frame_start_rows_without_the_decoders_starts() -> None:
    """A tape whose frame starts were not noted: counted from its leader."""
    frames = [Frame(dx=3, k=10), Frame(dx=-3, k=20)]       # 6 rows each
    data = tape.encode(frames, "8", leader=3)
    t = tape.decode(data)
    assert t.starts == [5, 11]
    assert verify.frame_start_rows(data, replace(t, starts=None)) == [5, 11]


def test_corrupt_row_is_a_code_error_with_its_row(board, tmp_path) -> None:
    out = tmp_path / "tapes"
    shutil.copytree(board, out)
    (out / "BOARD.job").unlink()            # another program's tapes: no job sheet
    path = out / "BOARD-small.ptp"
    data = bytearray(path.read_bytes())
    data[29] = 0o15                         # row 30: no such code
    path.write_bytes(bytes(data))
    (r,) = verify.verify(BOARD, out).reasons
    assert (r.kind, r.row) == ("code", 30)
    assert r.message == "row 30: code or grammar error: code 15 (octal) is not an EM-703 code"
    data[29] = 0o37                         # a GM inside a frame: a grammar error
    path.write_bytes(bytes(data))
    (r,) = verify.verify(BOARD, out).reasons
    assert r.kind == "code" and r.row == 30


def test_missing_tape(board, tmp_path) -> None:
    out = tmp_path / "tapes"
    shutil.copytree(board, out)
    (out / "BOARD-large.ptp").unlink()
    (r,) = verify.verify(BOARD, out).reasons
    assert (r.kind, r.tape) == ("tape-missing", "BOARD-large.ptp")


# ---------------------------------------------------------------------------
# The command.
# ---------------------------------------------------------------------------
def test_command_exit_status_and_deterministic_output(board, tmp_path, capsys) -> None:
    deck = tmp_path / "board.crd"
    deck.write_text(BOARD)
    assert main(["verify", str(deck), str(board)]) == 0
    assert capsys.readouterr().out.endswith("\nPASS\n")
    out = edited(board, tmp_path, "small", drop_pad)
    assert main(["verify", str(deck), str(out)]) == 1
    first = capsys.readouterr().out
    assert main(["verify", str(deck), str(out)]) == 1
    assert capsys.readouterr().out == first
    assert "       card 3 (D): round 1.60 mm pad at (10.00, 10.00) mm: missing" in first
    assert first.endswith("\nFAIL: 1 reason\n")


@pytest.mark.parametrize("args,fragment", [
    (["verify", "/nonexistent.crd", "."], "/nonexistent.crd: No such file"),
    (["verify", "{deck}", "/nonexistent"], "/nonexistent: no such directory"),
    (["verify", "{deck}", "{deck}"], "deck.crd: not a directory: give the folder the tapes are in"),
    (["verify", "{bad}", "."], "bad.crd: card 2: unknown card type 'Q' in column 1 (the harness "
                               "cannot read this deck, so there is nothing to verify against)"),
    (["verify", "{noend}", "."], "noend.crd: at the end of the deck: the deck ends without the "
                                 "E card (the last package must end with a card of E in "
                                 "column 1) (the harness cannot read this deck"),
    (["verify", "{deck}", ".", "--tol", "0.05"], "python -m harness verify: error: unrecognized arguments: "
                                                   "--tol 0.05"),
    (["verify", "{deck}", ".", "--tolerance", "0.001"], "--tolerance must be whole 0.01 mm"),
    (["verify", "{deck}", ".", "--tolerance", "1e9"], "--tolerance must be whole 0.01 mm, 0.02 "
                                                     "to 10.00 mm, not 1e9"),
    (["verify", "{deck}", ".", "--tolerance", "0.01"], "--tolerance must be whole 0.01 mm, 0.02 "
                                                      "to 10.00 mm, not 0.01"),
    (["verify", "{deck}", ".", "--tolerance", "10.01"], "--tolerance must be whole 0.01 mm, 0.02 "
                                                       "to 10.00 mm, not 10.01"),
    (["verify", "{deck}"], "usage:"),
])
def test_command_usage_and_io_errors_exit_2(tmp_path, capsys, args, fragment) -> None:
    (tmp_path / "deck.crd").write_text(BOARD)
    (tmp_path / "bad.crd").write_text("B\nQ\nE\n")
    (tmp_path / "noend.crd").write_text(BOARD[:BOARD.rindex("E")])
    argv = [a.format(deck=tmp_path / "deck.crd", bad=tmp_path / "bad.crd",
                     noend=tmp_path / "noend.crd") for a in args]
    assert main(argv) == 2
    assert fragment in capsys.readouterr().err


@pytest.mark.parametrize("mm", ["0.02", "10.00"])
def test_the_tolerance_may_be_its_least_or_its_greatest(board, tmp_path, capsys, mm) -> None:
    deck = tmp_path / "board.crd"
    deck.write_text(BOARD)
    assert main(["verify", str(deck), str(board), "--tolerance", mm]) == 0
    out = capsys.readouterr().out
    assert out.startswith(f"verify {deck} against {board} (tolerance {mm} mm)\n")
    assert out.endswith("\nPASS\n")


def test_two_packages_naming_the_same_files_are_refused(tmp_path) -> None:
    """'A_B' and 'A B' both punch A_B-small.ptp ...: no verdict."""
    deck = cards.deck([cards.CardPackage("A_B", []), cards.CardPackage("A B", [])],
                      envelope=False)
    with pytest.raises(verify.VerifyError) as info:
        verify.verify(deck, tmp_path, deck_name="two.crd")
    assert str(info.value) == ("two.crd: card 3: package name 'A B' names the same files "
                               "as card 1")


def test_python_dash_m_harness_verify(board, tmp_path) -> None:
    deck = tmp_path / "board.crd"
    deck.write_text(BOARD)
    proc = subprocess.run([sys.executable, "-m", "harness", "verify", str(deck), str(board)],
                          cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.endswith("PASS\n")


def test_m_card_drawing_left_out(run_tenzor, tmp_path) -> None:
    """Example 4's hand-coded line (its M card is card 6) travelled raised."""
    deck = ROOT / "examples" / "report" / "example4.crd"
    proc, out = run_tenzor(deck)
    assert proc.returncode == 0
    path = out / "EXAMPLE4-cond.ptp"
    frames = list(tape.decode(path.read_bytes()).frames)
    assert frames[0] == Frame(dx=-500, dy=-500, k=10)
    frames[0] = replace(frames[0], k=20)
    path.write_bytes(tape.encode(frames))
    (out / "EXAMPLE4.job").unlink()         # another program's tapes: no job sheet
    v = verify.verify(deck.read_text(), out)
    assert [(r.kind, r.card) for r in v.reasons] == [("m-drawing", 6)], v.text()
    assert "card 6 (M), M frame 1 of this tape: the line it draws from (0.00, 0.00) mm " \
           "to (-5.00, -5.00) mm: incomplete" in v.text()


# ---------------------------------------------------------------------------
# verify itself takes any tape: a verdict, never an exception.
# ---------------------------------------------------------------------------
SMALL = cards.deck([cards.CardPackage("S", [
    cards.p_card(5000, 5000, 40), cards.d_card(500, 500, 160),
    cards.l_card(0, 1000), cards.plus_card(1000, 1000)])], envelope=False)


@settings(max_examples=300 if os.environ.get("HYPOTHESIS_PROFILE") == "long" else 12,
          deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(small=st.one_of(st.binary(max_size=300), frame_lists(max_items=2).map(tape.encode)),
       cond=st.one_of(st.binary(max_size=300), frame_lists(max_items=2).map(tape.encode)))
@example(small=tape.encode([Frame(x=1_000_000, k=13)]), cond=b"")
@example(small=tape.encode([Frame(dx=5000, cyc=999_999, k=20), Frame(dx=-5000, k=20)]),
         cond=tape.encode([Frame(dx=-600_000, k=10), Frame(dx=600_000, k=20)]))
def test_any_tape_gets_a_verdict(tmp_path, small, cond) -> None:
    here = tmp_path / f"v{len(list(tmp_path.iterdir()))}"
    here.mkdir()
    (here / "S-small.ptp").write_bytes(small)
    (here / "S-cond.ptp").write_bytes(cond)
    v = verify.verify(SMALL, here)
    assert not v.passed                       # S-large.ptp is missing, at least
    assert v.text().endswith(f"FAIL: {v.count} reason{'s' if v.count != 1 else ''}\n")
