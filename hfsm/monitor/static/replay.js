"use strict";
// The state of a run at a time, rebuilt from its trace records (hfsm-run --trace): per agent the
// active states at every depth, timers, attempts, vars and mailbox; the messages; the room's poses.

class Replay {
  constructor() { this.records = []; this.names = []; this.known = new Set(); this.posed = false; this.reset(); }

  reset() {
    this.applied = 0;
    this.agents = new Map();   // name -> {active: Map(key -> entry), mailbox: [], result, failed}
    this.sentNames = new Set(); // the names of the messages sent so far
    this.poses = null;         // the latest pose record
    this.lastKind = null;
  }

  // Records as they come; the agents' names and whether any pose came are kept as they do (a long
  // live run is never scanned whole again for them).
  add(records) {
    for (const r of records) {
      this.records.push(r);
      if (r.kind === "pose") this.posed = true;
      else if (r.agent && !this.known.has(r.agent)) { this.known.add(r.agent); this.names.push(r.agent); }
    }
  }

  get end() { return this.records.length ? this.records[this.records.length - 1].t : 0; }

  // Apply every record with t <= time (rewinding when time is earlier than what is applied).
  seek(time) {
    if (this.applied > 0 && this.records[this.applied - 1].t > time) this.reset();
    while (this.applied < this.records.length && this.records[this.applied].t <= time + 1e-9) {
      this.apply(this.records[this.applied]);
      this.applied += 1;
    }
    this.time = time;
  }

  // The times at which something happened, for stepping.
  nextTime(time) {
    for (const r of this.records) if (r.t > time + 1e-9) return r.t;
    return time;
  }
  previousTime(time) {
    let best = 0;
    for (const r of this.records) { if (r.t < time - 1e-9) best = r.t; else break; }
    return best;
  }

  agent(name) {
    if (!this.agents.has(name)) this.agents.set(name, { active: new Map(), mailbox: [], result: null, failed: null, final: null });
    return this.agents.get(name);
  }

  apply(r) {
    if (r.kind === "pose") { this.poses = r; return; }
    if (r.agent == null) return;  // the run's own records: its flags, a resume, the operator's pause
    const a = this.agent(r.agent);
    // the states active just before a cascade of exits, kept so an ended agent still shows its figures
    if ((r.kind === "exit" || r.kind === "failed") && a.lastKind !== "exit" && a.active.size) a.before = new Map(a.active);
    a.lastKind = r.kind;
    const key = r.path.join("/");
    switch (r.kind) {
      case "enter": {
        const previous = a.active.get(key);
        a.active.set(key, { path: r.path, key, t: r.t, do: r.do || (r.path.length === 1 ? r.path[0] : ""),
                            deadline: r.deadline, attempt: 1, vars: previous ? previous.vars : null,
                            machineDeadline: previous ? previous.machineDeadline : undefined });
        if (r.path.length === 1) { a.result = null; a.failed = null; a.final = null; }
        this.frameFacts(a, r);
        break;
      }
      case "exit":
        for (const k of [...a.active.keys()]) if (k === key || k.startsWith(key + "/")) a.active.delete(k);
        if (r.path.length === 1) { a.result = r.outcome === undefined ? null : r.outcome; a.final = a.before || null; }
        break;
      case "event": {
        const entry = a.active.get(key);
        if (r.event === "retry" && entry) entry.attempt = r.attempt || entry.attempt + 1;
        if (r.arrived !== undefined) a.lastBarrier = { path: key, arrived: r.arrived, t: r.t };
        this.frameFacts(a, r);
        const i = a.mailbox.findIndex(m => m.message === r.event);
        if (i >= 0 && r.message_arc !== false && this.isMessage(r.event)) a.mailbox.splice(i, 1);
        break;
      }
      case "send":
        this.sentNames.add(r.message);
        break;
      case "receive": {
        // keep: last - in place of the sender's copy not yet taken; `id`: its send record's number
        const old = r.replaced ? a.mailbox.findIndex(m => m.message === r.message && m.sender === r.sender) : -1;
        if (old >= 0) a.mailbox.splice(old, 1);
        a.mailbox.push({ message: r.message, sender: r.sender, t: r.t, id: r.id });
        break;
      }
      case "failed":
        a.failed = r.reason || "failed";
        if (a.active.size) a.final = a.before || new Map(a.active);
        a.active.clear();
        break;
      default:
        break;
    }
  }

  // A record of a machine's state may tell the machine's vars that changed and its timer: both
  // belong to the entry that runs the machine, one level up.
  frameFacts(a, r) {
    if (r.vars === undefined && r.machine_deadline === undefined) return;
    const frame = a.active.get(r.path.slice(0, -1).join("/"));
    if (!frame) return;
    if (r.vars !== undefined) frame.vars = frame.vars ? { ...frame.vars, ...r.vars } : r.vars;  // those changed
    if (r.machine_deadline !== undefined) frame.machineDeadline = r.machine_deadline;
  }

  isMessage(name) { return this.sentNames.has(name); }

  // Every message of the whole trace with when each addressee got it (null: never), whatever the
  // time shown: so a message still in flight is told apart from one the radio lost.
  // Kept up as records come: a receive is matched to its send by the send's `id`, or (a trace
  // without ids) to the oldest send of that message from that sender still awaited by that agent.
  fates() {
    if (!this._fates) { this._fates = []; this._fatesOf = 0; this._awaited = new Map(); this._byId = new Map(); }
    const names = this.agentNames();
    for (; this._fatesOf < this.records.length; this._fatesOf += 1) {
      const r = this.records[this._fatesOf];
      if (r.kind === "send") {
        const to = r.to === "others" ? names.filter(n => n !== r.agent) : r.to === "all" ? names : [r.to];
        const m = { t: r.t, from: r.agent, message: r.message, got: Object.fromEntries(to.map(n => [n, null])) };
        this._fates.push(m);
        if (r.id !== undefined) { this._byId.set(r.id, m); continue; }
        for (const n of to) {
          const key = JSON.stringify([r.agent, r.message, n]);
          if (!this._awaited.has(key)) this._awaited.set(key, []);
          this._awaited.get(key).push(m);
        }
      } else if (r.kind === "receive" && r.id !== undefined) {
        const m = this._byId.get(r.id);
        if (m && r.agent in m.got) m.got[r.agent] = r.t;
      } else if (r.kind === "receive") {
        const waiting = this._awaited.get(JSON.stringify([r.sender, r.message, r.agent]));
        if (waiting && waiting.length) waiting.shift().got[r.agent] = r.t;
      }
    }
    return this._fates;
  }

  // The states to draw: the active ones, or once the agent has ended those active at its end.
  shown(agentName) {
    const a = this.agent(agentName);
    return a.active.size || !a.final ? a.active : a.final;
  }

  hasPoses() { return this.posed; }

  // The deepest active path of an agent (the first entered at each depth), for the breadcrumb.
  activePath(agentName) {
    let path = [];
    for (const e of this.shown(agentName).values()) if (e.path.length > path.length) path = e.path;
    return path;
  }

  // Shown entries whose path is `path` plus one name, in the order they were entered.
  children(agentName, path) {
    const depth = path.length;
    const prefix = path.join("/") + "/";
    return [...this.shown(agentName).values()].filter(e => e.path.length === depth + 1 && e.key.startsWith(prefix));
  }

  agentNames() { return this.names; }
}

if (typeof module !== "undefined") module.exports = { Replay };
