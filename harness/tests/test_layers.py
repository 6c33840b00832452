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
from fractions import Fraction
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from harness import cards
from harness.deck import LAYERS, CardError, Package, parse_deck
from harness.raster import compare
from harness.sim import simulate
from harness.tape import TapeError, decode

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = sorted((ROOT / "examples").glob("**/*.crd"))
FIELD_MM = Decimal(1200)
TOLERANCE = 5                                   # 0.05 mm, the machine's accuracy


def read_job(path: Path) -> dict[str, str]:
    """``key = value`` lines of a job sheet (``#`` lines are comments)."""
    job: dict[str, str] = {}
    for line in path.read_text(encoding="ascii").splitlines():
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        key, sep, value = line.partition("=")
        assert sep, f"{path}: not a `key = value` line: {line!r}"
        job[key.strip()] = value.strip()
    return job


def check_package(pkg: Package, out: Path, deck_path: Path) -> list[str]:
    """All the checks of the module doc for one package; a list of failures."""
    where = f"deck {deck_path}, package {pkg.name!r}"
    problems: list[str] = []
    job_path = out / f"{pkg.file_name}.job"
    if not job_path.exists():
        return [f"{where}: no job sheet {job_path.name} in {out}"]
    job = read_job(job_path)
    tools = dict(zip(LAYERS, pkg.tools))
    expect = {"start_x_mm": pkg.start_mm[0], "start_y_mm": pkg.start_mm[1],
              **{f"{k}.tool_mm": Decimal(tools[k]) / 100 for k in LAYERS}}
    for key, value in expect.items():
        if key not in job or Decimal(job[key]) != value:
            problems.append(f"{where}: job sheet {key} = {job.get(key)!r}, P card says {value}")
    num, den = pkg.scale
    got = job.get("scale", "")
    if ":" not in got or Fraction(*map(int, got.split(":"))) != Fraction(num, den):
        problems.append(f"{where}: job sheet scale = {got!r}, P card says {num}:{den}")
    if job.get("code") != pkg.code:
        problems.append(f"{where}: job sheet code = {job.get('code')!r}, P card says {pkg.code}")
    x0, y0 = pkg.start_mm
    for key in LAYERS:
        name = f"{pkg.file_name}-{key}.ptp"
        if job.get(f"{key}.tape") != name:
            problems.append(f"{where}: job sheet {key}.tape = {job.get(key + '.tape')!r}, "
                            f"expected {name}")
        path = out / name
        if not path.exists():
            problems.append(f"{where}: tape {name} missing")
            continue
        try:
            tape = decode(path.read_bytes(), code=pkg.code)
            run = simulate(tape.frames)
        except (TapeError, ValueError) as exc:
            problems.append(f"{where}: tape {name}: {exc}")
            continue
        if run.end != (0, 0) or run.tool_down_at_end:
            problems.append(f"{where}: tape {name} ends at {run.end} (0.01 mm) with the tool "
                            f"{'down' if run.tool_down_at_end else 'up'}; expected (0, 0), up")
        scale = Decimal(num) / Decimal(den)
        xmin, xmax, ymin, ymax = (Decimal(repr(v)) for v in run.bbox)
        lo = (x0 + xmin * scale, y0 + ymin * scale)
        hi = (x0 + xmax * scale, y0 + ymax * scale)
        if min(lo) < 0 or max(hi) > FIELD_MM:
            problems.append(f"{where}: tape {name} leaves the field: machine position "
                            f"x {lo[0]}..{hi[0]}, y {lo[1]}..{hi[1]} mm")
        report = compare(run, tools[key], pkg.layers[key], tol=TOLERANCE)
        if not report.ok:
            problems.append(f"{where}: tape {name} (tool {tools[key] / 100:.2f} mm) does not "
                            f"draw the ideal {key} layer:\n{report.summary()}")
    return problems


def check_outputs(proc, out: Path, deck_path: Path) -> list[str]:
    """Check TENZOR's run on a deck it must accept; a list of failures."""
    if proc.returncode != 0:
        return [f"deck {deck_path}: TENZOR exit status {proc.returncode}\n"
                + proc.stdout.decode("latin-1")[-2000:] + proc.stderr.decode("latin-1")[-2000:]]
    problems: list[str] = []
    for pkg in parse_deck(deck_path.read_text(encoding="ascii")):
        problems += check_package(pkg, out, deck_path)
    return problems


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
    pkgs = draw(st.lists(cards.st_package(), min_size=1, max_size=2))
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
@given(pkg=cards.st_package(name="ROUNDTRIP"))
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
            assert -cards.REACH - 100 <= b[0] <= b[1] <= cards.REACH + 100
            assert -cards.REACH - 100 <= b[2] <= b[3] <= cards.REACH + 100


def _m_shapes(pkg: Package, key: str) -> int:
    """Shapes that the M frames of a tape add to its layer."""
    return len(simulate(pkg.m_frames[key]).strokes)


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
