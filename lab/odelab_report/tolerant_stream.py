"""Standard error that may go away without failing the report."""


class TolerantStream:
    """Standard error that may go away (a closed pipe, a terminal that is
    gone): what the lab says there is advice, and losing it must not fail
    or falsify the report. Writes that fail are dropped, silently."""

    def __init__(self, stream):
        self._stream = stream

    def write(self, text):
        try:
            return self._stream.write(text)
        except (OSError, ValueError):
            return len(text)

    def flush(self):
        try:
            self._stream.flush()
        except (OSError, ValueError):
            pass

    def isatty(self):
        try:
            return self._stream.isatty()
        except (OSError, ValueError):
            return False

    def __getattr__(self, name):
        return getattr(self._stream, name)
