"use strict";
// Drawing a Replay into the page: a column per agent with its active path at every depth (the
// machine's drawing with its active states lit, regions side by side, each depth foldable), the
// room from above, and the messages as a sequence diagram.

const SVGNS = "http://www.w3.org/2000/svg";
const MAILBOX_SHOWN = 20;           // the newest messages of a mailbox shown
const folded = new Set();          // keys of blocks the user folded; kept across redraws

function el(tag, attrs = {}, text = "") {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  if (text) node.textContent = clip(text);
  return node;
}

function fmt(seconds) { return (Math.round(seconds * 100) / 100).toFixed(2); }

// A value for people: numbers rounded to 3 decimals (at most 3 significant below 1), at any depth.
function human(value) {
  return JSON.stringify(value, (_, v) => (typeof v === "number" && isFinite(v) && !Number.isInteger(v)
    ? Number(Math.abs(v) >= 1 ? v.toFixed(3) : v.toPrecision(3)) : v));
}

function drawAgents(replay, machines, container) {
  const names = replay.agentNames();
  for (const column of [...container.children]) if (!names.includes(column.dataset.agent)) column.remove();
  for (const name of names) {
    let column = container.querySelector(`.agent[data-agent="${CSS.escape(name)}"]`);
    if (!column) {
      column = el("div", { class: "agent", "data-agent": name });
      column.append(el("h2", {}, name), el("nav", { class: "crumbs" }), el("div", { class: "result" }),
                    el("div", { class: "tree" }),
                    el("div", { class: "mailbox" }));
      container.append(column);
    }
    drawAgent(replay, machines, name, column);
  }
}

function drawAgent(replay, machines, name, column) {
  const a = replay.agent(name);
  column.classList.toggle("failed", !!a.failed);
  const result = a.failed ? `failed: ${a.failed}` : a.result !== null ? `ended in '${a.result}'` : "";
  column.querySelector(".result").textContent = clip(result);
  const tree = column.querySelector(".tree");
  const shown = replay.shown(name);
  column.classList.toggle("ended", shown !== a.active);
  drawCrumbs(replay.activePath(name), column);
  const roots = [...shown.values()].filter(e => e.path.length === 1);
  reconcile(tree, roots.map(e => e.key), key => block(replay, machines, name, shown.get(key)),
            (node, key) => updateBlock(replay, machines, name, shown.get(key), node));
  const box = column.querySelector(".mailbox");
  const waiting = a.mailbox.slice(-MAILBOX_SHOWN).map(m => `${m.message} from ${m.sender}`).join(", ");
  const more = a.mailbox.length > MAILBOX_SHOWN ? `${a.mailbox.length - MAILBOX_SHOWN} more, then ` : "";
  box.textContent = clip(a.mailbox.length ? `mailbox: ${more}${waiting}` : "mailbox: empty");
  if (a.lastBarrier) {
    const b = a.lastBarrier;
    box.append(el("div", { class: "barrier-passed" },
                  `last barrier passed at ${fmt(b.t)} s (${b.path.split("/").pop()}), with ${b.arrived.join(", ") || "nobody"}`));
  }
}

// The agent's active path, top/.../deepest; a click scrolls the deepest state's figure into view.
function drawCrumbs(path, column) {
  const crumbs = column.querySelector(".crumbs");
  const key = path.join("/");
  if (crumbs.dataset.path === key) return;
  crumbs.dataset.path = key;
  crumbs.replaceChildren(...path.flatMap((name, i) => {
    const link = el("button", { class: "crumb", type: "button", "data-path": path.slice(0, i + 1).join("/") }, name);
    link.onclick = () => revealState(column, key);
    return i ? [el("span", { class: "sep" }, "/"), link] : [link];
  }));
}

// Scroll to the figure that shows the state at `key` (its lit node in the parent's drawing).
function revealState(column, key) {
  const parts = key.split("/");
  const parent = column.querySelector(`details.block[data-key="${CSS.escape(parts.slice(0, -1).join("/"))}"]`);
  const own = column.querySelector(`details.block[data-key="${CSS.escape(key)}"]`);
  const target = (parent && [...parent.querySelectorAll(":scope > .drawing g.node")]
    .find(g => g.querySelector("title")?.textContent === parts[parts.length - 1])) || own;
  if (!target) return null;
  for (let d = target.closest("details"); d; d = d.parentElement.closest("details")) d.open = true;
  mark(target);
  target.scrollIntoView({ block: "center" });
  return target;
}

