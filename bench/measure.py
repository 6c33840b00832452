"""Running TENZOR on a board and reading its tapes back.

* :func:`time_tenzor`: wall time of the whole run, deck to tapes (the
  program reads the deck, writes three tapes, their frame texts, the
  listing with its control plots and the job sheet), by
  ``time.perf_counter`` around a fresh process, repeated; and the CPU time
  (user + system) of each process, which the other work on a shared machine
  disturbs less.
* :func:`peak_rss`: the peak resident set size of TENZOR, from a run of its
  own.  Not ``ru_maxrss``: Linux keeps a process's peak across ``execve``,
  and Python starts a child with ``vfork``, so the child's ``ru_maxrss``
  (from ``os.wait4`` or ``RUSAGE_CHILDREN``) is at least the *benchmark's*
  own size (measured: ``/bin/true`` started from a 500 MB Python reports
  500 MB).  Instead the kernel's high-water mark of the new program's own
  memory, ``VmHWM`` in ``/proc/PID/status``, is read until the process ends
  (without pause for 50 ms, then every millisecond), in three runs, and the
  largest reading kept (see :func:`peak_rss`).
* :func:`read_tapes`: each tape decoded by :mod:`harness.tape` and run by
  :mod:`harness.sim`: frames, rows, drawn and raised length, run time, and
  the rows of the same frames with every cycle unrolled.
* :func:`time_verify`: ``python -m harness verify`` of a deck and its tapes
  in a fresh process: wall time, CPU time and peak resident set size (the
  same ``VmHWM`` reading), and whether it passed.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

from harness import sim, tape

TAPES: tuple[str, ...] = ("small", "large", "cond")


def _check(proc: subprocess.Popen, deck: Path) -> None:
    if proc.returncode != 0:
        err = proc.stderr.read().decode(errors="replace") if proc.stderr else ""
        raise RuntimeError(f"tenzor {deck} exited {proc.returncode}: {err.strip()[:500]}")


#: What the release build adds to fpm's release profile (``make release``
#: passes the same; a test holds the Makefile to it). ``-static``: no
#: dynamic loader and no shared Fortran run-time library to map and bind at
#: start-up, about 1 ms of every run; ``-flto``: the routines of legacy/,
#: one file each, inlined into each other at the link. Neither changes a
#: result: every tape is the same byte for byte (docs/PERFORMANCE.md).
RELEASE_FLAGS = "-flto -static"


def release_binary(tree: Path, flags: str = RELEASE_FLAGS) -> Path:
    """Build the TENZOR of ``tree`` optimised (``fpm build --profile
    release --flag FLAGS``, :data:`RELEASE_FLAGS` unless told otherwise;
    fpm gives the flags to the compiler and the link, and builds each set
    in a directory of its own) and return the path of the executable.
    SystemExit when fpm is not on PATH; CalledProcessError (its output
    captured) when the build fails."""
    fpm = shutil.which("fpm")
    if fpm is None:
        raise SystemExit("fpm is not on PATH: run `make bench`, or put .venv/bin on PATH")
    profile = ["--profile", "release"] + (["--flag", flags] if flags else [])
    subprocess.run([fpm, "build", *profile], cwd=tree, check=True, capture_output=True)
    out = subprocess.run([fpm, "run", *profile, "--runner", "echo", "tenzor"],
                         cwd=tree, check=True, capture_output=True, text=True).stdout.split()
    return tree / out[-1]


def _start(exe: Path, deck: Path, out: Path,
           env: dict[str, str] | None = None) -> subprocess.Popen:
    out.mkdir(parents=True, exist_ok=True)
    return subprocess.Popen([str(exe), str(deck), "-o", str(out)], env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def run_once(exe: Path, deck: Path, out: Path,
             env: dict[str, str] | None = None) -> tuple[float, float]:
    """One run of TENZOR, deck to tapes: (wall seconds, CPU seconds, user
    and system, of that process from ``os.wait4``).  Raises RuntimeError if
    it does not exit 0.  ``env``: the process's environment, if not this
    one's.

    The output directory is emptied first (outside the timing), so every run
    writes new files as a first run does: replacing the files of the run
    before would add the file system's work of the rename over an existing
    file (ext4 writes the new data out before such a rename,
    ``auto_da_alloc``), which is the disk's time, not TENZOR's."""
    shutil.rmtree(out, ignore_errors=True)
    t = time.perf_counter()
    proc = _start(exe, deck, out, env)
    _, status, usage = os.wait4(proc.pid, 0)
    seconds = time.perf_counter() - t
    proc.returncode = os.waitstatus_to_exitcode(status)
    _check(proc, deck)
    proc.stderr.close()
    return seconds, usage.ru_utime + usage.ru_stime


def time_tenzor(exe: Path, deck: Path, out: Path, repeats: int,
                budget: float = 1.0, cap: int = 30) -> tuple[list[float], list[float]]:
    """Wall and CPU times of at least ``repeats`` runs, each in a fresh
    process; short runs are repeated until they add up to ``budget``
    seconds (at most ``cap`` runs), since the wall time of a run of a few
    milliseconds on a shared machine is mostly the wait for a free core."""
    # What earlier boards wrote (a 100 000-pad board's tapes, verify's
    # files) is written out first: the file system's writeback of it must
    # not land in this board's fsyncs. Outside the timing.
    os.sync()
    runs = []
    while len(runs) < repeats or (sum(w for w, _ in runs) < budget and len(runs) < cap):
        runs.append(run_once(exe, deck, out))
    return [w for w, _ in runs], [c for _, c in runs]


def _hwm_kb(pid: int) -> int | None:
    try:
        with open(f"/proc/{pid}/status", encoding="ascii") as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1])
    except OSError:
        pass
    return None


#: A reading below this (KiB) was taken before the program was loaded: just
#: after ``execve`` the new process holds a page or two (4 KiB was seen).
LOADED_KB = 512


def peak_rss(exe: Path, deck: Path, out: Path, runs: int = 3, tries: int = 50) -> int:
    """Peak resident set size of TENZOR, KiB (see the module doc): the largest
    of ``runs`` runs.

    The first 50 ms of a run are sampled without pause (a small board's run
    takes 3-5 ms, and a sample every millisecond could see only the first
    moment after ``execve``, before the program is mapped), then every
    millisecond. The last sample can still come a little before the peak, so
    the largest of several runs is kept. A run that ends before a reading of
    the loaded program is taken does not count, and is run again (at most
    ``tries`` runs in all; 0 if no run ever counted)."""
    peaks: list[int] = []
    for _ in range(tries):
        shutil.rmtree(out, ignore_errors=True)
        proc = _start(exe, deck, out)
        start = time.perf_counter()
        peak = 0
        while proc.poll() is None:
            hwm = _hwm_kb(proc.pid)
            if hwm is not None:
                peak = max(peak, hwm)
            if time.perf_counter() - start > 0.05:
                time.sleep(0.001)
        _check(proc, deck)
        proc.stderr.close()
        if peak >= LOADED_KB:
            peaks.append(peak)
            if len(peaks) == runs:
                break
    return max(peaks, default=0)


@contextmanager
def executed_limit(limit: int):
    """Let :mod:`harness.sim` run more executed frames than its default
    (10**6) while inside; the 100 000-pad tapes need it."""
    old = sim.MAX_EXECUTED
    sim.MAX_EXECUTED = max(old, limit)
    try:
        yield
    finally:
        sim.MAX_EXECUTED = old


@dataclass
class TapeStats:
    name: str
    rows: int
    frames: int
    unrolled_rows: int         # rows of the same frames, cycles unrolled
    executed: int              # frames executed (cycles unrolled)
    drawn_mm: float
    travel_mm: float
    minutes: float
    run: sim.Run

    @property
    def cycle_ratio(self) -> float:
        """Rows as punched over rows without cycles."""
        return self.rows / self.unrolled_rows


def unrolled_rows(frames: list[tape.Frame], code: str) -> int:
    """Rows of the tape the same frames would make without cycles: every
    cycle written out, frame after frame, with the same leader."""
    flat = [tape.Frame(f.x, f.y, f.dx, f.dy, 0, f.k) for f in sim.unroll(frames)]
    return len(tape.encode(flat, code))


def read_tape(path: Path) -> TapeStats:
    data = path.read_bytes()
    decoded = tape.decode(data)
    with executed_limit(10**7):
        run = sim.simulate(decoded.frames)
        flat = unrolled_rows(decoded.frames, decoded.code)
    return TapeStats(path.stem.rsplit("-", 1)[-1], len(data), len(decoded.frames), flat,
                     run.executed, run.drawn_mm, run.travel_mm, run.minutes, run)


def read_tapes(out: Path, name: str) -> dict[str, TapeStats]:
    """The three tapes of package ``name`` in ``out``."""
    return {t: read_tape(out / f"{name}-{t}.ptp") for t in TAPES}


def read_job(path: Path) -> dict[str, str]:
    """A job sheet's ``key = value`` lines."""
    job: dict[str, str] = {}
    for line in path.read_text(encoding="ascii").splitlines():
        if line.strip() and not line.startswith("#"):
            key, _, value = line.partition("=")
            job[key.strip()] = value.strip()
    return job


