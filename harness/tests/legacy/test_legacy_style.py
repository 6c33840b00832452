"""SPEC section 7 holds for every file of legacy/: the faithful programs read as
a 1977 listing (fixed form, six-character names, upper case, COMMON blocks and
PARAMETERs declared alike everywhere, every variable declared)."""
from __future__ import annotations

from pathlib import Path

from harness.f77check import check_dir

LEGACY = Path(__file__).resolve().parents[3] / "legacy"


def test_legacy_sources_follow_spec_section_7():
    notes: list[str] = []
    violations = check_dir(LEGACY, notes=notes)
    assert not notes, notes  # gfortran must be there: the set-up installs it
    assert not violations, "\n".join(str(v) for v in violations)


def test_every_unit_names_its_source_and_ends_with_a_trailer():
    for path in sorted(LEGACY.glob("*.f")):
        text = path.read_text()
        unit = path.stem.upper()
        assert f"C     {unit}" in text.splitlines()[1] or f"C     {unit} " in text, path
        assert "C     SOURCE:" in text, path
        assert f"C     END OF {unit}" in text, path
