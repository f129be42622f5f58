#pragma once
// The live page's own files (classroom/live_page.h): its HTML and script.
// The script shows the newest baked version the server has (`scene.json`),
// asks again when `/events` says a newer one is ready, and lists the chat
// as text (textContent: a classmate's markup is shown, never obeyed). It
// sets body[data-ready] and body[data-version] for the browser test.

namespace fl::classroom {

inline constexpr const char* kLivePageHtml = R"html(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>FunctionLab class, live</title>
<link rel="stylesheet" href="viewer/page.css">
<script src="viewer/x_ite.min.js"></script>
<script src="live.js"></script>
</head>
<body>
<header>
<h1>FunctionLab class, live</h1>
<p>The class's shared scene as it is now: it changes as the class edits it. Drag to turn it,
scroll to come closer. This page only watches: to model with the class, join it in FunctionLab.</p>
<p id="status" role="status">Connecting…</p>
</header>
<x3d-canvas id="scene" contextMenu="false" splashScreen="false"></x3d-canvas>
<footer><h2>Chat</h2><ul id="chat"></ul>
Made with FunctionLab; drawn by <a href="viewer/LICENSE.md">X_ITE</a>.</footer>
</body>
</html>
)html";

inline constexpr const char* kLivePageScript = R"js("use strict";
(function () {
  const params = new URLSearchParams(location.search);
  const code = params.get("class");
  const suffix = code === null ? "" : "?class=" + encodeURIComponent(code);
  let shown = -1, wanted = 0, loading = false;

  function say(text) {
    document.getElementById("status").textContent = text;
  }

  function startTime(clock) {
    switch (clock.base) {
      case "utc": return clock.start;
      case "local": return clock.start + new Date().getTimezoneOffset() * 60;
      default: return Date.now() / 1000 + clock.start;
    }
  }

  async function show() {
    if (loading || wanted <= shown) return;
    loading = true;
    try {
      const response = await fetch("scene.json" + suffix, { cache: "no-store" });
      if (!response.ok) throw new Error(response.status + " " + (await response.text()));
      const page = await response.json();
      if (page.version > shown) {
        const dom = new DOMParser().parseFromString(page.x3d, "application/xml");
        const sensors = Array.from(dom.getElementsByTagName("TimeSensor"));
        for (const clock of page.clocks) {
          const sensor = sensors.find(s => s.getAttribute("DEF") === clock.timeSensor);
          if (sensor) sensor.setAttribute("startTime", String(startTime(clock)));
        }
        const browser = X3D.getBrowser(document.getElementById("scene"));
        await browser.replaceWorld(await browser.importDocument(dom));
        shown = page.version;
        document.body.dataset.version = String(shown);
        document.body.dataset.ready = "yes";
        say("Version " + shown + " of the class's scene.");
      }
    } catch (error) {
      say("The scene could not be shown: " + error.message);
    }
    loading = false;
    if (wanted > shown) setTimeout(show, 250);
  }

  function addChat(line) {
    const list = document.getElementById("chat");
    const item = document.createElement("li");
    const who = document.createElement("b");
    who.textContent = String(line.from);
    item.append(who, document.createTextNode(": " + String(line.text)));
    list.append(item);
    while (list.children.length > 50) list.firstElementChild.remove();
  }

  window.addEventListener("load", () => {
    if (params.has("shot")) {
      // A picture for the tests: the canvas alone, without X_ITE's notices.
      document.body.classList.add("shot");
      const root = document.getElementById("scene").shadowRoot;
      const style = document.createElement("style");
      style.textContent =
        ".x_ite-private-buttons, .x_ite-private-notification { display: none !important; }";
      if (root) root.appendChild(style);
    }
    const events = new EventSource("events" + suffix);
    events.addEventListener("version", event => {
      wanted = Math.max(wanted, Number(event.data));
      show();
    });
    events.addEventListener("chat", event => addChat(JSON.parse(event.data)));
    events.addEventListener("notice", event => say(event.data));
    events.onerror = () => say("Waiting for the class server…");
  });
})();
)js";

inline constexpr const char* kLivePageChatStyle = R"css(footer h2 {
  font-size: 1rem;
  margin: 0.4rem 0 0.2rem;
}
#chat {
  max-height: 8rem;
  overflow-y: auto;
  margin: 0 0 0.4rem;
  padding-left: 1.2rem;
  white-space: pre-wrap;
}
)css";

} // namespace fl::classroom
