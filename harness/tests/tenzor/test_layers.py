"""Integration: TENZOR's tapes draw exactly the deck's ideal layers.

For every deck under examples/ and for random boards (harness.cards), run
the real TENZOR, decode each of the three tapes of each package with
harness.tape, simulate them with harness.sim and check:

* the drawing with the tape's tool equals the ideal layer of harness.deck
  within 0.05 mm (no holes, no excess; harness.raster);
* the tape ends with the tool raised at its start point (0, 0);
* the machine position X0 + v*N/D stays inside 0..1200 mm on both axes;
* the job sheet agrees with the P card (tools, start point, scale, code).
"""

from __future__ import annotations

from decimal import Decimal
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from harness import cards
from harness.tests.strategies import REACH, st_package
from harness.deck import LAYERS, CardError, Package, parse_deck
from harness.shapes import distinct_strokes, run_shapes
from harness.sim import simulate, stroke_frames

from harness.tests.helpers import DECKS as EXAMPLES
from harness.tests.helpers import ROOT, check_outputs


@pytest.mark.parametrize("deck_path", EXAMPLES, ids=[str(p.relative_to(ROOT)) for p in EXAMPLES])
def test_example_deck_draws_its_ideal_layers(run_tenzor, deck_path: Path) -> None:
    proc, out = run_tenzor(deck_path)
    if proc.returncode != 0:
        listing = "".join(p.read_text(encoding="latin-1") for p in sorted(out.glob("*.lst"))) \
            if out.exists() else ""
        errors = [ln.strip() for ln in (listing + proc.stdout.decode("latin-1")
                                        + proc.stderr.decode("latin-1")).splitlines()
                  if "ERROR" in ln.upper()]
        pytest.skip(f"TENZOR reports errors for {deck_path.name} (exit {proc.returncode}): "
                    + ("; ".join(errors[:3]) or "see its listing"))
    problems = check_outputs(proc, out, deck_path)
    assert not problems, "\n".join(problems)


# ---------------------------------------------------------------------------
# Random boards.
# ---------------------------------------------------------------------------
@st.composite
def st_deck(draw: st.DrawFn) -> str:
    """A deck of 1-2 random packages with distinct names."""
    pkgs = draw(st.lists(st_package(), min_size=1, max_size=2))
    seen: set[str] = set()
    for n, p in enumerate(pkgs):
        while p.name in seen:
            p.name = f"{p.name[:6]}Z{n}"
            n += 1
        seen.add(p.name)
    return cards.deck(pkgs, envelope=draw(st.booleans()))


