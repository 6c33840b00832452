"""The oracle stays independent: no module of harness/ (outside its tests)
imports the neighbouring systems (seeds), the benchmarks (bench) or a test
library, and none imports anything that is not the standard library, numpy
or the oracle itself. Read from the source with ast, so that an import
inside a function counts as much as one at the top."""
from __future__ import annotations

import ast
import sys
from pathlib import Path

import pytest

HARNESS = Path(__file__).resolve().parents[2]
ALLOWED = {"harness", "numpy", "__future__"}
MODULES = sorted(p for p in HARNESS.rglob("*.py") if "tests" not in p.relative_to(HARNESS).parts)


def imported(source: str) -> set[str]:
    """The top-level package of every absolute import in a module."""
    names: set[str] = set()
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            names |= {a.name.split(".")[0] for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names.add(node.module.split(".")[0])
    return names


@pytest.mark.parametrize("module", MODULES, ids=[p.name for p in MODULES])
def test_oracle_module_imports_only_the_standard_library_numpy_and_itself(module):
    outside = {n for n in imported(module.read_text(encoding="utf-8"))
               if n not in ALLOWED and n not in sys.stdlib_module_names}
    assert not outside, f"{module.relative_to(HARNESS.parent)} imports {sorted(outside)}"


def test_the_check_sees_imports_anywhere_in_a_module():
    source = "import os\nfrom seeds import seed002\ndef f():\n    import hypothesis\n" \
             "    from bench.tours import x\n    from . import tape\n"
    assert imported(source) == {"os", "seeds", "hypothesis", "bench"}


def test_there_are_oracle_modules_to_check():
    assert {"tape.py", "sim.py", "shapes.py", "deck.py", "raster.py", "verify.py",
            "cards.py"} <= {p.name for p in MODULES}
