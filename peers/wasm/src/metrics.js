'use strict';
// The metrics as utils/Metrics.cpp writes them: ordered "name = value" lines
// and a flat JSON object, whole numbers exact, the rest to 10 significant
// digits as C++'s default stream prints them, non-finite values as null.
const fs = require('fs');
const path = require('path');

function formatNumber(value) {
  if (!Number.isFinite(value)) return 'null';
  if (Number.isInteger(value) && Math.abs(value) < 2 ** 53) return value.toFixed(0);
  // %.10g: scientific below 1e-4 and from 1e10 up; trailing zeros dropped.
  const [mantissa, exponentText] = value.toExponential(9).split('e');
  const exponent = Number(exponentText);
  const trim = (s) => (s.includes('.') ? s.replace(/0+$/, '').replace(/\.$/, '') : s);
  if (exponent < -4 || exponent >= 10) {
    const sign = exponent < 0 ? '-' : '+';
    return `${trim(mantissa)}e${sign}${String(Math.abs(exponent)).padStart(2, '0')}`;
  }
  return trim(value.toFixed(9 - exponent));
}

class Metrics {
  constructor() {
    this.entries = new Map();
  }
  set(name, value) {
    this.entries.set(name, Number(value));
  }
  get(name) {
    return this.entries.has(name) ? this.entries.get(name) : NaN;
  }
  text() {
    return [...this.entries].map(([name, value]) => `${name} = ${formatNumber(value)}\n`).join('');
  }
  json() {
    const lines = [...this.entries].map(([name, value]) => `\n  "${name}": ${formatNumber(value)}`);
    return `{${lines.join(',')}\n}\n`;
  }
  // A unique temporary file beside the target, renamed over it: a reader
  // never sees half a file.
  writeJsonAtomically(file) {
    const temporary = path.join(path.dirname(file), `.${path.basename(file)}.${process.pid}.tmp`);
    try {
      fs.writeFileSync(temporary, this.json());
      fs.renameSync(temporary, file);
    } catch (error) {
      try { fs.unlinkSync(temporary); } catch (_) { /* never written */ }
      throw new Error(`cannot write ${file}: ${error.message}`);
    }
  }
}

module.exports = { Metrics, formatNumber };
