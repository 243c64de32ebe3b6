// Runs one scene of the browser build in headless Chromium and keeps what
// it gave: the program's output (log.txt), its end status (result.json),
// the files it wrote (files/), a picture of the canvas (canvas.png) with
// how much of it is not background (in result.json), and, when asked, one
// of its files fetched through the page's download link (downloads/), and
// the requests the site refused and the console's errors (in result.json).
//
//   node web/drive.mjs --site DIR --scene testN --out DIR [--timeout S]
//                      [--download NAME] [--clock-step MS] -- [program arguments...]
//
// --clock-step MS gives the page a coarse clock: performance.now() rounded
// down to a multiple of MS, as browsers that blur their timers do, so that
// frames in the same step read the same time.
//
// Exits 0 when the run ended (whatever its status: the caller judges), 1
// when it did not end in time or the browser failed, 2 for bad usage.
import { mkdirSync, readFileSync, writeFileSync, existsSync, rmSync } from "node:fs";
import { join, resolve } from "node:path";
import { serveSite, launchChromium, watchProblems } from "./site.mjs";

function usage(message) {
  console.error(`error: ${message}\nusage: node drive.mjs --site DIR --scene testN --out DIR [--timeout S] [--download NAME] [--clock-step MS] -- [arguments...]`);
  process.exit(2);
}

const options = { timeout: 120, download: "", "clock-step": "0" };
const programArgs = [];
{
  const argv = process.argv.slice(2);
  for (let i = 0; i < argv.length; ++i) {
    if (argv[i] === "--") {
      programArgs.push(...argv.slice(i + 1));
      break;
    }
    const name = argv[i].replace(/^--/, "");
    if (!["site", "scene", "out", "timeout", "download", "clock-step"].includes(name) || i + 1 >= argv.length) usage(`bad argument '${argv[i]}'`);
    options[name] = argv[++i];
  }
}
if (!options.site || !options.scene || !options.out) usage("--site, --scene and --out are needed");
const timeoutSeconds = Number(options.timeout);
if (!(timeoutSeconds > 0)) usage(`--timeout must be a positive number of seconds, not '${options.timeout}'`);
const clockStep = Number(options["clock-step"]);
if (!(clockStep >= 0)) usage(`--clock-step must be a number of milliseconds, not '${options["clock-step"]}'`);
const site = resolve(options.site);
// The site's list of scenes (scenes.json, from tests/scenes/scenes.txt).
let listed = [];
try {
  listed = JSON.parse(readFileSync(join(site, "scenes.json"), "utf8")).map((scene) => scene.name);
} catch (error) {
  usage(`${site} has no readable scenes.json (build it with scripts/odelab.sh web): ${error.message}`);
}
if (!listed.includes(options.scene)) usage(`no such scene '${options.scene}'; the site's scenes are ${listed.join(" ")}`);
if (!existsSync(join(site, options.scene + ".js"))) usage(`${site} holds no ${options.scene}.js (build it with scripts/odelab.sh web)`);
const out = resolve(options.out);
rmSync(out, { recursive: true, force: true });
mkdirSync(join(out, "files"), { recursive: true });

const server = await serveSite(site);
const port = server.port;
const chromium = await launchChromium();
const browser = chromium.browser;

let exitCode = 0;
const result = { scene: options.scene, arguments: programArgs };
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1400, height: 1000 });
  const problems = watchProblems(page);
  if (clockStep > 0) {
    await page.evaluateOnNewDocument((step) => {
      const now = performance.now.bind(performance);
      performance.now = () => Math.floor(now() / step) * step;
    }, clockStep);
  }
  const query = new URLSearchParams({ scene: options.scene });
  // "--name value" and "--flag" become address parameters, as a user types them.
  for (let i = 0; i < programArgs.length; ++i) {
    const name = programArgs[i].replace(/^--/, "");
    const value = i + 1 < programArgs.length && !programArgs[i + 1].startsWith("--") ? programArgs[++i] : "";
    query.append(name, value);
  }
  const started = Date.now();
  await page.goto(`http://127.0.0.1:${port}/scene.html?${query}`);
  try {
    await page.waitForFunction(() => window.odelabRun && window.odelabRun.ended, { timeout: timeoutSeconds * 1000, polling: 250 });
  } catch (error) {
    result.error = `the run did not end within ${timeoutSeconds} s`;
    exitCode = 1;
  }
  result.seconds = (Date.now() - started) / 1000;
  const run = await page.evaluate(() => ({ status: window.odelabRun.status, log: window.odelabRun.log }));
  result.status = run.status;
  writeFileSync(join(out, "log.txt"), run.log.join("\n") + "\n");

  // The files the run wrote, straight from the module's file system.
  const files = await page.evaluate(() => window.odelabRun.files ? window.odelabRun.files() : {});
  for (const [name, bytes] of Object.entries(files)) writeFileSync(join(out, "files", name), Buffer.from(bytes));
  result.files = Object.keys(files);
  result.missing = problems.missing;
  result.console_errors = problems.consoleErrors;

  // The canvas as the page shows it, and the share of its pixels that
  // differ from its commonest colour (the sky).
  const box = await page.evaluate(() => {
    const r = document.getElementById("canvas").getBoundingClientRect();
    return { x: r.left + window.scrollX, y: r.top + window.scrollY, width: r.width, height: r.height };
  });
  const png = await page.screenshot({ type: "png", clip: box });
  writeFileSync(join(out, "canvas.png"), png);
  result.picture = await page.evaluate(async (data) => {
    const image = new Image();
    image.src = "data:image/png;base64," + data;
    await image.decode();
    const board = document.createElement("canvas");
    board.width = image.width;
    board.height = image.height;
    const context = board.getContext("2d");
    context.drawImage(image, 0, 0);
    const pixels = context.getImageData(0, 0, board.width, board.height).data;
    const counts = new Map();
    for (let i = 0; i < pixels.length; i += 4) {
      const key = (pixels[i] << 16) | (pixels[i + 1] << 8) | pixels[i + 2];
      counts.set(key, (counts.get(key) || 0) + 1);
    }
    const total = pixels.length / 4;
    const commonest = Math.max(...counts.values());
    return { width: board.width, height: board.height, colours: counts.size, other_than_commonest: 1 - commonest / total };
  }, Buffer.from(png).toString("base64"));

  // One file through the page's own download link, as a user gets it.
  if (options.download) {
    const downloads = join(out, "downloads");
    mkdirSync(downloads, { recursive: true });
    const session = await browser.target().createCDPSession();
    await session.send("Browser.setDownloadBehavior", { behavior: "allow", downloadPath: downloads, eventsEnabled: true });
    const finished = new Promise((done) => session.on("Browser.downloadProgress", (event) => {
      if (event.state === "completed" || event.state === "canceled") done(event.state);
    }));
    const clicked = await page.evaluate((name) => {
      const link = Array.from(document.querySelectorAll("#files a")).find((a) => a.textContent === name);
      if (!link) return false;
      link.click();
      return true;
    }, options.download);
    result.download = clicked ? await Promise.race([finished, new Promise((done) => setTimeout(() => done("timed out"), 30000))])
                              : "no link named " + options.download;
  }
} catch (error) {
  result.error = String(error);
  exitCode = 1;
} finally {
  await chromium.close();
  server.close();
}
writeFileSync(join(out, "result.json"), JSON.stringify(result, null, 1) + "\n");
console.log(JSON.stringify(result));
process.exit(exitCode);
