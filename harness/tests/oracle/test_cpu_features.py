"""The raster oracle's verdicts may not depend on the CPU: numpy picks SIMD
code paths (AVX2, AVX-512) by what the processor has, and a result that
depended on which element a SIMD kernel returns first would change from
machine to machine. `make test-cpus` (run by CI) runs the raster, verify and
coverage tests again with numpy's AVX-512 paths disabled, and again without
AVX2, through the variable NPY_DISABLE_CPU_FEATURES; this test proves the
variable took: every group it names is off."""
from __future__ import annotations

import os

import pytest
from numpy._core._multiarray_umath import __cpu_features__


def test_the_disabled_cpu_features_are_off():
    names = os.environ.get("NPY_DISABLE_CPU_FEATURES", "").replace(",", " ").split()
    if not names:
        pytest.skip("NPY_DISABLE_CPU_FEATURES is not set: numpy uses every path this "
                    "CPU has (make test-cpus sets it)")
    on = [name for name in names if __cpu_features__.get(name)]
    assert not on, f"numpy still uses {on}"