@dataclass
class VerifyStats:
    seconds: float             # wall time
    cpu: float                 # user + system
    peak_rss_kb: int
    passed: bool


def time_verify(deck: Path, tapes: Path) -> VerifyStats:
    """One run of ``python -m harness verify DECK TAPES`` in a fresh process
    (this Python, from the project's root): wall time, CPU time from
    ``os.wait4``, and the peak resident set size read from ``VmHWM`` every
    10 ms (the check runs for seconds; the high-water mark only grows, so
    the last reading is within 10 ms of the end).  Raises RuntimeError if
    it exits with neither 0 (PASS) nor 1 (FAIL)."""
    root = Path(__file__).resolve().parents[1]
    t = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "harness", "verify", str(deck), str(tapes)],
                            cwd=root, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    peak = 0
    while True:
        hwm = _hwm_kb(proc.pid)
        if hwm is not None:
            peak = max(peak, hwm)
        pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
        if pid:
            break
        time.sleep(0.01)
    seconds = time.perf_counter() - t
    proc.returncode = code = os.waitstatus_to_exitcode(status)
    err = proc.stderr.read().decode(errors="replace") if proc.stderr else ""
    proc.stderr.close()
    if code not in (0, 1):
        raise RuntimeError(f"harness verify {deck} exited {code}: {err.strip()[-500:]}")
    return VerifyStats(seconds, usage.ru_utime + usage.ru_stime, peak, code == 0)
