'use strict';
// The one rule for the files the web peers write and read (checks/file_rules.json,
// the same as the C++ programs' utils/SafeFile and the lab's files.py).
//
// Writing: only a regular file with one link, or nothing, is replaced, in a
// folder that exists. checkWritable() says so from the path alone, before a
// run, so a bad target costs no run and is left exactly as it was.
// writeAtomically() then writes a hidden temporary file beside the target,
// its name with a random part and created exclusively (O_CREAT|O_EXCL: a
// link planted at that name is never followed), checks the target again
// and renames the temporary file over it: a reader sees the old file or the
// whole new one.
//
// Reading: readBounded() reads only a regular file of at most a limit of
// bytes; a FIFO is refused before it is opened (opening one blocks until a
// writer comes), a device (/dev/zero never ends) and an oversized file too.
const crypto = require('crypto');
const fs = require('fs');
const path = require('path');

// A refusal: the path and what is wrong with it, in the phrases all the
// project's writers and readers use.
class FileRefused extends Error {}

const NAME_MAX = 255;  // bytes in one name on Linux file systems
const RANDOM_BYTES = 8;
const CHUNK = 1 << 20;
const TEMPORARY_ATTEMPTS = 8;

function temporaryName(base) {
  return `.${base}.${crypto.randomBytes(RANDOM_BYTES).toString('hex')}.tmp`;
}
// The longest target name whose temporary name still fits in NAME_MAX.
const LONGEST_NAME = NAME_MAX - Buffer.byteLength(temporaryName(''));

// What a non-regular file is, in the phrases of the table; null for a regular file.
function kindOf(info) {
  if (info.isSymbolicLink()) return 'is a symbolic link';
  if (info.isFIFO()) return 'is a FIFO';
  if (info.isCharacterDevice() || info.isBlockDevice()) return 'is a device';
  if (info.isDirectory()) return 'is a folder';
  if (info.isSocket()) return 'is a socket';
  if (!info.isFile()) return 'is not a regular file';
  return null;
}

function lstatOrNull(file) {
  try {
    return fs.lstatSync(file);
  } catch (error) {
    if (error.code === 'ENOENT') return null;
    throw new FileRefused(`${file}: cannot be looked at (${error.code})`);
  }
}

// Throws FileRefused unless `file` may be written by writeAtomically: absent
// or a regular file with one link, in an existing folder this process may
// create files in, with a name short enough for the temporary name beside it.
function checkWritable(file) {
  const folder = path.dirname(file);
  const base = path.basename(file);
  if (base === '' || base === '.' || base === '..' || file.endsWith('/')) throw new FileRefused(`${file}: is a folder`);
  if (Buffer.byteLength(base) > LONGEST_NAME)
    throw new FileRefused(`${file}: name is too long (at most ${LONGEST_NAME} bytes, so that the hidden temporary name beside it fits)`);
  let folderInfo;
  try {
    folderInfo = fs.statSync(folder);
  } catch (error) {
    throw new FileRefused(`${file}: no such folder ${folder}`);
  }
  if (!folderInfo.isDirectory()) throw new FileRefused(`${file}: no such folder ${folder} (it is not a folder)`);
  const info = lstatOrNull(file);
  if (info) {
    const kind = kindOf(info);
    if (kind) throw new FileRefused(`${file}: ${kind}; only a regular file is replaced`);
    if (info.nlink > 1) throw new FileRefused(`${file}: has more than one link; replacing it would part it from the others`);
  }
  try {
    fs.accessSync(folder, fs.constants.W_OK | fs.constants.X_OK);
  } catch (error) {
    throw new FileRefused(`${file}: cannot create files in ${folder} (${error.code})`);
  }
}

// Writes `data` (a string or a Buffer) to `file` whole or not at all.
// Throws FileRefused for a target checkWritable refuses, Error for a failed write.
function writeAtomically(file, data) {
  checkWritable(file);
  let temporary, fd;
  try {
    // A name taken (planted there, or a crypto-random clash) is left alone: another name is drawn.
    for (let attempt = 1; fd === undefined; ++attempt) {
      temporary = path.join(path.dirname(file), temporaryName(path.basename(file)));
      try {
        fd = fs.openSync(temporary, 'wx', 0o644);
      } catch (error) {
        if (error.code !== 'EEXIST' || attempt === TEMPORARY_ATTEMPTS) {
          temporary = undefined;
          throw error;
        }
      }
    }
    const bytes = Buffer.isBuffer(data) ? data : Buffer.from(String(data));
    for (let done = 0; done < bytes.length;) done += fs.writeSync(fd, bytes, done, bytes.length - done);
    fs.fsyncSync(fd);
    fs.closeSync(fd);
    fd = undefined;
    checkWritable(file);  // again: something may have been put there while the run went on
    fs.renameSync(temporary, file);
  } catch (error) {
    if (fd !== undefined) {
      try { fs.closeSync(fd); } catch (_) { /* closed already */ }
    }
    if (temporary !== undefined) {  // made by this call (a name it could not take is not its own)
      try { fs.unlinkSync(temporary); } catch (_) { /* renamed already */ }
    }
    if (error instanceof FileRefused) throw error;
    throw new Error(`cannot write ${file}: ${error.message}`);
  }
}

// The contents of the regular file `file`, at most `limit` bytes (a Buffer).
// Checked before it is opened and again on the open file; the read stops
// at limit + 1 bytes whatever the size said.
function readBounded(file, limit) {
  const check = (info) => {
    const kind = kindOf(info);
    if (kind) throw new FileRefused(`${file}: ${kind}, not a regular file`);
    if (info.size > limit) throw new FileRefused(`${file}: is ${info.size} bytes, larger than the ${limit} bytes it may be`);
  };
  let info;
  try {
    info = fs.statSync(file);
  } catch (error) {
    if (error.code === 'ENOENT' || error.code === 'ENOTDIR') throw new FileRefused(`${file}: does not exist`);
    throw new FileRefused(`${file}: cannot be read (${error.code})`);
  }
  check(info);
  let fd;
  try {
    fd = fs.openSync(file, fs.constants.O_RDONLY | fs.constants.O_NONBLOCK);
  } catch (error) {
    throw new FileRefused(`${file}: cannot be read (${error.code})`);
  }
  try {
    check(fs.fstatSync(fd));
    const chunks = [];
    let total = 0;
    for (;;) {
      const chunk = Buffer.alloc(Math.min(CHUNK, limit + 1 - total));
      const got = fs.readSync(fd, chunk, 0, chunk.length, null);
      if (got === 0) break;
      chunks.push(chunk.subarray(0, got));
      total += got;
      if (total > limit) throw new FileRefused(`${file}: grew larger than the ${limit} bytes it may be while it was read`);
    }
    return Buffer.concat(chunks, total);
  } finally {
    fs.closeSync(fd);
  }
}

module.exports = { FileRefused, checkWritable, writeAtomically, readBounded, LONGEST_NAME };
