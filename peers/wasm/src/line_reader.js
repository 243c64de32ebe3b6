'use strict';
// The server's stdin as lines (doc/engine-protocol.md: one message a line),
// each line at most `maxBytes`. Each chunk is searched once for its line
// ends (a long line is not searched again as it grows, as a string kept and
// searched from its start would be), and a line past the bound ends the
// reading through `tooLong` rather than filling the machine's memory.

function readLines(stream, maxBytes, { line, tooLong, end }) {
  let parts = [];
  let length = 0;
  let stopped = false;
  const emit = () => {
    let text = Buffer.concat(parts, length).toString('utf8');
    if (text.endsWith('\r')) text = text.slice(0, -1);
    parts = [];
    length = 0;
    line(text);
  };
  const add = (piece) => {
    length += piece.length;
    if (length > maxBytes) {
      stopped = true;
      stream.pause();
      tooLong(length);
      return false;
    }
    if (piece.length) parts.push(piece);
    return true;
  };
  stream.on('data', (chunk) => {
    let start = 0;
    while (!stopped) {
      const newline = chunk.indexOf(10, start);
      if (newline < 0) {
        add(chunk.subarray(start));
        return;
      }
      if (!add(chunk.subarray(start, newline))) return;
      emit();
      start = newline + 1;
    }
  });
  stream.on('end', () => {
    if (stopped) return;
    if (length) emit();
    end();
  });
}

module.exports = { readLines };
