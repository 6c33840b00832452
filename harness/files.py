"""Whole-file writes for every Python writer of the project (the harness,
the neighbouring systems of seeds/, the benchmarks): a file is written whole
or not at all.

The bytes go to a new temporary file beside the target, created exclusively
with a fresh name (never an existing file, never through a planted symbolic
link), are flushed and fsynced, and the file is renamed over the target; the
directory is fsynced after. When anything fails (a full disk, a directory in
the way) the temporary file is removed, the target is as it was, and the
OSError goes to the caller, which reports it. ``inputs`` are the files the
command read: an output that is one of them is refused before anything is
written, as the Fortran programs do (src/base/base_files). A target that
exists and is not a regular file (a pipe, a terminal, /dev/stdout) is written
straight into; a symbolic link at the target is replaced, not followed.
"""
from __future__ import annotations

import errno
import functools
import io
import os
import select
import stat
import sys
import tempfile
from collections.abc import Callable, Iterable
from pathlib import Path


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def same_file(a: str | Path, b: str | Path) -> bool:
    """True when a and b name one existing file."""
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False


def write_whole(path: str | Path, data: bytes | str, encoding: str = "ascii",
                inputs: Iterable[str | Path] = ()) -> None:
    """Write data (text in ``encoding``) as the whole file path."""
    path = Path(path)
    for given in inputs:
        if same_file(path, given):
            raise OSError(errno.EEXIST, f"will not write over its own input {given}",
                          str(path))
    if isinstance(data, str):
        data = data.encode(encoding)
    try:
        special = not stat.S_ISREG(os.stat(path).st_mode)
    except OSError:
        special = False
    if special:
        if path.is_dir():
            raise IsADirectoryError(errno.EISDIR, os.strerror(errno.EISDIR), str(path))
        with open(path, "wb") as f:
            f.write(data)
        return
    directory = path.parent if str(path.parent) else Path(".")
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=directory)
    except OSError as exc:
        # the message names the file asked for, not the temporary one beside it
        raise type(exc)(exc.errno, exc.strerror, str(path)) from None
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        os.chmod(tmp, 0o666 & ~_umask())
        os.replace(tmp, path)
    except BaseException as exc:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        if isinstance(exc, OSError) and exc.errno is not None:
            raise type(exc)(exc.errno, exc.strerror, str(path)) from None
        raise
    try:
        dfd = os.open(directory, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(dfd)
    except OSError:
        pass                        # not every file system can; the rename stands
    finally:
        os.close(dfd)


def ascii_text(data: bytes, unit: str = "line") -> str:
    """``data`` as ASCII text; ValueError naming the ``unit`` (line, card)
    and column of the first byte that is not ASCII."""
    try:
        return data.decode("ascii")
    except UnicodeDecodeError as exc:
        bad = exc.start
    line = data.count(b"\n", 0, bad) + 1
    column = bad - (data.rfind(b"\n", 0, bad) + 1) + 1
    raise ValueError(f"{unit} {line}, column {column}: byte {data[bad]:#04x} is not ASCII")


def _reader_gone(stream) -> bool:
    """Whether ``stream`` is a pipe whose reader has closed it (poll's
    POLLERR on its write end); True when that cannot be asked."""
    try:
        poller = select.poll()
        poller.register(stream.fileno(), select.POLLOUT)
        return any(ev & select.POLLERR for _, ev in poller.poll(0))
    except (AttributeError, OSError, ValueError, io.UnsupportedOperation):
        return True


def quiet_when_output_closes(main: Callable[..., int]) -> Callable[..., int]:
    """A command's ``main``, stopped quietly when the reader of its standard
    output (or error) closes the pipe early (``python -m seeds ... | head -1``):
    exit status 2, an I/O failure, instead of BrokenPipeError's traceback
    or Python's "Exception ignored ... BrokenPipeError" at its last flush.
    The closed stream is pointed at /dev/null so that nothing written after
    can fail again.  A BrokenPipeError with both streams still read (a pipe
    to a child process, say) is not this, and is raised as it was."""

    @functools.wraps(main)
    def wrapped(*args, **kwargs) -> int:
        try:
            status = main(*args, **kwargs)
            sys.stdout.flush()
            return status
        except BrokenPipeError:
            gone = [s for s in (sys.stdout, sys.stderr) if _reader_gone(s)]
            if not gone:
                raise
            for stream in gone:
                try:
                    null = os.open(os.devnull, os.O_WRONLY)
                    os.dup2(null, stream.fileno())
                    os.close(null)
                except (OSError, ValueError, io.UnsupportedOperation):
                    pass
            return 2

    return wrapped
