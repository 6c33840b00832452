"""Every mutant of scripts/mutants.py (`make mutants`, not run by CI) can
still be applied: its text stands exactly once in its file. A change that
copies or rewrites such a line otherwise leaves the mutant reported as not
applied only when someone next runs the hour-long script (mutant 31's line
was copied into a second place of CMOPT2 and went unnoticed)."""
from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]


def _mutants():
    spec = importlib.util.spec_from_file_location("mutants", ROOT / "scripts" / "mutants.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules.setdefault("mutants", module)   # its dataclass looks itself up there
    spec.loader.exec_module(module)
    return module.MUTANTS


def test_every_mutant_text_stands_once_in_its_file():
    mutants = _mutants()
    assert len(mutants) >= 40
    off = [(n, m.path, (ROOT / m.path).read_text().count(m.old))
           for n, m in enumerate(mutants, 1) if (ROOT / m.path).read_text().count(m.old) != 1]
    assert not off, f"(mutant number, file, copies of its text): {off}"
