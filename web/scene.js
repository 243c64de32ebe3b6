// Runs one scene: scene.html?scene=test2&erp=0.4&pause gives the program
// the arguments --erp 0.4 --pause; compare=havok,jolt runs it on those
// engines beside ODE's, each in a view of the one canvas. The run's folder
// (/run in the module's memory file system) is listed under the picture,
// each file a download.
// window.odelabRun tells a driver (checks/web.cmake's) how the run stands.
"use strict";

const params = new URLSearchParams(location.search);
const sceneName = params.get("scene") || "";
const statusLine = document.getElementById("status");
const logBox = document.getElementById("log");
const fileList = document.getElementById("files");
const RUN_DIR = "/run";
const USAGE_STATUS = 2; // utils/ExitCodes.h
window.odelabRun = { ended: false, status: null, log: [] };

function say(text) {
  window.odelabRun.log.push(text);
  logBox.textContent += text + "\n";
}

// Every address parameter but "scene" is an option: a value gives
// "--name value", none gives the flag "--name".
function argumentsFromAddress() {
  const args = [];
  for (const [name, value] of params) {
    if (name === "scene") continue;
    args.push("--" + name);
    if (value !== "") args.push(value);
  }
  return args;
}

// The regular files in the run's folder.
function runFiles(module) {
  return module.FS.readdir(RUN_DIR).filter(
    (name) => name !== "." && name !== ".." && module.FS.isFile(module.FS.stat(RUN_DIR + "/" + name).mode));
}

// A file's bytes. Once a headless run has returned, the runtime has exited
// and FS.readFile refuses; the file is still in memory, read from its node.
function readRunFile(module, name) {
  const path = RUN_DIR + "/" + name;
  try {
    return module.FS.readFile(path);
  } catch (error) {
    const node = module.FS.lookupPath(path).node;
    return Uint8Array.from(node.contents.subarray(0, node.usedBytes));
  }
}

function listFiles(module) {
  let names;
  try {
    names = runFiles(module);
  } catch (error) {
    return;
  }
  const shown = Array.from(fileList.querySelectorAll("a")).map((a) => a.textContent).join("\n");
  if (names.length === 0 || shown === names.join("\n")) return;
  fileList.textContent = "";
  for (const name of names) {
    const item = document.createElement("li");
    const link = document.createElement("a");
    link.href = "#";
    link.textContent = name;
    // The file as it is when clicked: a running scene's file grows.
    link.addEventListener("click", (event) => {
      event.preventDefault();
      const bytes = readRunFile(module, name);
      const save = document.createElement("a");
      save.href = URL.createObjectURL(new Blob([bytes], { type: "application/octet-stream" }));
      save.download = name;
      document.body.appendChild(save);
      save.click();
      save.remove();
      setTimeout(() => URL.revokeObjectURL(save.href), 10000);
    });
    item.appendChild(link);
    fileList.appendChild(item);
  }
}

function ended(module, status) {
  window.odelabRun.ended = true;
  window.odelabRun.status = status;
  statusLine.textContent = "ended, status " + status;
  // Status 2 is a refused option (the program's message, under Output,
  // names it): the scene's own list of options is one click away.
  if (status === USAGE_STATUS) {
    const help = document.createElement("a");
    help.href = "scene.html?scene=" + encodeURIComponent(sceneName) + "&help";
    help.textContent = "the options of " + sceneName;
    statusLine.append(" (a refused option; see ", help, ")");
  }
  listFiles(module);
}

function start(factory) {
  const args = argumentsFromAddress();
  document.title = sceneName + " " + args.join(" ");
  statusLine.textContent = "running " + sceneName + " " + args.join(" ");
  const canvas = document.getElementById("canvas");
  // The canvas's size on the page is the window's (--width, --height; the
  // programs' defaults otherwise), fixed, so that SDL keeps the window that
  // size when the page is resized rather than following the page's layout.
  canvas.style.width = (params.get("width") || canvas.width) + "px";
  canvas.style.height = (params.get("height") || canvas.height) + "px";
  let module = null;
  factory({
    arguments: args,
    canvas: canvas,
    print: say,
    printErr: say,
    preRun: [
      (m) => {
        module = m;
        m.ENV.ODELAB_SHADER_DIR = "/odelab/shaders";
        m.FS.mkdir(RUN_DIR);
        m.FS.chdir(RUN_DIR);
      },
    ],
    // A window run ends here (utils/web/WebMainLoop.cpp) ...
    onRunEnd: (status) => ended(module, status),
    // ... a headless run or a refused one when main returns.
    onExit: (status) => ended(module, status),
    onAbort: (what) => {
      say("aborted: " + what);
      ended(module, "aborted");
    },
  }).then((m) => {
    // For a driver: every file of the run's folder, as byte arrays.
    window.odelabRun.files = () => {
      const files = {};
      for (const name of runFiles(m)) files[name] = Array.from(readRunFile(m, name));
      return files;
    };
    canvas.focus();
    setInterval(() => listFiles(m), 1000);
  });
}

// The engines other than ODE that the address names (compare=havok,jolt
// or engine=rapier; list-engines: all), loaded into the page before the
// scene starts (engines/, bundled from web/engines/). One that does not
// load is the scene's to report: --list-engines and --engine say why.
function enginesNamed() {
  if (params.has("list-engines")) return "all";
  const names = (params.get("compare") || "").split(",").concat([params.get("engine") || ""]);
  return names.map((name) => name.trim()).filter((name) => name !== "" && name !== "ode");
}

async function loadEngines(names) {
  if (names.length === 0) return;
  statusLine.textContent = "loading " + (names === "all" ? "the engines" : names.join(", "));
  try {
    await import("./engines/index.js");
    const engines = globalThis.odelabEngines;
    await engines.load(names === "all" ? engines.names : names);
  } catch (error) {
    say("this site's engines did not load (" + error.message + ")");
  }
}

// A scene of the site's list (scenes.json, from tests/scenes/scenes.txt), or a message.
fetch("scenes.json")
  .then((response) => response.json())
  .then((scenes) => {
    if (!scenes.some((scene) => scene.name === sceneName)) {
      statusLine.textContent = "no such scene: '" + sceneName + "' (see the list of scenes)";
      return;
    }
    const script = document.createElement("script");
    script.src = sceneName + ".js";
    script.onload = () => loadEngines(enginesNamed()).then(() => start(window["create_" + sceneName]));
    script.onerror = () => (statusLine.textContent = "no scene '" + sceneName + "' in this site (" + script.src + " did not load)");
    document.body.appendChild(script);
  })
  .catch(() => (statusLine.textContent = "this site's list of scenes (scenes.json) did not load"));
