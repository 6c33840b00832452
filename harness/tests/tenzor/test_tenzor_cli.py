"""The tenzor command as a user runs it: options, standard input, output
directory, listing and job sheet, and byte-identical output run after run."""
from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from harness import tape
from harness.tests.helpers import read_job

ROOT = Path(__file__).resolve().parents[3]
EXAMPLE5 = ROOT / "examples" / "report" / "example5.crd"


def _files(out: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(out.iterdir())}


def test_help(tenzor_exe):
    proc = subprocess.run([tenzor_exe, "--help"], capture_output=True, text=True)
    assert proc.returncode == 0
    assert "usage: tenzor [DECK] [-o DIR] [--code 8|K]" in proc.stdout


@pytest.mark.parametrize("args,fragment,usage", [
    (["--bogus"], "unknown option --bogus", True),
    (["--code"], "--code needs 8 or K", True),
    (["--code", "9", "x.crd"], '--code takes 8 (the "8" code) or K', True),
    (["-o"], "needs a directory", True),
    (["a.crd", "b.crd"], "one deck at a time", True),
    (["/nonexistent/deck.crd"], "cannot open the deck", False),
    (["/"], "cannot read the deck", False),
    ([""], "an empty argument is not a deck", True),
])
def test_usage_errors_exit_2_with_one_clear_line(tenzor_exe, tmp_path, args, fragment, usage):
    """A usage error gives the usage line after it; a deck that cannot be
    read is no usage error, and its one line stands alone."""
    proc = subprocess.run([tenzor_exe, *args], capture_output=True, text=True, cwd=tmp_path)
    assert proc.returncode == 2
    assert fragment in proc.stderr
    assert proc.stderr.count("\n") == (2 if usage else 1), proc.stderr
    assert ("usage: tenzor" in proc.stderr) == usage
    assert "Fortran runtime" not in proc.stderr and "Backtrace" not in proc.stderr


