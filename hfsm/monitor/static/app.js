"use strict";
// The page: loads the run's machines and records, follows a live run through server-sent events,
// and moves through time with the timeline (scrub, step, play at a chosen speed).

const replay = new Replay();
const page = { machines: {}, live: false, ended: false, time: 0, playing: false, last: 0 };
const $ = id => document.getElementById(id);

async function start() {
  const meta = await (await fetch("/api/meta")).json();
  page.machines = meta.machines; page.live = meta.live;
  $("title").textContent = clip(`hfsm monitor: ${meta.title}`);
  const first = await (await fetch("/api/records?from=0")).json();
  replay.add(first.records);
  page.ended = first.ended;
  page.control = meta.control;
  showVideo(meta.video);
  if (page.live && !page.ended) follow(first.next);
  seek(page.live ? replay.end : 0);  // a live run that waits (for its operator) shows where it stands
  status();
}

function follow(from) {
  const source = new EventSource(`/api/stream?from=${from}`);
  // Records are taken as they come; the page is drawn at most once a frame, so a fast run makes it
  // skip frames, never fall behind by a backlog of drawings.
  source.onmessage = event => {
    replay.add(JSON.parse(event.data));
    if (page.drawing) return;
    page.drawing = requestAnimationFrame(() => {
      page.drawing = 0;
      if ($("follow").checked) seek(replay.end); else render();
    });
  };
  source.addEventListener("end", () => {
    page.ended = true; source.close(); status(); render();
    if (window.hfsm.endControls) window.hfsm.endControls();
    awaitVideo();
  });
}

function status() {
  const mode = page.live ? (page.ended ? "live run: ended" : "live run") : "replay";
  $("status").textContent = `${mode} · ${replay.records.length} records`;
}

function seek(time) {
  page.time = Math.max(0, Math.min(time, replay.end));
  replay.seek(page.time);
  render();
}

function render() {
  const slider = $("slider");
  slider.max = replay.end; slider.value = page.time;
  $("time").textContent = `${fmt(page.time)} s`;
  drawAgents(replay, page.machines, $("agents"));
  drawRoom(replay, $("room"), $("room-note"), beliefChoice(replay, $("belief")), page.live && !page.ended);
  drawSequence(replay, $("sequence"), page.ended);
  drawMarks(replay, $("marks"));
  refreshFigure();
  videoFollows(page.time);
  status();
}

function tick(now) {
  if (!page.playing) return;
  const speed = parseFloat($("speed").value);
  if (page.last) seek(page.time + (now - page.last) / 1000 * speed);
  page.last = now;
  if (page.time >= replay.end && (page.ended || !page.live)) { pause(); return; }
  requestAnimationFrame(tick);
}

function play() { page.playing = true; page.last = 0; $("play").innerHTML = "&#10073;&#10073;"; requestAnimationFrame(tick); }
function pause() { page.playing = false; $("play").innerHTML = "&#9654;"; }

$("play").onclick = () => (page.playing ? pause() : (page.time >= replay.end && seek(0), play()));
$("step").onclick = () => { pause(); seek(replay.nextTime(page.time)); };
$("back").onclick = () => { pause(); seek(replay.previousTime(page.time)); };
$("belief").onchange = () => render();
$("slider").oninput = event => { pause(); $("follow").checked = false; seek(parseFloat(event.target.value)); };

function search() {
  const hits = findStates($("search").value);
  const box = $("search-hits");
  box.hidden = !$("search").value.trim();
  box.replaceChildren(hits.length ? `${hits.length} found:` : "no state of that name in the figures shown");
  for (const hit of hits.slice(0, 50)) {
    const link = document.createElement("button");
    link.type = "button"; link.className = "hit"; link.textContent = clip(`${hit.agent}: ${hit.key}`);
    link.onclick = () => { mark(hit.node); hit.node.scrollIntoView({ block: "center" }); };
    box.append(" ", link);
  }
  if (hits.length) { mark(hits[0].node); hits[0].node.scrollIntoView({ block: "center" }); }
}
$("search").oninput = search;

function jump(time) { if (time !== null) { pause(); $("follow").checked = false; seek(time); } }
$("next-mark").onclick = () => jump(nextMark(page.time));
$("prev-mark").onclick = () => jump(previousMark(page.time));
$("marks").onclick = event => { if (event.target.dataset.t) jump(parseFloat(event.target.dataset.t)); };

// A click on a state in a figure selects it (for `b`); its path below the top machine.
$("agents").addEventListener("click", event => {
  const g = event.target.closest(".drawing g.node");
  if (!g) return;
  const block = g.closest("details.block");
  const name = g.querySelector("title")?.textContent || "";
  page.selected = [...block.dataset.key.split("/").slice(1), name].join("/");
  for (const old of document.querySelectorAll("g.node.selected")) old.classList.remove("selected");
  g.classList.add("selected");
  $("selected").textContent = clip(`selected: ${page.selected}`);
});

// Keys: space plays or pauses, arrows step a tick with records, b toggles a breakpoint on the
// selected state's entry (a live run's controls only).
document.addEventListener("keydown", event => {
  if (!$("viewer").hidden && (event.key === "Escape" || event.key === "0")) {
    (event.key === "Escape" ? closeFigure : () => $("viewer-fit").click())();
    return;
  }
  if (event.target.closest("input, select, textarea") || event.ctrlKey || event.metaKey || event.altKey) return;
  const act = { " ": () => $("play").click(), ArrowRight: () => $("step").click(), ArrowLeft: () => $("back").click(),
                n: () => $("next-mark").click(), p: () => $("prev-mark").click(),
                b: () => page.selected && window.hfsm.toggleBreak && window.hfsm.toggleBreak(`enter:${page.selected}`) }[event.key];
  if (!act) return;
  event.preventDefault();
  act();
});
// a focused button would take the space as its own click
document.addEventListener("keyup", event => { if (event.key === " " && event.target.closest("button")) event.preventDefault(); });

setUpZoom();
setUpVideo();
window.hfsm = { replay, seek, page };
start();
