"use strict";
// Marks on the timeline for what one looks for in a run: messages, errors, timeouts, failures,
// holds and the operator's actions; a click on one, the buttons or n/p jump to it.

const marks = { list: [], seen: 0 };

function markOf(r) {
  const who = r.agent == null ? "run" : r.agent;
  if (r.kind === "send") return ["message", `${who} sends ${r.message}`];
  if (r.kind === "failed") return ["failure", `${who} failed: ${r.reason || ""}`];
  if (r.kind === "held") return ["hold", `${who} holds '${r.event}' at ${(r.path || []).join("/")}`];
  if (r.kind === "operator") return ["operator", `operator: ${r.do}${r.break ? ` (${r.break})` : ""}`];
  if (r.kind === "event" && r.event === "error") return ["error", `${who}: error at ${(r.path || []).join("/")}`];
  if (r.kind === "event" && r.event === "timeout") return ["timeout", `${who}: timeout at ${(r.path || []).join("/")}`];
  return null;
}

// Take the records added since the last call; redraw every mark (their places change as the run grows).
function drawMarks(replay, box) {
  for (; marks.seen < replay.records.length; marks.seen += 1) {
    const r = replay.records[marks.seen];
    const found = markOf(r);
    if (found) marks.list.push({ t: r.t, kind: found[0], text: found[1] });
  }
  const end = replay.end || 1;
  if (box.dataset.count === String(marks.list.length) && box.dataset.end === String(end)) return;
  box.dataset.count = String(marks.list.length); box.dataset.end = String(end);
  box.replaceChildren(...marks.list.map(m => {
    const node = document.createElement("span");
    node.className = `mark ${m.kind}`;
    node.style.left = `${(100 * m.t) / end}%`;
    node.dataset.t = String(m.t);
    node.title = `${fmt(m.t)} s: ${m.text}`;
    return node;
  }));
}

function nextMark(time) { const m = marks.list.find(x => x.t > time + 1e-9); return m ? m.t : null; }
function previousMark(time) {
  let best = null;
  for (const m of marks.list) { if (m.t < time - 1e-9) best = m.t; else break; }
  return best;
}