function mark(node) {
  for (const old of document.querySelectorAll(".found")) old.classList.remove("found");
  node.classList.add("found");
}

// Every state named like `query` in the figures shown: [{agent, key, name, node}].
function findStates(query) {
  const q = query.trim().toLowerCase();
  if (!q) return [];
  const hits = [];
  for (const drawing of document.querySelectorAll("#agents .drawing")) {
    const block = drawing.closest("details.block");
    const agent = drawing.closest(".agent").dataset.agent;
    for (const g of drawing.querySelectorAll("g.node")) {
      const name = g.querySelector("title")?.textContent || "";
      if (name.toLowerCase().includes(q)) hits.push({ agent, key: `${block.dataset.key}/${name}`, name, node: g });
    }
  }
  return hits;
}

// Keep the children of `parent` in step with `keys`: new ones made, old ones removed, kept ones updated.
function reconcile(parent, keys, make, update) {
  const have = new Map([...parent.children].map(c => [c.dataset.key, c]));
  for (const [key, node] of have) if (!keys.includes(key)) node.remove();
  let previous = null;
  for (const key of keys) {
    let node = have.get(key);
    if (!node) node = make(key);
    update(node, key);
    if (previous ? previous.nextSibling !== node : parent.firstChild !== node) {
      if (previous) previous.after(node); else parent.prepend(node);
    }
    previous = node;
  }
}

function block(replay, machines, agentName, entry) {
  const node = el("details", { class: "block", "data-key": entry.key, "data-depth": entry.path.length });
  node.open = !folded.has(agentName + ":" + entry.key);
  node.addEventListener("toggle", () => {
    const id = agentName + ":" + entry.key;
    if (node.open) folded.delete(id); else folded.add(id);
  });
  const svg = figureOf(machines, entry.do);
  node.append(el("summary"), el("div", { class: "facts" }));
  if (svg) {
    const drawing = el("div", { class: "drawing", "data-machine": entry.do });
    drawing.append(svg);
    drawing.prepend(el("button", { class: "enlarge", type: "button", title: "open full size (zoom, pan)" }, "\u2922"));
    node.append(drawing);
  }
  node.append(el("table", { class: "vars" }), el("div", { class: "children" }));
  return node;
}

// A machine's figure, made safe once (safesvg.js) and copied for each block that shows it.
const figures = new Map();
function figureOf(machines, name) {
  if (!machines[name]) return null;
  if (!figures.has(name)) figures.set(name, safeSvg(machines[name]));
  const svg = figures.get(name);
  return svg ? svg.cloneNode(true) : null;
}

function updateBlock(replay, machines, agentName, entry, node) {
  const name = entry.path[entry.path.length - 1];
  const callee = entry.do && entry.do !== name ? ` (${entry.do})` : "";
  node.querySelector(":scope > summary").textContent = clip(name + callee);
  node.querySelector(":scope > summary").setAttribute("data-path", entry.key);
  const facts = [`state.time ${fmt(replay.time - entry.t)} s`];
  if (entry.attempt > 1) facts.push(`attempt ${entry.attempt}`);
  const facts_ = node.querySelector(":scope > .facts");
  facts_.textContent = facts.join(" · ");
  if (entry.deadline !== undefined && entry.deadline !== null) {
    const timer = el("span", { class: "timer" }, ` · timer ${fmt(Math.max(0, entry.deadline - replay.time))} s left`);
    facts_.append(timer);
  }
  if (entry.machineDeadline !== undefined) {
    const left = fmt(Math.max(0, entry.machineDeadline - replay.time));
    facts_.append(el("span", { class: "timer machine" }, ` · ${entry.do}'s timer ${left} s left`));
  }
  if (entry.do === "barrier") facts_.append(el("span", { class: "barrier" }, " · waiting at a barrier"));
  const kids = replay.children(agentName, entry.path);
  const drawing = node.querySelector(":scope > .drawing");
  if (drawing) light(drawing, kids.map(k => k.path[k.path.length - 1]));
  drawVars(node.querySelector(":scope > table.vars"), entry.vars);
  reconcile(node.querySelector(":scope > .children"), kids.map(k => k.key),
            key => block(replay, machines, agentName, replay.shown(agentName).get(key)),
            (child, key) => updateBlock(replay, machines, agentName, replay.shown(agentName).get(key), child));
}