@settings(max_examples=25, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(text=st_deck())
def test_random_board_draws_its_ideal_layers(run_tenzor, tmp_path: Path, text: str) -> None:
    decks = tmp_path / "decks"
    decks.mkdir(exist_ok=True)
    deck_path = decks / f"deck{len(list(decks.iterdir()))}.crd"
    deck_path.write_text(text, encoding="ascii")
    proc, out = run_tenzor(deck_path)
    problems = check_outputs(proc, out, deck_path)
    assert not problems, f"failing deck written to {deck_path}\n" + "\n".join(problems)


# ---------------------------------------------------------------------------
# The oracle's own deck reading (no TENZOR needed).
# ---------------------------------------------------------------------------
@given(pkg=st_package(name="ROUNDTRIP"))
def test_generated_cards_parse_back(pkg: cards.CardPackage) -> None:
    (parsed,) = parse_deck(cards.deck([pkg]))
    assert parsed.name == "ROUNDTRIP"
    kinds = [c[:1] for c in pkg.cards if c]
    assert len(parsed.conductors) == kinds.count("L")
    assert len(parsed.circles) == kinds.count("O")
    assert len(parsed.arcs) == kinds.count("A")
    assert sum(len(v) for v in parsed.m_frames.values()) == kinds.count("M")
    pad_shapes = sum(len(parsed.layers[k]) - _m_shapes(parsed, k) for k in ("small", "large"))
    assert pad_shapes == sum(p.n for p in parsed.pads)
    for key in LAYERS:
        for shape in parsed.layers[key]:
            b = shape.bbox()
            assert -REACH - 100 <= b[0] <= b[1] <= REACH + 100
            assert -REACH - 100 <= b[2] <= b[3] <= REACH + 100


def _m_shapes(pkg: Package, key: str) -> int:
    """Shapes that the M frames of a tape add to its layer: each distinct
    stroke once (two M cards that draw the same dot add one shape)."""
    frames = pkg.m_frames[key]
    shapes = run_shapes(simulate(frames), pkg.layers[key].tool)
    return len(distinct_strokes(shapes, stroke_frames(frames))[0])


def test_card_fields_are_fortran_fields() -> None:
    card = cards.d_card(1250, -5, Decimal("1.6"), None, 4, 254, None)
    assert card[10:20] == "     12.50" and card[20:30] == "     -0.05"
    assert card[30:38] == "    1.60" and card[46:50] == "   4" and card[50:60] == "      2.54"
    (pkg,) = parse_deck(cards.deck([cards.CardPackage("X", [
        cards.p_card(50000, 60000, 30, 120, 40, 250, (1, 2), "K", "D"), card])]))
    assert pkg.start == (50000, 60000) and pkg.tools == (30, 120, 40)
    assert pkg.dmax == 250 and pkg.scale == (1, 2) and (pkg.code, pkg.order) == ("K", "D")
    assert [p.centres() for p in pkg.pads] == [[(1250 + 254 * i, -5) for i in range(4)]]
    assert len(pkg.layers["small"]) == 4 and not pkg.layers["large"]
    # implied decimals, defaults, strictness
    (pkg,) = parse_deck("B\nD         " + "      1250" + "        10" + "     160\nE\n")
    assert pkg.pads[0].x == 1250 and pkg.pads[0].y == 10 and pkg.pads[0].w == 160
    assert pkg.tools == (50, 100, 50) and pkg.dmax == 200 and pkg.code == "8"
    for bad in ("B\nD         12                  1.00\nE\n", "B\nQ\nE\n", "B\nD  junk\nE\n", "B\nP\n",
                "B\n+         1.00      2.00\nE\n"):
        with pytest.raises(ValueError, match="card"):
            parse_deck(bad)


def test_a_name_card_is_columns_1_to_18() -> None:
    """The writer puts a name of at most 18 characters in columns 1-18, where
    the reader finds it; a 19th would be column 19, which must be blank."""
    assert cards.name_card("N" * 18) == "N" * 18
    with pytest.raises(ValueError, match="bad package name 'NNNNNNNNNNNNNNNNNNN'"):
        cards.name_card("N" * 19)
    (pkg,) = parse_deck(cards.deck([cards.CardPackage("N" * 18, [])]))
    assert pkg.name == "N" * 18
    with pytest.raises(CardError, match="card 4: columns 19-72 must be blank"):
        parse_deck(cards.deck([cards.CardPackage("N" * 18, [])]).replace("N" * 18, "N" * 19))


@pytest.mark.parametrize("arc, col, words", [
    (("+", 1000, 1000, 1000, 1000, 1500, 1000), 31, "start of the arc is its centre"),
    (("+", 1000, 1000, 1001, 1000, 1000, 1000), 51, "end of the arc is its centre"),
    (("+", 1000, 1000, 1500, 1000, 1500, 1000), 51, "ends where it starts"),
])
def test_oracle_and_tenzor_reject_the_same_degenerate_arcs(run_tenzor, arc, col, words) -> None:
    """An A card whose start or end is its centre, or whose end is its start,
    is refused by TENZOR (card and column named) and by the harness's parser
    alike: the oracle must not draw what TENZOR will not punch."""
    card = cards.a_card(*arc)
    deck = cards.deck([cards.CardPackage("ARCS", [card])])
    no = deck.splitlines().index(card) + 1
    with pytest.raises(CardError) as err:
        parse_deck(deck)
    assert err.value.card == no and words in str(err.value)
    proc, _ = run_tenzor(deck)
    assert proc.returncode == 1
    text = proc.stderr.decode()
    assert f"CARD {no} COL {col}:" in text and words.upper() in text, text


@pytest.mark.parametrize("w, h", [(101, 101), (101, 81), (100, 81), (261, 147), (51, 200)])
def test_an_odd_rectangular_pad_is_short_never_over(run_tenzor, w: int, h: int) -> None:
    """A pad whose extent less the tool is an odd number of units is drawn
    half a unit short on each side (RECONSTRUCTION.md, "Odd sizes"): the
    tool's centre stays within (W - tool)/2 and (H - tool)/2 of the pad's
    centre, and reaches them to within half a unit."""
    from harness.tape import decode
    tool = 50
    deck = (f"ODD\nP             100.00    100.00{tool / 100:8.2f}{'':16}   10.00\n"
            f"D              10.00     10.00{w / 100:8.2f}{h / 100:8.2f}\nE\n")
    proc, out = run_tenzor(deck)
    assert proc.returncode == 0, proc.stderr.decode()
    x = y = 0
    xs, ys = [], []
    for f in decode((out / "ODD-small.ptp").read_bytes()).frames:
        if f.k == 10:                           # both ends of a stroke drawn
            xs += [x - 1000, x + f.dx - 1000]
            ys += [y - 1000, y + f.dy - 1000]
        x, y = x + f.dx, y + f.dy
    for got, extent in ((xs, w - tool), (ys, h - tool)):
        assert 2 * max(got) <= extent and 2 * -min(got) <= extent, (got, extent)
        assert 2 * max(got) >= extent - 1 and 2 * -min(got) >= extent - 1, (got, extent)
