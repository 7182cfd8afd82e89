"use strict";
// The page: loads the run's machines and records, follows a live run through server-sent events,
// and moves through time with the timeline (scrub, step, play at a chosen speed).

const replay = new Replay();
const page = { machines: {}, live: false, ended: false, time: 0, playing: false, last: 0 };
const $ = id => document.getElementById(id);

async function start() {
  const meta = await (await fetch("/api/meta")).json();
  page.machines = meta.machines; page.live = meta.live;
  $("title").textContent = `hfsm monitor: ${meta.title}`;
  const first = await (await fetch("/api/records?from=0")).json();
  replay.add(first.records);
  page.ended = first.ended;
  page.control = meta.control;
  if (meta.video) { $("video").src = meta.video; $("video-box").hidden = false; }
  if (page.live && !page.ended) follow(first.next);
  seek(page.live ? replay.end : 0);  // a live run that waits (for its operator) shows where it stands
  status();
}

function follow(from) {
  const source = new EventSource(`/api/stream?from=${from}`);
  source.onmessage = event => {
    replay.add(JSON.parse(event.data));
    if ($("follow").checked) seek(replay.end); else render();
  };
  source.addEventListener("end", () => { page.ended = true; source.close(); status(); render(); });
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
  drawRoom(replay, $("room"), $("room-note"));
  drawSequence(replay, $("sequence"), page.ended);
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
$("slider").oninput = event => { pause(); $("follow").checked = false; seek(parseFloat(event.target.value)); };

window.hfsm = { replay, seek, page };
start();