function light(drawing, names) {
  for (const g of drawing.querySelectorAll("g.node")) {
    const title = g.querySelector("title");
    g.classList.toggle("active", !!title && names.includes(title.textContent));
  }
}

function drawVars(table, vars) {
  table.replaceChildren();
  if (!vars) return;
  for (const [k, v] of Object.entries(vars)) {
    const row = el("tr");
    row.append(el("td", {}, k), el("td", {}, human(v)));
    table.append(row);
  }
}

// The robots the room view draws the beliefs of: the one chosen, or every robot ("").
function beliefChoice(replay, select) {
  const names = replay.agentNames();
  const have = [...select.options].map(o => o.value);
  for (const name of names) if (!have.includes(name)) select.append(el("option", { value: name }, name));
  return select.value ? [select.value] : names;
}

// What a machine asks the room view to draw of its agent's belief: its top machine's var `drawn`,
// {rects: [[x, y, yaw, length, width, label]], points: [[x, y, label]]} in the room's frame.
function drawnBy(replay, name) {
  const root = [...replay.agent(name).active.values()].find(e => e.path.length === 1);
  return (root && root.vars && root.vars.drawn) || {};
}

// A robot's own start frame (where it was told it started) to the room's.
function fromStart(start, x, y) {
  const a = start[2] * Math.PI / 180;
  return [start[0] + Math.cos(a) * x - Math.sin(a) * y, start[1] + Math.sin(a) * x + Math.cos(a) * y];
}

function drawBeliefs(replay, ctx, px, scale, names) {
  const shown = new Set();
  ctx.font = "10px sans-serif";
  for (const name of names) {
    const drawn = drawnBy(replay, name);
    for (const [x, y, yaw, length, width, label] of drawn.rects || []) {
      const key = JSON.stringify([x, y, yaw, length, width]);
      if (shown.has(key)) continue;
      shown.add(key);
      ctx.save(); ctx.translate(...px(x, y)); ctx.rotate(-yaw);
      ctx.fillStyle = "rgba(255, 220, 80, 0.18)"; ctx.strokeStyle = "#ffd84a"; ctx.setLineDash([4, 3]);
      ctx.fillRect(-length / 2 * scale, -width / 2 * scale, length * scale, width * scale);
      ctx.strokeRect(-length / 2 * scale, -width / 2 * scale, length * scale, width * scale);
      ctx.restore(); ctx.setLineDash([]);
      ctx.fillStyle = "#ffe9a0"; ctx.fillText(label || "", ...px(x, y));
    }
    if (names.length === 1) {
      for (const [x, y, label] of drawn.points || []) {
        const [cx, cy] = px(x, y);
        ctx.strokeStyle = "#7df"; ctx.beginPath(); ctx.arc(cx, cy, 5, 0, 2 * Math.PI); ctx.stroke();
        ctx.fillStyle = "#bef"; ctx.fillText(label, cx + 6, cy + 10);
      }
    }
    const sensed = ((replay.poses || {}).sensed || {})[name];
    if (!sensed) continue;
    for (const [input, reading] of Object.entries(sensed)) {
      if (input === "start" || !Array.isArray(reading.value)) continue;
      for (const thing of reading.value) {
        if (typeof thing !== "object" || thing === null || thing.x === undefined) continue;
        const [x, y] = fromStart(sensed.start, thing.x, thing.y);
        const yaw = ((thing.heading || 0) + sensed.start[2]) * Math.PI / 180;
        const length = thing.length || 0.1, width = thing.width || 0.1;
        ctx.save(); ctx.translate(...px(x, y)); ctx.rotate(-yaw);
        ctx.strokeStyle = "#f6f"; ctx.lineWidth = 1.5;
        ctx.strokeRect(-length / 2 * scale, -width / 2 * scale, length * scale, width * scale);
        ctx.restore(); ctx.lineWidth = 1;
      }
    }
  }
}

