"""The documentation stays true: every example card of docs/CARDS.md is a card
TENZOR accepts, column for column, and README's table of files is what TENZOR
writes."""
from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]


def _example_cards() -> list[str]:
    text = (ROOT / "docs" / "CARDS.md").read_text()
    cards = []
    for block in re.findall(r"```\n----\+----1.*?\n(.*?)```", text, re.S):
        if "..." in block:  # the outline of a package, not cards
            continue
        cards += [line for line in block.splitlines() if line[:1] in "PDL+OAM"]
    return cards


def test_cards_md_examples_are_accepted(run_tenzor):
    cards = _example_cards()
    kinds = {c[0] for c in cards}
    assert kinds == set("PDL+OAM"), kinds
    p = [c for c in cards if c[0] == "P"]
    rest = [c for c in cards if c[0] != "P"]
    # the example P card asks for a 1:1 board at (100, 100) mm: everything fits
    deck = "DOCS\n" + "\n".join(p + rest) + "\nE\n"
    proc, out = run_tenzor(deck)
    assert proc.returncode == 0, proc.stderr.decode()
    assert (out / "DOCS-cond.ptp").exists()


def test_readme_names_the_files_tenzor_writes(run_tenzor):
    readme = (ROOT / "README.md").read_text()
    proc, out = run_tenzor(ROOT / "examples" / "report" / "example4.crd")
    assert proc.returncode == 0
    for path in out.iterdir():
        suffix = re.sub(r"^EXAMPLE4", "NAME", path.name)
        pattern = suffix.replace("-small.txt", "-*.txt").replace("-large.txt", "-*.txt") \
                        .replace("-cond.txt", "-*.txt")
        assert f"`{pattern}`" in readme, pattern


def test_filling_md_row_excerpt_is_the_demo_tape(run_tenzor):
    """docs/FILLING.md quotes the first frames of the demo's small-pad tape."""
    text = (ROOT / "docs" / "FILLING.md").read_text()
    block = text.split("## Rows of pads", 1)[1].split("```", 2)[1]
    quoted = [line[:25].rstrip() for line in block.strip().splitlines()]
    proc, out = run_tenzor(ROOT / "examples" / "demo.crd")
    assert proc.returncode == 0
    frames = (out / "LOGIC-CARD-A-small.txt").read_text().splitlines()
    assert frames[1:1 + len(quoted)] == quoted


def test_files_md_listing_excerpt_is_the_demo_listing(run_tenzor):
    """docs/FILES.md quotes lines of the demo's listing (the small-pad tape's
    statistics, the order and kicks lines, the verdict), in order, with
    `...` for what it leaves out. The kicks line pins the kicks made, kept
    and their work, which no tape shows: an undone kick's reversals left out
    of the work count changes it and no recorded tour."""
    text = (ROOT / "docs" / "FILES.md").read_text()
    block = text.split("## The listing, `.lst`", 1)[1].split("```", 2)[1]
    quoted = [line for line in block.strip("\n").splitlines() if line != "..."]
    # the quote must still hold what the test is for, or it would pass empty
    assert any(line.lstrip().startswith("KICKS ") for line in quoted), block
    proc, out = run_tenzor(ROOT / "examples" / "demo.crd")
    assert proc.returncode == 0
    listing = (out / "LOGIC-CARD-A.lst").read_text().splitlines()
    at = [listing.index(line) if line in listing else -1 for line in quoted]
    assert -1 not in at, [q for q, i in zip(quoted, at) if i < 0]
    assert at == sorted(at)


def test_filling_md_control_plot_is_the_listings(run_tenzor):
    """docs/FILLING.md quotes the conductor tape's control plot of
    examples/filling.crd, down to its start point, as the listing prints it."""
    text = (ROOT / "docs" / "FILLING.md").read_text()
    block = text.split("## What the line printer shows", 1)[1].split("```", 2)[1]
    quoted = block.strip("\n").splitlines()
    assert len(quoted) > 10 and quoted[-1].startswith(" |+"), block
    proc, out = run_tenzor(ROOT / "examples" / "filling.crd")
    assert proc.returncode == 0
    listing = (out / "FILLING.lst").read_text().splitlines()
    plot = listing[next(i for i, line in enumerate(listing)
                        if line.startswith(" CONTROL PLOT, TAPE L")):]
    at = plot.index(quoted[0]) if quoted[0] in plot else -1
    assert plot[at:at + len(quoted)] == quoted, "docs/FILLING.md's control plot is stale"


def test_files_md_job_sheet_examples_are_the_demos(run_tenzor):
    """docs/FILES.md's table of job sheet keys gives the demo's values as
    examples (T as small; a value ending in ... is the start of one)."""
    text = (ROOT / "docs" / "FILES.md").read_text()
    section = text.split("## The job sheet, `.job`", 1)[1].split("\n## ", 1)[0]
    proc, out = run_tenzor(ROOT / "examples" / "demo.crd")
    assert proc.returncode == 0
    job = dict(line.split(" = ", 1) for line in
               (out / "LOGIC-CARD-A.job").read_text().splitlines() if " = " in line)
    checked = 0
    for keys_cell, example_cell in re.findall(r"^\| (`[^|]+) \| ([^|]*) \|", section, re.M):
        keys = re.findall(r"`([^`]+)`", keys_cell)
        examples = re.findall(r"`([^`]+)`", example_cell)
        if not examples or " or " in example_cell:
            continue
        for key, example in zip(keys, examples * len(keys) if len(examples) == 1 else examples):
            value = job[key.replace("T.", "small.")]
            assert value.startswith(example[:-3]) if example.endswith("...") \
                else value == example, (key, example, value)
            checked += 1
    assert checked >= 15, checked


def test_files_md_frame_text_excerpt_is_the_demos(run_tenzor):
    """docs/FILES.md's excerpt of a frame text: the demo's conductor tape,
    its first frames and its end."""
    text = (ROOT / "docs" / "FILES.md").read_text()
    block = text.split("## The frame text, `.txt`", 1)[1].split("```", 2)[1]
    head, tail = block.strip("\n").split("\n...\n")
    proc, out = run_tenzor(ROOT / "examples" / "demo.crd")
    assert proc.returncode == 0
    frames = (out / "LOGIC-CARD-A-cond.txt").read_text().splitlines()
    assert frames[:len(head.splitlines())] == head.splitlines()
    assert frames[-len(tail.splitlines()):] == tail.splitlines()


def test_readme_counts_the_demo_boards_pads():
    from harness.deck import parse_deck
    package = parse_deck((ROOT / "examples" / "demo.crd").read_text())[0]
    readme = " ".join((ROOT / "README.md").read_text().split())
    assert f"0.5 mm signals, {sum(p.n for p in package.pads)} pads)" in readme


def test_filling_pictures_are_current(tmp_path):
    """docs/img/filling*.svg are what scripts/pictures.sh draws now."""
    import subprocess
    subprocess.run(["bash", str(ROOT / "scripts" / "pictures.sh"), str(tmp_path)],
                   check=True, capture_output=True, cwd=ROOT)
    for fresh in sorted(tmp_path.glob("filling*.svg")):
        kept = ROOT / "docs" / "img" / fresh.name
        assert kept.exists(), f"{kept} is missing: run scripts/pictures.sh"
        assert kept.read_bytes() == fresh.read_bytes(), f"{kept} is stale: run scripts/pictures.sh"
