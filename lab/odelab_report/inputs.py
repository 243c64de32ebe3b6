"""The lab's bounded reader, under the name its callers import: the reader
and the writer of the one file rule live together in files.py."""

from .files import CHUNK, InputError, check_regular, kind, read_bytes, read_text  # noqa: F401
