"""harness.files.write_whole, the whole-file writer of every Python writer."""
from __future__ import annotations

import os
import subprocess
import sys

import pytest

from harness.files import write_whole
from harness.tests.helpers import file_size_limit


def test_writes_and_replaces_whole(tmp_path):
    target = tmp_path / "out.txt"
    write_whole(target, "first\n")
    write_whole(target, b"second\n")
    assert target.read_bytes() == b"second\n"
    assert [p.name for p in tmp_path.iterdir()] == ["out.txt"], "a temporary file is left"


def test_a_folder_that_is_not_there_is_named_by_the_file_asked_for(tmp_path):
    """The error names the file asked for, not the temporary file beside it
    (the tools print its name)."""
    target = tmp_path / "nowhere" / "out.txt"
    with pytest.raises(FileNotFoundError) as err:
        write_whole(target, "x")
    assert err.value.filename == str(target)


def test_a_failed_write_leaves_the_old_file_and_no_temporary(tmp_path):
    target = tmp_path / "out.txt"
    write_whole(target, "good\n")
    with pytest.raises(UnicodeEncodeError):
        write_whole(target, "not ascii: \u00e9\n")
    (tmp_path / "dir").mkdir()
    with pytest.raises(IsADirectoryError):
        write_whole(tmp_path / "dir", "x")
    assert target.read_text() == "good\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["dir", "out.txt"]


def test_a_full_disk_leaves_the_old_file_and_no_temporary(tmp_path):
    """Files may not grow past 2 000 bytes (SIGXFSZ ignored: the write fails
    with EFBIG, as a full disk fails with ENOSPC), in a child process: the
    OSError reaches the caller, the old file is as it was, no temporary is
    left; and a command of the seeds built on it says so in one line, exit 2."""
    target = tmp_path / "out.txt"
    write_whole(target, "good\n")
    code = ("import sys\nfrom harness.files import write_whole\n"
            "try:\n    write_whole(sys.argv[1], 'x' * 100_000)\n"
            "except OSError as exc:\n    print(exc.errno, exc.strerror)\n")
    proc = subprocess.run([sys.executable, "-c", code, str(target)], capture_output=True,
                          text=True, preexec_fn=file_size_limit(2000), restore_signals=False,
                          timeout=60)
    assert proc.stdout.strip() == "27 File too large", (proc.stdout, proc.stderr)
    assert target.read_text() == "good\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.txt"]
    deck = tmp_path / "flange.crd"
    deck.write_text("old\n")
    profile = ["-m", "seeds", "profile", "-o", str(deck)]
    points = tmp_path / "points.txt"
    points.write_text("".join(f"{i} {i * i % 97}\n" for i in range(200)))
    proc = subprocess.run([sys.executable, *profile, str(points)], capture_output=True,
                          text=True, preexec_fn=file_size_limit(2000), restore_signals=False,
                          timeout=120)
    assert proc.returncode == 2, (proc.stdout, proc.stderr)
    assert "File too large" in proc.stderr and "Traceback" not in proc.stderr, proc.stderr
    assert deck.read_text() == "old\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["flange.crd", "out.txt",
                                                            "points.txt"]


def test_a_planted_link_is_replaced_not_followed(tmp_path):
    victim = tmp_path / "victim"
    victim.write_text("precious")
    link = tmp_path / "out.txt"
    link.symlink_to(victim)
    write_whole(link, "new\n")
    assert victim.read_text() == "precious"
    assert not link.is_symlink() and link.read_text() == "new\n"


def test_an_output_over_an_input_is_refused(tmp_path):
    deck = tmp_path / "deck.crd"
    deck.write_text("DECK\n")
    with pytest.raises(OSError, match="will not write over its own input"):
        write_whole(tmp_path / "." / "deck.crd", "x", inputs=[deck])
    assert deck.read_text() == "DECK\n"


def test_a_pipe_is_written_straight_into(tmp_path):
    """/dev/stdout, a pipe here: written into, never renamed over."""
    code = ("from harness.files import write_whole; "
            "write_whole('/dev/stdout', 'through the pipe\\n')")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=dict(os.environ), timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout == "through the pipe\n"
    assert os.path.islink("/dev/stdout")


def test_the_file_mode_follows_the_umask(tmp_path):
    old = os.umask(0o022)
    try:
        write_whole(tmp_path / "f", "x")
    finally:
        os.umask(old)
    assert (tmp_path / "f").stat().st_mode & 0o777 == 0o644
