// The site served from 127.0.0.1 and a headless Chromium to open it, for
// the drivers of the browser build's checks (drive.mjs, check-pages.mjs).
import { createServer } from "node:http";
import { existsSync, readFileSync, statSync, mkdtempSync, rmSync } from "node:fs";
import { join, extname } from "node:path";
import { tmpdir } from "node:os";
import puppeteer from "puppeteer-core";

// The types the browser insists on (an icon of the wrong type is not shown).
const TYPES = {
  ".html": "text/html", ".js": "text/javascript", ".css": "text/css", ".json": "application/json",
  ".wasm": "application/wasm", ".svg": "image/svg+xml", ".png": "image/png", ".ico": "image/x-icon",
};

// Serves the folder SITE; resolves to { port, close }.
export async function serveSite(site) {
  const server = createServer((request, response) => {
    const path = join(site, decodeURIComponent(new URL(request.url, "http://x").pathname));
    if (!path.startsWith(site) || !existsSync(path) || !statSync(path).isFile()) {
      response.writeHead(404).end();
      return;
    }
    response.writeHead(200, { "Content-Type": TYPES[extname(path)] || "application/octet-stream" });
    response.end(readFileSync(path));
  });
  await new Promise((done) => server.listen(0, "127.0.0.1", done));
  return { port: server.address().port, close: () => server.close() };
}

// A fresh profile each time; software WebGL2 through ANGLE's SwiftShader;
// nothing that reaches out to the network. Resolves to { browser, close }.
export async function launchChromium() {
  const profile = mkdtempSync(join(tmpdir(), "odelab-chromium-"));
  const browser = await puppeteer.launch({
    executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
    headless: true,
    args: [
      "--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
      "--disable-background-networking", "--disable-component-update", "--disable-sync",
      "--no-first-run", "--disable-quic", `--user-data-dir=${profile}`,
    ],
  });
  return {
    browser,
    close: async () => {
      await browser.close();
      rmSync(profile, { recursive: true, force: true });
    },
  };
}

// Records on PAGE every request the site refused or that failed, and the
// console's errors, into the arrays of the object it returns.
export function watchProblems(page) {
  const problems = { missing: [], consoleErrors: [] };
  page.on("response", (response) => {
    if (response.status() >= 400) problems.missing.push(`${response.status()} ${response.url()}`);
  });
  page.on("requestfailed", (request) => {
    // A download link's blob: address is handed to the download, not loaded.
    if (!request.url().startsWith("blob:")) problems.missing.push(`failed ${request.url()} (${request.failure()?.errorText})`);
  });
  page.on("console", (message) => {
    if (message.type() === "error") problems.consoleErrors.push(message.text());
  });
  return problems;
}
