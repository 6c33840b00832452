"""What the test suites share besides fixtures (those are in the root
conftest.py): where the examples are, what a program must never print, a
runner, job sheets read and written, the blocks of a seed 004 program, and
the coverage check of a package's tapes against its deck (the oracle's
decoder, simulator and raster)."""

from __future__ import annotations

import subprocess
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction
from pathlib import Path

from harness.deck import LAYERS, Package, parse_deck
from harness.raster import compare
from harness.sim import simulate
from harness.tape import TapeError, decode

ROOT = Path(__file__).resolve().parents[2]
#: Every deck of examples/, in a fixed order.
DECKS: list[Path] = sorted((ROOT / "examples").rglob("*.crd"))
FIELD_MM = Decimal(1200)
TOLERANCE = 5                                   # 0.05 mm, the machine's accuracy

#: What a program of the project must never print, whatever its input: the
#: Fortran run-time library's error reports and the signals of a crash
#: (the fuzz suites check both streams for these).
FORBIDDEN = ("Fortran runtime", "Backtrace", "Error termination", "Program received signal",
             "SIGSEGV", "SIGFPE", "SIGABRT", "SIGBUS", "SIGILL", "Segmentation fault",
             "core dumped", "Aborted", "Illegal instruction")


@dataclass(frozen=True)
class Example:
    """The output of TENZOR for one example deck."""

    deck: Path
    out: Path

    @property
    def tapes(self) -> list[Path]:
        return sorted(self.out.glob("*.ptp"))

    @property
    def jobs(self) -> list[Path]:
        return sorted(self.out.glob("*.job"))


def run(exe: Path, *args: str | Path, check: int | None = None) -> subprocess.CompletedProcess:
    """Run em703; with ``check``, assert the exit status."""
    proc = subprocess.run([str(exe), *map(str, args)], capture_output=True, timeout=120)
    if check is not None:
        assert proc.returncode == check, (args, proc.returncode, proc.stdout[-2000:],
                                          proc.stderr.decode("latin-1"))
    return proc


def iso_programs(text: str) -> list[list[str]]:
    """The blocks of each program of a text of seed 004's block format (as
    `em703 gcode --dialect iso-1970s` writes it, in any kind of frame), the
    comments and % lines aside; every program is closed by its %."""
    progs: list[list[str]] = []
    cur: list[str] | None = None
    assert text.endswith("%\n"), text[-200:]
    for line in text.split("\n")[:-1]:
        if line == "%":
            if cur is None:
                cur = []
            else:
                progs.append(cur)
                cur = None
        elif cur is not None and not line.startswith("("):
            cur.append(line)
    assert cur is None
    return progs


def keys(text: str) -> dict[str, str]:
    """``key = value`` lines as a dict (blank and ``#`` lines skipped)."""
    out: dict[str, str] = {}
    for line in text.splitlines():
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        key, sep, value = line.partition("=")
        assert sep, f"not a `key = value` line: {line!r}"
        out[key.strip()] = value.strip()
    return out


def read_job(path: Path) -> dict[str, str]:
    """A job sheet's ``key = value`` lines as a dict."""
    return keys(path.read_text(encoding="ascii"))


def write_job(directory: Path, name: str, tapes: dict[str, bytes],
              tools: dict[str, str], code: str = "8") -> Path:
    """A job sheet and its three tapes (missing tapes are GM GM)."""
    empty = bytes([0] * 20 + [0o37, 0o37] + [0] * 20)
    lines = ["# written by the em703 tests", f"name = {name}", f"code = {code}",
             "scale = 1:1", "start_x_mm = 600.00", "start_y_mm = 600.00"]
    for key in ("small", "large", "cond"):
        (directory / f"{name}-{key}.ptp").write_bytes(tapes.get(key, empty))
        lines += [f"{key}.tape = {name}-{key}.ptp", f"{key}.tool_mm = {tools.get(key, '0.50')}"]
    path = directory / f"{name}.job"
    path.write_text("\n".join(lines) + "\n")
    return path


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


def doc_sessions(text: str, prefix: str) -> list[tuple[str, list[str]]]:
    """(command, the lines shown after it) of each `$ PREFIX...` line in the
    fenced blocks of a page (a session runs to the next `$` line or the end
    of its block)."""
    out: list[tuple[str, list[str]]] = []
    fenced = session = False
    for line in text.splitlines():
        if line.startswith("```"):
            fenced, session = not fenced, False
        elif fenced and line.startswith("$ "):
            out.append((line[2:], []))
            session = True
        elif session:
            out[-1][1].append(line)
    return [s for s in out if s[0].startswith(prefix)]


def assert_session(got: list[str], want: list[str], where: object) -> None:
    """A page's session output: ``got`` is ``want``, where a line ``...``
    of ``want`` stands for any lines left out."""
    if "..." in want:
        cut = want.index("...")
        head, tail = want[:cut], want[cut + 1:]
        assert got[:len(head)] == head and got[len(got) - len(tail):] == tail, (where, got)
    else:
        assert got == want, (where, "\n".join(got))


def file_size_limit(limit: int):
    """For subprocess's preexec_fn (with restore_signals=False): files may
    grow to ``limit`` bytes; a longer write fails with EFBIG (SIGXFSZ
    ignored), as a full disk fails with ENOSPC."""
    def apply() -> None:
        import resource
        import signal
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
    return apply
