"""The one rule for the files the lab writes and reads (checks/file_rules.json,
the same as the C++ programs' utils/SafeFile and the web peers' src/files.js).

Writing: only a regular file with one link, or nothing, is replaced, in a
folder that exists. check_writable() says so from the path alone; the
writers below check again, write a hidden temporary file beside the target
(a random name, created with O_CREAT | O_EXCL | O_NOFOLLOW: a link planted
there is never followed), flush it to disk, check the target once more and
rename the temporary file over it: a reader sees the old file or the whole
new one, and a failure leaves no temporary file.

Reading: files the lab did not write itself (the build's CMakeCache.txt,
what a program left in its run folder, /proc/cpuinfo) are checked for type
and size before they are opened and again on the open file. A FIFO would
block the open or the read for ever, a device or a sparse file never ends,
and a binary file gives nonsense read as text; each is an InputError
naming the file and what is wrong with it."""

import contextlib
import io
import os
import secrets
import stat

CHUNK = 1 << 20
NAME_MAX = 255  # bytes in one name on Linux file systems
RANDOM_HEX = 16
TEMPORARY_ATTEMPTS = 8


class FileRefused(Exception):
    """A file the lab would write or read is not what the rule allows."""


# Readers raise it under the name their callers have always caught.
InputError = FileRefused


def _temporary_name(base):
    return f".{base}.{secrets.token_hex(RANDOM_HEX // 2)}.tmp"


# The longest target name whose temporary name still fits in NAME_MAX bytes.
LONGEST_NAME = NAME_MAX - len(_temporary_name("").encode())


def kind(mode):
    """What a file that is not a regular file is, in the rule's phrases."""
    for test, name in ((stat.S_ISLNK, "a symbolic link"), (stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a FIFO"),
                       (stat.S_ISCHR, "a device"), (stat.S_ISBLK, "a device"), (stat.S_ISSOCK, "a socket")):
        if test(mode):
            return name
    return "not a regular file"


# ---- writing -----------------------------------------------------------------

def check_writable(path):
    """Raises FileRefused unless `path` may be written by the writers below:
    absent or a regular file with one link, in an existing folder this
    process may create files in, its name short enough for the temporary
    name beside it."""
    path = os.fspath(path)
    folder, base = os.path.split(path)
    folder = folder or "."
    if base in ("", ".", ".."):
        raise FileRefused(f"{path} is a folder")
    if len(os.fsencode(base)) > LONGEST_NAME:
        raise FileRefused(f"{path}: the name is too long (at most {LONGEST_NAME} bytes, so that the hidden "
                          f"temporary name beside it fits)")
    if not os.path.isdir(folder):
        raise FileRefused(f"{path}: no such folder {folder}")
    try:
        info = os.lstat(path)
    except FileNotFoundError:
        info = None
    except OSError as error:
        raise FileRefused(f"{path} cannot be looked at: {error.strerror}") from None
    if info is not None:
        if not stat.S_ISREG(info.st_mode):
            raise FileRefused(f"{path} is {kind(info.st_mode)}; only a regular file is replaced")
        if info.st_nlink > 1:
            raise FileRefused(f"{path} has more than one link; replacing it would part it from the others")
    if not os.access(folder, os.W_OK | os.X_OK):
        raise FileRefused(f"{path}: cannot create files in {folder}")


def _open_temporary(path):
    """(fd, name) of a new temporary file beside `path`, made by this call."""
    folder, base = os.path.split(os.fspath(path))
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | getattr(os, "O_CLOEXEC", 0)
    for attempt in range(1, TEMPORARY_ATTEMPTS + 1):
        name = os.path.join(folder, _temporary_name(base))
        try:
            return os.open(name, flags, 0o644), name
        except FileExistsError:  # planted there, or a clash: that name is not ours
            if attempt == TEMPORARY_ATTEMPTS:
                raise
    raise AssertionError("unreachable")


@contextlib.contextmanager
def replacing(path, newline=None):
    """A text stream whose contents replace `path` whole when the block ends
    without an exception (and are dropped otherwise). Raises FileRefused for
    a target check_writable refuses, OSError for a failed write."""
    check_writable(path)
    fd, temporary = _open_temporary(path)
    try:
        with io.open(fd, "w", encoding="utf-8", newline=newline) as stream:
            yield stream
            stream.flush()
            os.fsync(stream.fileno())
        check_writable(path)  # again: something may have been put there meanwhile
        os.rename(temporary, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(temporary)
        raise


def write_atomically(path, data):
    """Replaces `path` with `data` (str or bytes), whole or not at all."""
    check_writable(path)
    fd, temporary = _open_temporary(path)
    try:
        with io.open(fd, "wb") as stream:
            stream.write(data.encode("utf-8") if isinstance(data, str) else data)
            stream.flush()
            os.fsync(stream.fileno())
        check_writable(path)
        os.rename(temporary, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(temporary)
        raise


# ---- reading -----------------------------------------------------------------

def _check_info(info, path, limit, what):
    if not stat.S_ISREG(info.st_mode):
        raise InputError(f"{what} {path} is {kind(info.st_mode)}, not a regular file")
    if info.st_size > limit:
        raise InputError(f"{what} {path} is {info.st_size} bytes, larger than the {limit} bytes such a file can be")


def _cannot_read(error, path, what):
    if isinstance(error, (FileNotFoundError, NotADirectoryError)):
        return InputError(f"{what} {path} does not exist")
    return InputError(f"cannot read {what} {path}: {error.strerror}")


def check_regular(path, limit, what):
    """Raises InputError unless `path` (not followed if it is a link) is a
    regular file of at most `limit` bytes."""
    try:
        info = os.lstat(path)
    except OSError as error:
        raise _cannot_read(error, path, what) from None
    _check_info(info, path, limit, what)


def read_bytes(path, limit, what):
    """The contents of the regular file `path`, at most `limit` bytes.
    Checked before it is opened (opening a FIFO blocks, opening some devices
    acts), and again on the open file, in case it was swapped meanwhile;
    O_NONBLOCK: opening a FIFO put there meanwhile does not wait for a
    writer. The read stops at limit + 1 bytes, whatever st_size said (/proc
    files say 0; a file may grow while it is read)."""
    try:
        _check_info(os.stat(path), path, limit, what)
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    except OSError as error:
        raise _cannot_read(error, path, what) from None
    try:
        _check_info(os.fstat(fd), path, limit, what)
        chunks, total = [], 0
        while total <= limit:
            chunk = os.read(fd, min(CHUNK, limit + 1 - total))
            if not chunk:
                break
            chunks.append(chunk)
            total += len(chunk)
        if total > limit:
            raise InputError(f"{what} {path} grew larger than the {limit} bytes such a file can be while it was read")
        return b"".join(chunks)
    except OSError as error:
        raise _cannot_read(error, path, what) from None
    finally:
        os.close(fd)


def read_text(path, limit, what):
    """read_bytes as text. A NUL byte says the file is not text at all;
    other undecodable bytes are replaced (a stray Latin-1 character in a
    program's message is still text)."""
    data = read_bytes(path, limit, what)
    if b"\0" in data:
        raise InputError(f"{what} {path} is not a text file (it holds NUL bytes)")
    return data.decode("utf-8", errors="replace")
