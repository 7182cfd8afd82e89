"use strict";
// The operator's controls of a live run: each button posts one decision to /api/control with the
// run's token (from the page's address); the run takes it at the start of its next tick and writes
// it to the trace as an `operator` record. Every text shown is set as text, never as markup.

const operator = { token: new URLSearchParams(location.search).get("token") || "" };

async function ask(body) {
  const answer = await fetch("/api/control", {
    method: "POST",
    headers: { "Content-Type": "application/json", "X-HFSM-Token": operator.token },
    body: JSON.stringify(body),
  });
  const said = await answer.json();
  $("op-said").textContent = answer.ok ? `sent: ${body.do}` : `refused: ${said.error}`;
  if (answer.ok) showBreaks(said.breaks);
  return answer.ok;
}

function showBreaks(breaks) { operator.breaks = breaks; $("op-breaks").textContent = breaks.length ? `breakpoints: ${breaks.join(", ")}` : ""; }

function heldNow() {
  // the held records whose state has not been left (nor answered) since
  const open = new Map();
  for (const r of replay.records) {
    if (r.agent == null) continue;
    const key = `${r.agent} ${r.path.join("/")}`;
    if (r.kind === "held") open.set(key, r);
    else if (r.kind === "exit") for (const k of [...open.keys()]) if (k === key || k.startsWith(key + "/")) open.delete(k);
  }
  return [...open.values()];
}

function showHeld() {
  const held = heldNow();
  $("op-held").textContent = held.map(r => `${r.agent}: ${r.path.slice(1).join("/")} holds '${r.event}' (needs ${r.level})`).join("; ");
}

function setUp() {
  if (!page.control || !operator.token) return;
  $("operator").hidden = false;
  for (const name of page.control.agents) {
    const option = document.createElement("option");
    option.textContent = name;
    $("op-agent").appendChild(option);
  }
  showBreaks(page.control.breaks);
  const agent = () => $("op-agent").value;
  const event = () => $("op-event").value.trim() || undefined;
  $("op-pause").onclick = () => ask({ do: "pause" });
  $("op-resume").onclick = () => ask({ do: "resume" });
  $("op-step").onclick = () => ask({ do: "step" });
  $("op-autonomy").onclick = () => ask({ do: "autonomy", level: $("op-level").value });
  $("op-accept").onclick = () => ask({ do: "accept", agent: agent(), event: event() });
  $("op-force").onclick = () => ask({ do: "force", agent: agent(), event: event() });
  $("op-send").onclick = () => {
    let data = {};
    try { data = JSON.parse($("op-data").value || "{}"); } catch (e) { $("op-said").textContent = "data: not JSON"; return; }
    ask({ do: "message", agent: agent(), message: $("op-message").value.trim(), data });
  };
  $("op-add-break").onclick = () => ask({ do: "break", spec: $("op-break").value.trim() });
  $("op-clear-breaks").onclick = () => ask({ do: "break", spec: "clear" });
  setInterval(showHeld, 250);
}

// Add the breakpoint, or remove it when set (the server only clears all: the others are set again).
async function toggleBreak(spec) {
  const breaks = operator.breaks || [];
  if (!breaks.includes(spec)) return ask({ do: "break", spec });
  if (!(await ask({ do: "break", spec: "clear" }))) return false;
  for (const other of breaks.filter(b => b !== spec)) await ask({ do: "break", spec: other });
  return true;
}

const waitForMeta = setInterval(() => { if (page.control !== undefined) { clearInterval(waitForMeta); setUp(); } }, 50);
window.hfsm.ask = ask;
window.hfsm.toggleBreak = spec => (operator.token && page.control ? toggleBreak(spec) : Promise.resolve(false));