function drawRoom(replay, canvas, note, beliefs = [], live = false) {
  const ctx = canvas.getContext("2d");
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  const pose = replay.poses;
  if (!pose) {
    note.textContent = replay.hasPoses() ? "The room: no pose recorded yet at this time."
      : live ? "The room: no pose received yet." : "No poses in this trace (a run without the simulator).";
    return;
  }
  note.textContent = "";
  const [w, d] = pose.room;
  const scale = (canvas.width - 20) / Math.max(w, d);
  const px = (x, y) => [canvas.width / 2 + x * scale, canvas.height / 2 - y * scale];
  ctx.fillStyle = "#6a5038"; ctx.fillRect(...px(-w / 2, d / 2), w * scale, d * scale);
  for (const table of pose.tables || []) {
    const [x, y, yaw, length, width, lift] = table;
    ctx.save(); ctx.translate(...px(x, y)); ctx.rotate(-yaw);
    ctx.fillStyle = lift > 0.02 ? "#5b7cff" : "#2a4cd0";
    ctx.fillRect(-length / 2 * scale, -width / 2 * scale, length * scale, width * scale); ctx.restore();
  }
  drawBeliefs(replay, ctx, px, scale, beliefs);
  ctx.font = "11px sans-serif";
  for (const [id, x, y] of pose.targets || []) {
    const [cx, cy] = px(x, y);
    ctx.strokeStyle = "#d22"; ctx.lineWidth = 2; ctx.beginPath();
    ctx.moveTo(cx - 6, cy - 6); ctx.lineTo(cx + 6, cy + 6); ctx.moveTo(cx - 6, cy + 6); ctx.lineTo(cx + 6, cy - 6);
    ctx.stroke(); ctx.lineWidth = 1; ctx.fillStyle = "#fdd"; ctx.fillText(clip(id).slice(0, 40), cx + 8, cy + 12);
  }
  for (const [name, [x, y, yaw]] of Object.entries(pose.robots || {})) {
    const [cx, cy] = px(x, y);
    const failed = replay.agent(name).failed;
    ctx.fillStyle = failed ? "#999" : "#f4a340"; ctx.beginPath(); ctx.arc(cx, cy, 6, 0, 2 * Math.PI); ctx.fill();
    ctx.strokeStyle = "#fff"; ctx.beginPath(); ctx.moveTo(cx, cy);
    ctx.lineTo(cx + 10 * Math.cos(yaw), cy - 10 * Math.sin(yaw)); ctx.stroke();
    ctx.fillStyle = "#fff"; ctx.fillText(clip(name).slice(0, 40), cx + 8, cy - 8);
  }
}

// Messages up to the time shown, newest last: an arrow from sender to each addressee, solid once
// received, dotted while in flight, red and crossed when the world lost it.
function drawSequence(replay, box, ended) {
  const names = replay.agentNames();
  const shown = replay.fates().filter(m => m.t <= replay.time + 1e-9).slice(-25);
  const width = 320, lane = width / Math.max(1, names.length), row = 20;
  const svg = document.createElementNS(SVGNS, "svg");
  svg.setAttribute("viewBox", `0 0 ${width} ${30 + row * shown.length}`);
  const x = name => lane * (names.indexOf(name) + 0.5);
  names.forEach(name => {
    svg.append(svgEl("text", { x: x(name), y: 12, "text-anchor": "middle", "font-size": 11 }, name));
    svg.append(svgEl("line", { x1: x(name), y1: 16, x2: x(name), y2: 30 + row * shown.length, stroke: "#bbb" }));
  });
  shown.forEach((m, i) => {
    const y = 32 + row * i;
    for (const [to, got] of Object.entries(m.got)) {
      const state = got !== null && got <= replay.time + 1e-9 ? "received" : got !== null || !ended ? "in-flight" : "lost";
      const colour = state === "lost" ? "#c33" : state === "received" ? "#357" : "#999";
      const line = svgEl("line", { x1: x(m.from), y1: y, x2: x(to), y2: y + 8, stroke: colour,
                                   "stroke-dasharray": state === "received" ? "" : "3 3", class: `msg ${state}` });
      svg.append(line);
      svg.append(svgEl("text", { x: x(to) + (x(to) > x(m.from) ? -10 : 4), y: y + 10, "font-size": 10, fill: colour },
                       state === "lost" ? "\u2715" : state === "received" ? "\u25B8" : ""));
    }
    svg.append(svgEl("text", { x: Math.min(x(m.from), width - 90) + 3, y: y - 3, "font-size": 9 }, `${fmt(m.t)} ${m.message}`));
  });
  box.replaceChildren(svg);
}

function svgEl(tag, attrs, text = "") {
  const node = document.createElementNS(SVGNS, tag);
  for (const [k, v] of Object.entries(attrs)) if (v !== "") node.setAttribute(k, v);
  if (text) node.textContent = clip(text);
  return node;
}
