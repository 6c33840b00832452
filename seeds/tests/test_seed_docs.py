"""The seed pages stay true: README names every seed command that exists
and links every page, and the pages' pictures are what the tools draw."""
from __future__ import annotations

import re
from pathlib import Path

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
