// The web engines inside the page: Havok, Jolt, Rapier and PhysX from their npm
// WebAssembly builds (peers/wasm's packages, bundled into the site by
// bundle.mjs), each spoken to in doc/engine-protocol.md by the scene's
// C++ adapter (peers/engines/BrowserEngine.cpp) through
// globalThis.odelabEngines. The same adapters and the same message handling
// as the desktop's Node.js server (peers/wasm/src/).
import { Session } from "../../peers/wasm/src/session.js";
import havokWasmAddress from "@babylonjs/havok/lib/umd/HavokPhysics.wasm";
import physxWasmAddress from "physx-js-webidl/physx-js-webidl.wasm";

// Each engine's adapter in a chunk of its own, loaded only when asked for.
const ADAPTERS = {
  havok: () => import("../../peers/wasm/src/engines/havok.js"),
  jolt: () => import("../../peers/wasm/src/engines/jolt.js"),
  rapier: () => import("../../peers/wasm/src/engines/rapier.js"),
  physx: () => import("../../peers/wasm/src/engines/physx.js"),
};
// The .wasm files of the engines whose packages do not inline theirs,
// bundled beside the chunks (esbuild's file loader gives their addresses).
const WASM_ADDRESSES = { havok: havokWasmAddress, physx: physxWasmAddress };
// The packages' versions, written in by bundle.mjs from their package.json.
const VERSIONS = ODELAB_ENGINE_VERSIONS;

const loaded = {};    // name -> { adapter, module } or { error }
const sessions = new Map();
let lastSession = 0;

async function fetchBytes(address) {
  const response = await fetch(new URL(address, import.meta.url));
  if (!response.ok) throw new Error(`${address}: HTTP ${response.status}`);
  return new Uint8Array(await response.arrayBuffer());
}

// Loads the engines named (each once); one that cannot load is kept with
// its reason, which info() gives the scene.
async function load(names) {
  for (const name of names) {
    if (!ADAPTERS[name] || loaded[name]) continue;
    try {
      const adapter = (await ADAPTERS[name]()).default;
      const wasmBinary = adapter.wasmFile ? await fetchBytes(WASM_ADDRESSES[name]) : undefined;
      loaded[name] = { adapter, module: await adapter.load({ wasmBinary }) };
    } catch (error) {
      loaded[name] = { error: `cannot load ${name}: ${error.message}` };
    }
  }
}

// {"version", "missing"} as JSON: "missing" is empty when the page has it.
function info(name) {
  const entry = loaded[name];
  let missing = "";
  if (!ADAPTERS[name]) missing = "not one of " + Object.keys(ADAPTERS).join(", ");
  else if (!entry) missing = `this page did not load it (name it in the address: compare=${name} or engine=${name})`;
  else if (entry.error) missing = entry.error;
  return JSON.stringify({ version: VERSIONS[name] || "", missing });
}

// A new engine session: its number.
function open(name, setting) {
  const entry = loaded[name];
  if (!entry || !entry.module) throw new Error(JSON.parse(info(name)).missing || `${name} is not loaded`);
  sessions.set(++lastSession, new Session(entry.adapter.make(entry.module, setting),
    () => entry.adapter.make(entry.module, setting)));
  return lastSession;
}

// One message of a session; its reply, or "" for a message that takes none.
function request(number, line) {
  const session = sessions.get(number);
  if (!session) throw new Error(`no engine session ${number}`);
  const reply = session.line(line);
  if (session.quit) sessions.delete(number);
  return reply === null ? "" : reply;
}

globalThis.odelabEngines = { names: Object.keys(ADAPTERS), load, info, open, request };
