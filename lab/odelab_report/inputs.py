"""Files the lab reads but did not write itself (the build's CMakeCache.txt,
what a program left in its run folder, /proc/cpuinfo): each is checked for
type and size on the open file before a byte is read. A FIFO would block
the open or the read for ever, a device or a sparse file never ends, and a
binary file gives nonsense read as text; each is an InputError naming the
file and what is wrong with it."""

import os
import stat

CHUNK = 1 << 20


class InputError(Exception):
    """A file the lab needs is not what it should be."""


def kind(mode):
    """What a file that is not a regular file is, in words."""
    for test, name in ((stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a FIFO"), (stat.S_ISCHR, "a character device"),
                       (stat.S_ISBLK, "a block device"), (stat.S_ISSOCK, "a socket"), (stat.S_ISLNK, "a symbolic link")):
        if test(mode):
            return name
    return "not a regular file"


def check_regular(path, limit, what):
    """Raises InputError unless `path` (not followed if it is a link) is a
    regular file of at most `limit` bytes."""
    try:
        info = os.lstat(path)
    except OSError as error:
        raise InputError(f"cannot read {what} {path}: {error.strerror}") from None
    _check_info(info, path, limit, what)


def _check_info(info, path, limit, what):
    if not stat.S_ISREG(info.st_mode):
        raise InputError(f"{what} {path} is {kind(info.st_mode)}, not a regular file")
    if info.st_size > limit:
        raise InputError(f"{what} {path} is {info.st_size} bytes, more than the {limit} bytes such a file can be")


def read_bytes(path, limit, what):
    """The contents of the regular file `path`, at most `limit` bytes.
    Checked before it is opened (opening some devices acts), and again on
    the open file, in case it was swapped meanwhile; O_NONBLOCK: opening a
    FIFO put there meanwhile does not wait for a writer. The read stops at
    limit + 1 bytes, whatever st_size said (/proc files say 0; a file may
    grow while it is read)."""
    try:
        _check_info(os.stat(path), path, limit, what)
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    except OSError as error:
        raise InputError(f"cannot read {what} {path}: {error.strerror}") from None
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
            raise InputError(f"{what} {path} grew beyond {limit} bytes while it was read")
        return b"".join(chunks)
    except OSError as error:
        raise InputError(f"cannot read {what} {path}: {error.strerror}") from None
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
