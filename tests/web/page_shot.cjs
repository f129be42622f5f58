// Opens a FunctionLab web page in headless Chromium and takes screenshots:
//   node page_shot.cjs URL WIDTHxHEIGHT FIRST.png [SECOND.png [THIRD.png]]
//                      [--timeout SECONDS] [--follow]
// Waits until the page says it is ready (body[data-ready], set by
// viewer/functionlab-page.js), lets two frames pass, saves FIRST.png; with
// SECOND.png, waits a quarter of the shortest cycle among the page's active
// TimeSensors (1 s when none plays; at most 20 s) and saves it too; with
// THIRD.png, waits another 0.15 of that cycle and saves it (a motion that is
// symmetric in time — a bounce — can look the same a quarter cycle apart,
// but not both a quarter and 0.4 of a cycle apart).
// Prints one JSON line: {ready, status, activeCycles, waitedMs, errors}.
// --follow (the class's live page): after FIRST.png prints {ready, version},
// waits for a line on stdin (the test has sent an edit), then for the page's
// body[data-version] to pass that version, and saves SECOND.png; the last
// line adds followMs, the time from the stdin line to the new version.
// Speaks the DevTools protocol over --remote-debugging-pipe (file
// descriptors 3 and 4, messages ended by NUL), so it needs nothing but
// Node 18 and Chromium. The browser draws with SwiftShader: no GPU needed.
"use strict";
const { spawn } = require("child_process");
const fs = require("fs");
const os = require("os");
const path = require("path");

const args = process.argv.slice(2);
let timeoutSeconds = 120;
let follow = false;
const positional = [];
for (let i = 0; i < args.length; ++i) {
  if (args[i] === "--timeout") timeoutSeconds = Number(args[++i]);
  else if (args[i] === "--follow") follow = true;
  else positional.push(args[i]);
}
const [url, size, first, second, third] = positional;
if (!url || !/^\d+x\d+$/.test(size || "") || !first) {
  console.error(
    "usage: node page_shot.cjs URL WIDTHxHEIGHT FIRST.png [SECOND.png [THIRD.png]] [--timeout S]");
  process.exit(2);
}
const [width, height] = size.split("x").map(Number);

const profile = fs.mkdtempSync(path.join(os.tmpdir(), "functionlab-chromium-"));
const browserBinary = process.env.CHROMIUM || "chromium";
const chrome = spawn(browserBinary, [
  "--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
  "--remote-debugging-pipe", "--user-data-dir=" + profile, "--no-first-run",
  "--window-size=" + width + "," + height, "about:blank",
], { stdio: ["ignore", "ignore", "ignore", "pipe", "pipe"] });

const sleep = ms => new Promise(resolve => setTimeout(resolve, ms));
const errors = [];
let nextId = 0;
const pending = new Map();
let buffered = "";
chrome.stdio[4].on("data", chunk => {
  buffered += chunk.toString("utf8");
  let end;
  while ((end = buffered.indexOf("\0")) >= 0) {
    const message = JSON.parse(buffered.slice(0, end));
    buffered = buffered.slice(end + 1);
    if (message.id && pending.has(message.id)) {
      pending.get(message.id)(message);
      pending.delete(message.id);
    } else if (message.method === "Runtime.exceptionThrown") {
      errors.push(message.params.exceptionDetails.exception?.description ||
                  message.params.exceptionDetails.text);
    }
  }
});
function send(method, params = {}, sessionId) {
  return new Promise((resolve, reject) => {
    const id = ++nextId;
    pending.set(id, m => (m.error ? reject(new Error(method + ": " + m.error.message)) : resolve(m.result)));
    chrome.stdio[3].write(JSON.stringify({ id, method, params, sessionId }) + "\0");
  });
}

function finish(code, report) {
  console.log(JSON.stringify(report));
  chrome.kill("SIGKILL");
  try { fs.rmSync(profile, { recursive: true, force: true }); } catch (e) { /* still in use */ }
  process.exit(code);
}

// A page that hangs the renderer never answers an evaluation: the watchdog
// ends the run anyway.
setTimeout(() => finish(1, { ready: "timeout", status: "no answer in " + timeoutSeconds + " s", errors }),
           (timeoutSeconds + 30) * 1000).unref();

(async () => {
  const { targetId } = await send("Target.createTarget", { url: "about:blank" });
  const { sessionId } = await send("Target.attachToTarget", { targetId, flatten: true });
  const page = (method, params) => send(method, params, sessionId);
  const evaluate = async expression =>
    (await page("Runtime.evaluate", { expression, returnByValue: true, awaitPromise: true })).result.value;
  await page("Runtime.enable");
  await page("Page.enable");
  await page("Emulation.setDeviceMetricsOverride",
             { width, height, deviceScaleFactor: 1, mobile: false });
  await page("Page.navigate", { url });
  const deadline = Date.now() + timeoutSeconds * 1000;
  let ready;
  while (Date.now() < deadline) {
    ready = await evaluate("document.body ? document.body.dataset.ready || '' : ''").catch(() => "");
    if (ready) break;
    await sleep(200);
  }
  const status = await evaluate("(document.getElementById('status') || {}).textContent || ''")
    .catch(() => "");
  if (ready !== "yes") finish(1, { ready: ready || "timeout", status, errors });
  const frames = "new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))";
  await evaluate(frames);
  await sleep(300);
  const shoot = async file => {
    const shot = await page("Page.captureScreenshot", { format: "png" });
    fs.writeFileSync(file, Buffer.from(shot.data, "base64"));
  };
  await shoot(first);
  if (follow) {
    const before = Number(await evaluate("document.body.dataset.version"));
    console.log(JSON.stringify({ ready, version: before }));
    await new Promise(resolve => process.stdin.once("data", resolve));
    const started = Date.now();
    let version = before;
    while (version <= before && Date.now() - started < 20000) {
      await sleep(20);
      version = Number(await evaluate("document.body.dataset.version"));
    }
    const followMs = Date.now() - started;
    await evaluate(frames);
    if (second) await shoot(second);
    finish(version > before ? 0 : 1, { ready, version, followMs, errors });
  }
  const activeCycles = await evaluate(
    "FunctionLabTimeSensors().filter(n => n.isActive).map(n => n.cycleInterval)");
  let waitedMs = 0;
  if (second) {
    const shortest = activeCycles.length ? Math.min(...activeCycles) : 4;
    waitedMs = Math.min(20000, shortest * 250);
    await sleep(waitedMs);
    await evaluate(frames);
    await shoot(second);
    if (third) {
      const more = Math.min(12000, shortest * 150);
      await sleep(more);
      await evaluate(frames);
      await shoot(third);
    }
  }
  finish(0, { ready, status, activeCycles, waitedMs, errors });
})().catch(error => finish(1, { ready: "error", status: String(error), errors }));
