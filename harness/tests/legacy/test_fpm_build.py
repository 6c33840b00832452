"""scripts/fpm_build.sh, the build of `make test`: the test programs run the
code as it is now, whichever fpm command compiled it.

fpm 0.12 links a program again only in the run that compiled one of its
objects, and `fpm build` does not link the test programs: after a change,
`fpm build` then `fpm test` ran test programs linked before the change. The
script links them again. The test makes a package of one module and one test
program, changes the module after a first `fpm test`, and has `fpm build`
compile the change; the test program must then see it.
"""
from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]
FPM = shutil.which("fpm")

MODULE = """module answer
    implicit none
contains
    integer function value()
        value = {v}
    end function value
end module answer
"""
CHECK = """program check
    use answer, only: value
    implicit none
    if (value() /= 1) error stop 'value is not 1'
    print '(a)', 'value is 1'
end program check
"""
APP = """program show
    use answer, only: value
    implicit none
    print '(i0)', value()
end program show
"""


def fpm(package: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([FPM, *args], cwd=package, capture_output=True, text=True, timeout=300)


@pytest.mark.skipif(FPM is None, reason="fpm is not on PATH (make setup)")
def test_the_tests_run_what_fpm_build_compiled(tmp_path) -> None:
    package = tmp_path / "pkg"
    for folder, name, text in [("src", "answer.f90", MODULE.format(v=1)),
                               ("test", "check.f90", CHECK), ("app", "show.f90", APP)]:
        (package / folder).mkdir(parents=True)
        (package / folder / name).write_text(text)
    (package / "fpm.toml").write_text('name = "pkg"\n')
    (package / "scripts").mkdir()
    shutil.copy(ROOT / "scripts" / "fpm_build.sh", package / "scripts")
    assert fpm(package, "test").returncode == 0
    (package / "src" / "answer.f90").write_text(MODULE.format(v=2))
    assert fpm(package, "build").returncode == 0            # compiles the change
    assert fpm(package, "run").stdout.strip() == "2"
    build = subprocess.run(["bash", "scripts/fpm_build.sh"], cwd=package, capture_output=True,
                           text=True, timeout=300)
    assert build.returncode == 0, build.stderr
    test = fpm(package, "test")
    assert test.returncode != 0 and "value is not 1" in test.stdout + test.stderr, test.stdout
    # and back: the test passes again, its program linked with the old value
    (package / "src" / "answer.f90").write_text(MODULE.format(v=1))
    assert subprocess.run(["bash", "scripts/fpm_build.sh"], cwd=package,
                          capture_output=True, timeout=300).returncode == 0
    assert fpm(package, "test").returncode == 0


def test_every_make_target_that_runs_fpm_test_builds_with_the_script() -> None:
    """make test, test-checks and fuzz build through the script first, with
    the flags of the fpm test that follows."""
    make = (ROOT / "Makefile").read_text()
    assert "build: setup\n\t@bash scripts/fpm_build.sh >/dev/null\n" in make
    for target in ("test-checks", "fuzz"):
        recipe = make.split(f"\n{target}: setup\n", 1)[1].split("\n\n", 1)[0]
        assert recipe.startswith('\t@bash scripts/fpm_build.sh --profile debug --flag "$(CHECKS)"')
    assert "test: build\n\tfpm test\n" in make
