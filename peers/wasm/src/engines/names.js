'use strict';
// The engines of peers/wasm, each an adapter src/engines/<name>.js, in
// --list-engines' order (peers/engines/WasmEngines.cpp lists the same on
// the C++ side, with what each one's "best" changes).
module.exports = ['havok', 'jolt', 'rapier', 'physx'];