def test_unwritable_output_directory_exits_2(tenzor_exe, tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("not a directory")
    proc = subprocess.run([tenzor_exe, EXAMPLE5, "-o", blocker / "out"], capture_output=True, text=True)
    assert proc.returncode == 2
    assert "cannot create the output directory" in proc.stderr
    proc = subprocess.run([tenzor_exe, EXAMPLE5, "-o", blocker], capture_output=True, text=True)
    assert (proc.returncode, proc.stderr) == (2, f"tenzor: cannot create the output directory "
                                                 f"{blocker}: a file of that name is in the "
                                                 f"way; -o names a directory\n")


def test_an_output_name_too_long_for_a_file_name_is_said_so(tenzor_exe, tmp_path):
    """A name of 256 characters in the -o path cannot be made (ENAMETOOLONG);
    255 can. Nothing is written for the long one."""
    long = tmp_path / ("a" * 256) / "out"
    proc = subprocess.run([tenzor_exe, EXAMPLE5, "-o", long], capture_output=True, text=True)
    assert (proc.returncode, proc.stderr) == (2, f"tenzor: cannot create the output directory "
                                                 f"{long}: a name in it is longer than the 255 "
                                                 "characters a file name may have\n")
    assert list(tmp_path.iterdir()) == []
    ok = tmp_path / ("b" * 255)
    proc = subprocess.run([tenzor_exe, EXAMPLE5, "-o", ok], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    assert any(ok.glob("*.ptp"))


def test_standard_input_and_default_output_directory(tenzor_exe, tmp_path):
    proc = subprocess.run([tenzor_exe], stdin=EXAMPLE5.open("rb"), capture_output=True,
                          text=True, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    assert "EXAMPLE5: tapes out/EXAMPLE5-small.ptp" in proc.stdout
    names = sorted(p.name for p in (tmp_path / "out").iterdir())
    assert names == ["EXAMPLE5-cond.ptp", "EXAMPLE5-cond.txt", "EXAMPLE5-large.ptp",
                     "EXAMPLE5-large.txt", "EXAMPLE5-small.ptp", "EXAMPLE5-small.txt",
                     "EXAMPLE5.job", "EXAMPLE5.lst"]


def test_nested_output_directory_is_created(run_tenzor, tmp_path):
    proc, out = run_tenzor(EXAMPLE5, out=tmp_path / "a" / "b" / "c")
    assert proc.returncode == 0
    assert (out / "EXAMPLE5-cond.ptp").exists()


def test_output_is_byte_identical_run_after_run(run_tenzor):
    decks = sorted((ROOT / "examples").rglob("*.crd"))
    for deck in decks:
        a, out_a = run_tenzor(deck)
        b, out_b = run_tenzor(deck)
        assert a.returncode == b.returncode
        assert a.stdout.replace(bytes(out_a), b"") == b.stdout.replace(bytes(out_b), b"")
        assert _files(out_a) == _files(out_b), deck


def test_crlf_deck_reads_like_lf(run_tenzor):
    text = EXAMPLE5.read_text()
    _, out_lf = run_tenzor(text)
    _, out_crlf = run_tenzor(text.replace("\n", "\r\n"))
    assert _files(out_lf) == _files(out_crlf)


def test_listing_has_heading_echo_statistics_and_plot(run_tenzor):
    proc, out = run_tenzor(EXAMPLE5)
    lines = (out / "EXAMPLE5.lst").read_text().splitlines()
    assert all(len(line) <= 128 for line in lines)
    text = "\n".join(lines)
    assert "JOB      REPORT EXAMPLE 5" in text
    assert "ENVELOPE *MAIN TENZOR" in text
    deck = EXAMPLE5.read_text().splitlines()
    m_card = next(i for i, line in enumerate(deck, 1) if line.startswith("M"))
    assert f"{m_card:8d} {deck[m_card - 1]}" in lines
    assert "TAPE L  CONDUCTORS" in text
    # the saw: 8 x (5 mm + sqrt(17) mm) drawn, 32 mm back raised
    assert "DRAWN         72.98 MM   TRAVEL         32.00 MM" in text
    assert "CONTROL PLOT, TAPE L (CONDUCTORS)" in text


def test_job_sheet_carries_what_the_tools_need(run_tenzor):
    _, out = run_tenzor(EXAMPLE5)
    job = read_job(out / "EXAMPLE5.job")
    assert job["name"] == "EXAMPLE5"
    assert job["code"] == "8"
    assert job["scale"] == "1:1"
    assert (job["start_x_mm"], job["start_y_mm"]) == ("10.00", "10.00")
    for t, tool in (("small", "0.50"), ("large", "1.00"), ("cond", "0.50")):
        assert job[f"{t}.tape"] == f"EXAMPLE5-{t}.ptp"
        assert job[f"{t}.tool_mm"] == tool
        data = (out / job[f"{t}.tape"]).read_bytes()
        assert job[f"{t}.rows"] == str(len(data))
        assert job[f"{t}.frames"] == str(len(tape.decode(data).frames))


def test_package_names_are_sanitised(run_tenzor):
    deck = "  MY/BOARD v1.2    \n" + "M" + " " * 35 + "1.00" + " " * 18 + "10\nE\n"
    proc, out = run_tenzor(deck)
    assert proc.returncode == 0, proc.stderr
    assert (out / "MY_BOARD_v1_2-cond.ptp").exists()


def test_fifo_and_standard_input_read_the_bytes_of_a_file(tenzor_exe, tmp_path):
    """A deck through a FIFO (as `tenzor <(make-deck)` gives it) or standard
    input reads exactly as the same bytes in a file: a CR not before a LF is
    a bad byte in all three, never a line end."""
    import os
    import threading
    deck = EXAMPLE5.read_bytes().replace(b"EXAMPLE5\n", b"EXAMPLE5\rX\n")
    path = tmp_path / "deck.crd"
    path.write_bytes(deck)
    results = []
    proc = subprocess.run([tenzor_exe, path, "-o", tmp_path / "a"], capture_output=True)
    results.append(proc)
    proc = subprocess.run([tenzor_exe, "-o", tmp_path / "b"], input=deck, capture_output=True)
    results.append(proc)
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    writer = threading.Thread(target=fifo.write_bytes, args=(deck,))
    writer.start()
    proc = subprocess.run([tenzor_exe, fifo, "-o", tmp_path / "c"], capture_output=True,
                          timeout=60)
    writer.join()
    results.append(proc)
    errs = [p.stderr.decode().replace(label, "DECK") for p, label in
            zip(results, [str(path), "<stdin>", str(fifo)])]
    assert [p.returncode for p in results] == [1, 1, 1]
    assert errs[0] == errs[1] == errs[2]
    assert "CARD 4 COL 9: BYTE 13 IS NOT A CARD CHARACTER" in errs[0]
    assert _files(tmp_path / "a") == _files(tmp_path / "b") == _files(tmp_path / "c")


def _package_agrees_with_its_job_sheet(out: Path, name: str) -> bool:
    import hashlib
    keys = read_job(out / f"{name}.job")
    for file_key, size_key, sha_key in [("listing", "listing.bytes", "listing.sha256")] + [
            (f"{t}.{k}", f"{t}.{'bytes' if k == 'tape' else 'text_bytes'}",
             f"{t}.{'sha256' if k == 'tape' else 'text_sha256'}")
            for t in ("small", "large", "cond") for k in ("tape", "text")]:
        data = (out / keys[file_key]).read_bytes()
        if keys[size_key] != str(len(data)) or keys[sha_key] != hashlib.sha256(data).hexdigest():
            return False
    return True


def test_concurrent_runs_into_one_directory_never_mix(tenzor_exe, tmp_path):
    """Eight runs at once into one directory, of two decks whose packages have
    one name: every run succeeds, no temporary file is left, and the package
    in the directory is one run's whole (its files are the ones its job
    sheet records). Repeated, so that the runs' commits interleave."""
    decks = []
    for n, size in enumerate(("1.00", "2.00")):
        deck = tmp_path / f"deck{n}.crd"
        deck.write_text("SAME\nP             100.00    100.00\n"
                        f"D              10.00     10.00    {size}\n"
                        "L              20.00     20.00    0.50\n+              40.00     20.00\nE\n")
        decks.append(deck)
    out = tmp_path / "out"
    for _ in range(5):
        procs = [subprocess.Popen([str(tenzor_exe), str(decks[i % 2]), "-o", str(out)],
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE)
                 for i in range(8)]
        for p in procs:
            stdout, stderr = p.communicate(timeout=120)
            assert p.returncode == 0, stderr.decode()
        assert sorted(p.name for p in out.iterdir()) == [
            "SAME-cond.ptp", "SAME-cond.txt", "SAME-large.ptp", "SAME-large.txt",
            "SAME-small.ptp", "SAME-small.txt", "SAME.job", "SAME.lst"]
        assert _package_agrees_with_its_job_sheet(out, "SAME")


@pytest.mark.parametrize("delay", [0.02, 0.05, 0.1, 0.2, 0.4])
def test_a_run_killed_mid_job_leaves_whole_packages(tenzor_exe, tmp_path, delay):
    """SIGKILL at some moment of a job of many packages over an earlier run's
    output: every job sheet in the directory belongs with the files beside it
    (the job sheet is committed last, so a package whose tapes were renamed
    but not its sheet still has the earlier run's sheet, which then must not
    agree, or none). Only whole packages are taken as punched."""
    import signal
    import time
    pads = "".join(f"D         {10 + i:6d}.00     10.00    1.00\n" for i in range(60))
    deck = tmp_path / "many.crd"
    deck.write_text("".join(f"PKG{k}\n{pads}C\n" for k in range(80)).rstrip("C\n") + "\nE\n")
    out = tmp_path / "out"
    first = subprocess.run([str(tenzor_exe), str(deck), "-o", str(out)], capture_output=True,
                           timeout=300)
    assert first.returncode == 0, first.stderr.decode()
    deck.write_text(deck.read_text().replace("    1.00\n", "    1.20\n"))
    proc = subprocess.Popen([str(tenzor_exe), str(deck), "-o", str(out)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(delay)
    proc.send_signal(signal.SIGKILL)
    proc.wait(timeout=60)
    new = old = 0
    for k in range(80):
        if _package_agrees_with_its_job_sheet(out, f"PKG{k}"):
            # whole: the earlier run's or the new one's, never a mixture
            small = (out / f"PKG{k}-small.txt").read_text()
            new += "1.20" in (out / f"PKG{k}.lst").read_text()
            old += "1.20" not in (out / f"PKG{k}.lst").read_text()
            assert small
        else:
            # caught between its tapes and its sheet: the sheet must say so
            assert (out / f"PKG{k}.job").exists()
    assert new + old >= 79


@pytest.mark.parametrize("program", ["tenzor", "em703"])
def test_version_is_fpm_tomls(tenzor_exe, em703_exe, program):
    import tomllib
    want = tomllib.loads((Path(__file__).resolve().parents[3] / "fpm.toml").read_text())
    exe = tenzor_exe if program == "tenzor" else em703_exe
    proc = subprocess.run([str(exe), "--version"], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0 and proc.stderr == ""
    assert proc.stdout.startswith(f"{program} {want['version']} (EM-703 tape subsystem")
    assert proc.stdout.count("\n") == 1


def test_a_deck_over_a_gibibyte_is_refused(tenzor_exe, tmp_path):
    """A regular file over 1 GiB is refused from its size, unread (a sparse
    file here: nothing is written to disk)."""
    deck = tmp_path / "huge.crd"
    with deck.open("wb") as f:
        f.truncate(2 ** 30 + 1)
    proc = subprocess.run([tenzor_exe, deck, "-o", tmp_path / "out"], capture_output=True,
                          text=True)
    assert (proc.returncode, proc.stderr) == (2, f"tenzor: {deck}: the deck has more than "
                                                 f"1073741824 bytes; split the job\n")
    assert not (tmp_path / "out").exists() or not list((tmp_path / "out").iterdir())
