'use strict';
// Node 20 (V8 11.3) can hang at exit, after the program's output is written:
// the main thread waits in NodePlatform::DrainTasks for the background tasks
// to finish, while a background TurboFan job of the JavaScript glue waits for
// a garbage collection that only the main thread can run. Seen in 5 of 150
// 5-second runs of the bouncing ball on Havok (gdb: the main thread in
// DrainTasks, a worker in CollectionBarrier::AwaitCollectionBackground), and
// in none of 150 runs with --no-concurrent-recompilation, which compiles on
// the main thread. V8 takes that flag only on node's command line (set later
// with v8.setFlagsFromString it does not help), so the CMake launchers pass
// it, and an entry file started without it starts itself again with it.

const os = require('os');
const { spawn } = require('child_process');

const FLAG = '--no-concurrent-recompilation';

// True when `entry` (the entry file's __filename) has been started again
// with FLAG in a child whose status becomes this process's; false when this
// process has the flag and should run the program itself.
function restartedWithSafeExit(entry) {
  if (process.execArgv.includes(FLAG)) return false;
  const child = spawn(process.execPath, [FLAG, ...process.execArgv, entry, ...process.argv.slice(2)],
    { stdio: 'inherit' });
  // A signal for this process is the program's: pass it on, and end as it ends.
  for (const signal of ['SIGINT', 'SIGTERM', 'SIGHUP']) process.on(signal, () => child.kill(signal));
  child.on('error', (error) => {
    process.stderr.write(`error: cannot start ${process.execPath} ${FLAG} (${error.message})\n`);
    process.exitCode = 1;
  });
  child.on('exit', (code, signal) => {
    process.exitCode = code !== null ? code : 128 + (os.constants.signals[signal] || 0);
  });
  return true;
}

module.exports = { restartedWithSafeExit, NODE_FLAG: FLAG };
