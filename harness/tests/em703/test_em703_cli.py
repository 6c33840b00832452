"""The em703 command line: every subcommand has --help; a usage or I/O error
is one line on standard error with exit status 2, a bad input one line
naming the file and the row (or line) with exit status 1, and never a
Fortran runtime error; outputs are the same bytes from run to run."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from harness.tape import Frame, encode

from harness.tests.helpers import file_size_limit, run, write_job

SUBCOMMANDS = ["list", "sim", "svg", "gcode", "gerber", "punch", "view", "html"]


def one_line(proc) -> str:
    err = proc.stderr.decode("utf-8")
    assert err.count("\n") == 1 and err.endswith("\n"), err
    assert "Fortran runtime" not in err and "Error termination" not in err, err
    return err[:-1]


def test_help(em703_exe) -> None:
    for args in (["--help"], ["-h"], ["help"]):
        text = run(em703_exe, *args, check=0).stdout.decode()
        assert text.startswith("usage: em703 SUBCOMMAND")
        for sub in SUBCOMMANDS:
            assert f"  {sub} " in text
    for sub in SUBCOMMANDS:
        for flag in ("--help", "-h"):
            proc = run(em703_exe, sub, flag, check=0)
            text = proc.stdout.decode("utf-8")
            assert text.startswith(f"usage: em703 {sub} "), text
            assert "Exit status" in text and proc.stderr == b""
            assert max(len(line) for line in text.splitlines()) <= 80


def test_help_on_a_subcommand_is_its_help(em703_exe) -> None:
    for sub in SUBCOMMANDS + ["drill", "split", "check"]:
        assert run(em703_exe, "help", sub, check=0).stdout == \
            run(em703_exe, sub, "--help", check=0).stdout


@pytest.mark.parametrize("sub, code, read", [
    ("list", "k", "K"), ("list", "AUTO", "auto"), ("sim", "Auto", "auto"),
    ("view", "EM703", "em703"), ("view", "ISO", "iso"), ("punch", "Eia", "eia")])
def test_the_letters_of_a_code_are_read_in_either_case(em703_exe, example_tapes, tmp_path,
                                                       sub, code, read) -> None:
    if sub == "punch":
        src = tmp_path / "p.ngc"
        src.write_text("G00 X1\n")
        args = [["--code", c, "-o", tmp_path / f"{c}.ptp", src] for c in (code, read)]
        for a in args:
            run(em703_exe, "punch", *a, check=0)
        assert (tmp_path / f"{read}.ptp").stat().st_size > 0
        assert (tmp_path / f"{code}.ptp").read_bytes() == (tmp_path / f"{read}.ptp").read_bytes()
        return
    tape = example_tapes[0]
    a, b = (run(em703_exe, sub, tape, "--code", c) for c in (code, read))
    assert (a.returncode, a.stdout, a.stderr) == (b.returncode, b.stdout, b.stderr)


@pytest.mark.parametrize("args, words", [
    ([], "no subcommand"),
    (["frobnicate"], 'unknown subcommand "frobnicate"'),
    (["list"], "missing TAPE"),
    (["list", "a.ptp", "b.ptp"], "one file at a time"),
    (["list", "--code", "9", "a.ptp"], "--code takes 8, K or auto"),
    (["list", "--utf9", "a.ptp"], "unknown option --utf9"),
    (["sim", "a.ptp", "--scale", "10:1"], "--scale takes one of the machine's scales"),
    (["sim", "a.ptp", "--scale", "x"], "--scale takes"),
    (["sim", "a.ptp", "--start", "1300,0"], "--start takes X,Y in mm on the field"),
    (["sim", "a.ptp", "--start", "5"], "--start takes"),
    (["sim", "a.ptp", "--tool", "0"], "--tool takes"),
    # 184467440737095517 mm is 2**64 + 84 units: not 0.84 mm
    (["sim", "a.ptp", "--tool", "184467440737095517"], "--tool takes the tool width in mm"),
    (["sim", "a.ptp", "--start", "184467440737095517,0"], "--start takes X,Y in mm on the field"),
    (["sim", "a.ptp", "--svg"], "option --svg needs a value"),
    (["svg"], "missing JOB"),
    (["gcode", "a.ptp", "--chords", "0"], "--chords takes the tolerance in mm"),
    (["gcode", "a.ptp", "--chords", "1e-3"], "--chords takes"),
    (["gerber"], "missing JOB"),
    (["punch", "a.txt"], "missing --code iso|eia"),
    (["punch", "--code", "ascii", "a.txt"], "--code takes iso or eia"),
    (["view", "a.ptp", "--rows", "5:2"], "--rows takes FIRST:LAST"),
    (["view", "a.ptp", "--code", "baudot"], "--code takes auto, em703, iso or eia"),
    (["html"], "missing JOB"),
    (["html", "a.job", "--utf8"], "unknown option --utf8"),
    (["html", "a.job", "-o"], "option -o needs a value"),
    (["list", "a.ptp", "--code", "8", "--code", "K"], "option --code given twice: give it once"),
    (["gcode", "a.job", "-o", "x", "--output", "y"], "option --output given twice"),
    (["list", "--bare", "a.ptp", "--bare"], "option --bare given twice"),
    (["sim", "a.ptp", "--svg", "--tool", "1"],
     "option --svg needs a value, not the option --tool (a file of that name: ./--tool)"),
    (["list", "a.ptp", "--code", "ISO"], '--code takes 8, K or auto, not "ISO"'),
    (["help", "frobnicate"], 'unknown subcommand "frobnicate"'),
    (["help", "list", "sim"], 'help takes one subcommand, not "sim" too'),
    (["gerber", "a.job", "-o", ""], "-o needs a file name, not an empty one"),
    (["svg", "a.job", "--output", ""], "--output needs a file name, not an empty one"),
    (["split", "--bogus", "5", "5"], "unknown option --bogus"),
    (["split", "-x", "5", "5"], "unknown option -x"),
])
def test_usage_errors_are_one_line_with_status_2(em703_exe, args, words) -> None:
    proc = run(em703_exe, *args, check=2)
    line = one_line(proc)
    assert line.startswith("em703") and words in line, line
    assert proc.stdout == b""


@pytest.mark.parametrize("sub", ["list", "sim", "svg", "gcode", "gerber", "view", "html"])
def test_missing_and_unreadable_files_are_status_2(em703_exe, tmp_path, sub) -> None:
    missing = tmp_path / "nothing.job"
    line = one_line(run(em703_exe, sub, missing, check=2))
    assert line == f"{missing}: cannot open: no such file"
    line = one_line(run(em703_exe, sub, tmp_path, check=2))
    assert line.startswith(f"{tmp_path}: cannot ")


def test_unwritable_output_is_status_2(em703_exe, example_jobs, tmp_path) -> None:
    job = example_jobs[0]
    target = tmp_path / "no" / "such" / "dir" / "x.out"
    for sub in ("svg", "gcode", "gerber", "html"):
        line = one_line(run(em703_exe, sub, job, "-o", target, check=2))
        assert line.startswith(f"{target}: cannot write")
    src = tmp_path / "p.ngc"
    src.write_text("G00 X1\n")
    one_line(run(em703_exe, "punch", "--code", "iso", "-o", target, src, check=2))
    assert not target.exists()


def test_a_bad_tape_is_status_1_naming_the_row(em703_exe, tmp_path) -> None:
    data = bytearray(encode([Frame(dx=500, k=10), Frame(dx=-500, k=20)]))
    data[25] = 0o33                          # a row outside the code
    bad = tmp_path / "bad.ptp"
    bad.write_bytes(bytes(data))
    for sub in ("list", "sim", "gcode"):
        line = one_line(run(em703_exe, sub, bad, check=1))
        assert line == f"{bad}: row 26: code 33 (octal) is not an EM-703 code"


def test_a_bad_job_sheet_is_status_1_naming_the_line(em703_exe, example_jobs, tmp_path) -> None:
    job = example_jobs[0]
    for name in ("small", "large", "cond"):
        for tape in job.parent.glob(f"*-{name}.ptp"):
            (tmp_path / tape.name).write_bytes(tape.read_bytes())
    lines = job.read_text().splitlines()
    bad = tmp_path / "bad.job"
    bad.write_text("\n".join(lines[:3] + ["scale: 1:1"] + lines[3:]) + "\n")
    for sub in ("svg", "gcode", "gerber", "html"):
        line = one_line(run(em703_exe, sub, bad, check=1))
        assert line == f'{bad}: line 4: not a "key = value" line: "scale: 1:1"'
    tape_job = tmp_path / "tape.job"
    tape_job.write_bytes((tmp_path / keys_of(job)["cond.tape"]).read_bytes())
    for sub in ("svg", "gcode", "gerber", "drill", "html"):
        line = one_line(run(em703_exe, sub, tape_job, check=1))
        assert line == (f"{tape_job}: line 1, column 1: byte 000 (octal) is not text: a job "
                        "sheet is the text NAME.job that TENZOR writes beside the tapes (a "
                        "tape is read by em703 list)")
    long = tmp_path / "long.job"
    long.write_text("name = X\n" + "7" * 100_000 + "\n")
    line = one_line(run(em703_exe, "svg", long, check=1))
    assert line == f'{long}: line 2: not a "key = value" line: "{"7" * 60}..."'
    no_tool = tmp_path / "no_tool.job"
    no_tool.write_text("\n".join(l for l in lines if not l.startswith("cond.tool_mm")) + "\n")
    line = one_line(run(em703_exe, "gerber", no_tool, check=1))
    assert line == f'{no_tool}: the job sheet has no "cond.tool_mm = ..." line'
    for width in ("0.00", "1200.01", "99999999999999.00", "184467440737095517"):
        wide = tmp_path / "wide.job"
        wide.write_text("\n".join(f"cond.tool_mm = {width}" if l.startswith("cond.tool_mm")
                                  else l for l in lines) + "\n")
        number = next(k for k, l in enumerate(lines, 1) if l.startswith("cond.tool_mm"))
        for sub in ("svg", "gcode", "gerber", "drill", "html"):
            line = one_line(run(em703_exe, sub, wide, check=1))
            assert line == (f"{wide}: line {number}: cond.tool_mm must be a tool width in mm "
                            f"(above 0, at most 1200.00, the field; two decimals), "
                            f'not "{width}"')
    gone = tmp_path / "gone.job"
    gone.write_text(job.read_text())
    (tmp_path / keys_of(job)["large.tape"]).unlink()
    line = one_line(run(em703_exe, "svg", gone, check=2))
    assert line.endswith(": cannot open: no such file")


def keys_of(job: Path) -> dict[str, str]:
    return dict(line.split(" = ", 1) for line in job.read_text().splitlines()
                if " = " in line and not line.startswith("#"))


def test_a_tape_that_does_not_end_at_its_start_warns_and_shifts_the_next(em703_exe,
                                                                          tmp_path) -> None:
    from harness.tests.helpers import write_job
    job = write_job(tmp_path, "OPEN", {"small": encode([Frame(dx=1000, k=10)]),
                                       "cond": encode([Frame(dy=500, k=10)])}, {})
    proc = run(em703_exe, "gcode", job, check=1)
    assert one_line(proc) == (f"{tmp_path}/OPEN-small.ptp: the tape ends at (10.00, 0.00) mm "
                              "from its start point, not at it: the next tape starts there")
    assert "G01 X10.000 Y5.000" in proc.stdout.decode()


def test_outputs_are_the_same_bytes_every_run(em703_exe, example_tapes, example_jobs,
                                              tmp_path) -> None:
    for job in example_jobs[:3]:
        for sub, extra in (("svg", []), ("gcode", []), ("gcode", ["--chords", "0.01"]),
                           ("gcode", ["--z"]), ("gerber", []), ("html", [])):
            a, b = tmp_path / "a", tmp_path / "b"
            run(em703_exe, sub, job, *extra, "-o", a, check=0)
            run(em703_exe, sub, job, *extra, "-o", b, check=0)
            assert a.read_bytes() == b.read_bytes() and a.stat().st_size > 0
            stdout = run(em703_exe, sub, job, *extra, check=0).stdout
            assert stdout == a.read_bytes()
    for tape in example_tapes[:6]:
        for sub in ("list", "sim", "view"):
            assert run(em703_exe, sub, tape).stdout == run(em703_exe, sub, tape).stdout


def _copy_package(job: Path, to: Path) -> Path:
    """The job sheet and every file it names, copied into `to`."""
    to.mkdir(parents=True, exist_ok=True)
    for name in keys_of(job).values():
        if (job.parent / name).is_file():
            (to / name).write_bytes((job.parent / name).read_bytes())
    (to / job.name).write_bytes(job.read_bytes())
    return to / job.name


@pytest.mark.parametrize("args", [("gcode", "{job}", "-o", "{job}"),
                                  ("gcode", "{job}", "-o", "{small}"),
                                  ("svg", "{job}", "-o", "{cond}"),
                                  ("gerber", "{job}", "-o", "{large}"),
                                  ("html", "{job}", "-o", "{job}"),
                                  ("html", "{job}", "-o", "{cond}"),
                                  ("sim", "{small}", "--svg", "{small}"),
                                  ("gcode", "{small}", "-o", "{small}")])
def test_an_output_over_its_own_input_is_refused(em703_exe, example_jobs, tmp_path,
                                                 args) -> None:
    job = _copy_package(example_jobs[0], tmp_path)
    keys = keys_of(job)
    names = {"job": job, **{t: tmp_path / keys[f"{t}.tape"] for t in ("small", "large", "cond")}}
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    argv = [a.format(**names) for a in args]
    proc = run(em703_exe, *argv, check=2)
    target = argv[-1]
    assert f"em703: will not write {target} over its own input" in proc.stderr.decode()
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before


def test_punch_over_its_own_input_is_refused(em703_exe, tmp_path) -> None:
    src = tmp_path / "p.ngc"
    src.write_text("G00 X1\n")
    proc = run(em703_exe, "punch", "--code", "iso", "-o", tmp_path / "." / "p.ngc", src, check=2)
    assert "over its own input" in proc.stderr.decode()
    assert src.read_text() == "G00 X1\n"


@pytest.mark.parametrize("sub", ["svg", "gcode", "gerber", "html"])
def test_a_tape_that_is_not_the_job_sheets_is_refused(em703_exe, example_jobs, tmp_path,
                                                      sub) -> None:
    """The job sheet records each tape's size and SHA-256: a tape of another
    run (here: one byte changed) is refused, status 1, naming both files."""
    job = _copy_package(example_jobs[0], tmp_path)
    tape = tmp_path / keys_of(job)["large.tape"]
    data = bytearray(tape.read_bytes())
    data[0] ^= 1                             # a leader row, so the tape still decodes
    tape.write_bytes(bytes(data))
    line = one_line(run(em703_exe, sub, job, check=1))
    assert line.startswith(f"{tape}: the tape is not the one the job sheet {job} records")
    assert line.endswith("the package holds files of different runs; run tenzor again")


def test_output_to_dev_stdout_and_a_planted_link(em703_exe, example_jobs, tmp_path) -> None:
    """-o /dev/stdout writes into the pipe (the link in /dev stays); a link
    planted at the output's name is replaced, and the file it pointed to
    keeps its bytes."""
    job = example_jobs[0]
    piped = run(em703_exe, "gcode", job, "-o", "/dev/stdout")
    assert piped.stdout.decode().startswith("%\n") and Path("/dev/stdout").is_symlink()
    victim = tmp_path / "victim"
    victim.write_text("precious")
    out = tmp_path / "x.ngc"
    out.symlink_to(victim)
    run(em703_exe, "gcode", job, "-o", out)
    assert victim.read_text() == "precious"
    assert not out.is_symlink() and out.read_bytes() == piped.stdout
    assert sorted(p.name for p in tmp_path.iterdir()) == ["victim", "x.ngc"]


def test_view_rows_after_the_tape_are_refused(em703_exe, example_tapes) -> None:
    tape = example_tapes[0]
    n = tape.stat().st_size
    line = one_line(run(em703_exe, "view", tape, "--rows", f"{n + 1}:{n + 9}", check=2))
    assert line == (f"{tape}: --rows {n + 1}:{n + 9} begins after the tape's last row, {n} "
                    "(rows are numbered from 1)")
    last = run(em703_exe, "view", tape, "--rows", f"{n}:{n + 9}", check=0).stdout.decode()
    assert f"{n:>5} " in last or f" {n} " in last, last



def test_view_of_an_empty_tape_is_an_empty_picture(em703_exe, tmp_path) -> None:
    """Rows 1 to the end of a tape of no rows: the heading and the two
    borders; a --rows from row 2 on begins after its last row, 0."""
    empty = tmp_path / "empty.ptp"
    empty.write_bytes(b"")
    assert run(em703_exe, "view", empty, check=0).stdout.decode() == (
        "  row  5 4 3   2 1   code  meaning\n      +---------------+\n"
        "      +---------------+\n")
    line = one_line(run(em703_exe, "view", empty, "--rows", "2:3", check=2))
    assert line == (f"{empty}: --rows 2:3 begins after the tape's last row, 0 (rows are "
                    "numbered from 1)")


@pytest.mark.parametrize("args, line", [
    # the ends of each option's range are in it
    (["sim", "--start", "1200,1200"], "start_y_mm = 1200.00"),
    (["sim", "--start", "0,1200.00", "--tool", "20", "--svg", "SVG"], "start_x_mm = 0.00"),
    (["gcode", "--chords", "0.001"], "(arcs as chords within 0.0010 mm)"),
    (["gcode", "--chords", "100"], "(arcs as chords within 100.0000 mm)"),
    # and a step beyond them is not
    (["sim", "--start", "1200,1200.01"], "--start takes X,Y in mm on the field (0 to 1200"),
    (["sim", "--tool", "20.01"], "--tool takes the tool width in mm (0.01 to 20.00)"),
    (["gcode", "--chords", "0.0009"], "--chords takes the tolerance in mm (0.001 to 100)"),
    (["gcode", "--chords", "100.0001"], "--chords takes the tolerance in mm (0.001 to 100)"),
])
def test_option_ranges_take_their_ends(em703_exe, tmp_path, args, line) -> None:
    tape, svg = tmp_path / "still.ptp", tmp_path / "t.svg"
    tape.write_bytes(encode([Frame(k=20)]))
    proc = run(em703_exe, args[0], tape, *[str(svg) if a == "SVG" else a for a in args[1:]])
    if line.startswith("--"):
        assert proc.returncode == 2 and line in one_line(proc), proc.stderr
    else:
        assert proc.returncode == 0, proc.stderr
        assert line in proc.stdout.decode().splitlines()
        if "SVG" in args:
            assert 'id="tool-down" fill="none" stroke="#1a1a1a" stroke-width="20.00"' in \
                svg.read_text()


def test_split_takes_a_negative_move(em703_exe) -> None:
    assert run(em703_exe, "split", "-5", "5", check=0).stdout == b"-5 5\n"


@pytest.mark.parametrize("key, value, words", [
    ("scale", "3:1", "scale must be one of the machine's scales 1:100 1:10 1:5 1:2 1:1 2:1 "
                     '5:1 50:1 100:1, not "3:1"'),
    ("start_x_mm", "1300.00", "start_x_mm must be a place on the field, 0.00 to 1200.00 mm "
                              '(two decimals at most), not "1300.00"'),
    ("start_y_mm", "-5", "start_y_mm must be a place on the field"),
    ("start_x_mm", "184467440737095517", "start_x_mm must be a place on the field"),
])
def test_a_job_sheet_off_the_machine_is_refused(em703_exe, example_jobs, tmp_path, key,
                                                 value, words) -> None:
    job = example_jobs[0]
    for tape in job.parent.glob(f"{job.stem}-*.ptp"):
        (tmp_path / tape.name).write_bytes(tape.read_bytes())
    lines = job.read_text().splitlines()
    number = next(k for k, l in enumerate(lines, 1) if l.startswith(key + " "))
    bad = tmp_path / "bad.job"
    bad.write_text("\n".join(f"{key} = {value}" if k == number else l
                             for k, l in enumerate(lines, 1)) + "\n")
    for sub in ("svg", "gcode", "gerber", "drill", "html"):
        line = one_line(run(em703_exe, sub, bad, check=1))
        assert line.startswith(f"{bad}: line {number}: {words}"), line


@pytest.mark.parametrize("x, y, status", [("1200.00", "0.00", 0), ("0", "1200", 0),
                                          ("1200.01", "0.00", 1), ("0.00", "1200.01", 1)])
def test_a_start_point_on_the_edge_of_the_field_is_on_it(em703_exe, tmp_path, x, y,
                                                         status) -> None:
    job = write_job(tmp_path, "edge", {}, {})
    text = job.read_text().replace("start_x_mm = 600.00", f"start_x_mm = {x}")
    job.write_text(text.replace("start_y_mm = 600.00", f"start_y_mm = {y}"))
    proc = run(em703_exe, "gcode", job, check=status)
    if status:
        key, number = ("start_x_mm", 5) if x != "0.00" else ("start_y_mm", 6)
        assert one_line(proc).startswith(f"{job}: line {number}: {key} must be a place on the "
                                         "field, 0.00 to 1200.00 mm")


def test_a_job_sheet_with_crlf_lines_reads_as_with_lf(em703_exe, example_jobs, tmp_path) -> None:
    job = example_jobs[0]
    for tape in job.parent.glob(f"{job.stem}-*.ptp"):
        (tmp_path / tape.name).write_bytes(tape.read_bytes())
    crlf = tmp_path / job.name
    crlf.write_bytes(job.read_bytes().replace(b"\n", b"\r\n"))
    for sub in ("gcode", "gerber", "drill", "svg"):
        want = run(em703_exe, sub, job, check=0).stdout
        assert run(em703_exe, sub, crlf, check=0).stdout == want, sub


def test_a_tape_too_long_to_draw_names_the_command(em703_exe, tmp_path) -> None:
    """10 000 001 frames run (a cycle of 5 000 000 over two, and one more):
    each writer names itself; sim and html take it."""
    saw = encode([Frame(dx=1, cyc=5_000_000, k=10), Frame(dx=-1, k=20), Frame(k=20)])
    job = write_job(tmp_path, "SAW", {"cond": saw}, {})
    for sub in ("svg", "gcode", "gerber", "drill"):
        line = one_line(run(em703_exe, sub, job, check=1))
        assert line.endswith(": the tape runs 10000001 frames (cycles unrolled): more than the "
                             f"10000000 that {sub} writes one by one (sim and html take any "
                             "tape)"), line
    tape = tmp_path / "SAW-cond.ptp"
    line = one_line(run(em703_exe, "sim", tape, "--svg", tmp_path / "s.svg", check=1))
    assert "that sim --svg writes one by one" in line
    assert not (tmp_path / "s.svg").exists()


def test_a_full_disk_leaves_the_old_output_and_no_temporary_file(em703_exe, example_jobs,
                                                                 tmp_path) -> None:
    """Files may not grow past 200 bytes (SIGXFSZ ignored: a write fails
    with EFBIG, as on a full disk with ENOSPC): the output fails, exit 2
    naming it, and the file that was there is left as it was."""
    target = tmp_path / "board.ngc"
    target.write_text("the old program\n")
    for sub in ("gcode", "svg", "gerber", "html"):
        proc = subprocess.run([str(em703_exe), sub, str(example_jobs[0]), "-o", str(target)],
                              capture_output=True, preexec_fn=file_size_limit(200),
                              restore_signals=False, timeout=120)
        err = proc.stderr.decode()
        assert proc.returncode == 2 and err.startswith(f"{target}: cannot write"), (sub, err)
        assert target.read_text() == "the old program\n"
        assert sorted(p.name for p in tmp_path.iterdir()) == ["board.ngc"]
