// The preview page (scripts/serve.py serves it; docs/live.md, "Browser preview"). It shows the
// frames texrender sends, a control per constant argument of every node, a rewire menu per
// input, and sends each change as one small WebSocket message. window.preview holds what the
// browser test (testsuite/live/Inputs/serve_browser.py) reads.
"use strict";

const preview = { frames: 0, hellos: 0, lastMeta: null, lastPng: null, sent: [], edits: {}, errors: [] };
window.preview = preview;
let socket = null;
let nextId = 1;
let pendingMeta = null;
let frameUrl = null;
const $ = (id) => document.getElementById(id);

function el(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k === "class") e.className = v; else if (k.startsWith("on")) e.addEventListener(k.slice(2), v);
    else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c);
  return e;
}

function connect() {
  socket = new WebSocket(`ws://${location.host}/ws`);
  socket.binaryType = "blob";
  socket.onopen = () => setConnection("connected", true);
  socket.onclose = () => { setConnection("disconnected: reload the page", false); };
  socket.onmessage = (ev) => {
    if (typeof ev.data !== "string") { showFrame(ev.data); return; }
    const msg = JSON.parse(ev.data);
    const handler = { hello: onHello, frame: (m) => { pendingMeta = m; },
                      applied: onApplied, error: onError }[msg.type];
    if (handler) handler(msg);
  };
}

function setConnection(text, ok) {
  $("connection").textContent = text;
  $("connection").className = ok ? "good" : "bad";
}

function send(message, label) {
  message.id = nextId++;
  preview.sent.push(message);
  preview.edits[message.id] = { label, t0: performance.now() };
  socket.send(JSON.stringify(message));
}

function showFrame(blob) {
  const meta = pendingMeta || {};
  pendingMeta = null;
  preview.frames++;
  preview.lastMeta = meta;
  preview.lastPng = blob;
  if (frameUrl) URL.revokeObjectURL(frameUrl);
  frameUrl = URL.createObjectURL(blob);
  $("frame").src = frameUrl;
  $("tier").textContent = meta.tier ?? "-";
  $("spp").textContent = meta.spp ?? "-";
  // A reduced first pass comes at its own size (1/factor of the width and height); the image
  // element scales every frame to the same box.
  $("resolution").textContent = meta.width != null ?
    `${meta.width}x${meta.height}` + (meta.reduced ? ` (1/${meta.factor})` : "") : "-";
  $("builds").textContent = meta.builds ?? "-";
  $("frames").textContent = preview.frames;
  const edit = meta.edit != null ? preview.edits[meta.edit] : null;
  if (edit && meta.latency_ms != null && edit.latency == null) {
    edit.latency = meta.latency_ms;
    edit.seen = performance.now() - edit.t0;
    logEdit(meta.edit, `${edit.label}: first refined frame ${meta.latency_ms.toFixed(1)} ms ` +
            `(texrender), ${edit.seen.toFixed(0)} ms in this page; tier ${meta.tier}`);
  }
}

function logEdit(id, text, refused) {
  const li = el("li", { class: refused ? "refused" : "", "data-id": id }, text);
  $("edits").prepend(li);
  while ($("edits").children.length > 50) $("edits").lastChild.remove();
}

function onApplied(msg) {
  if (msg.id == null) { updateControl(msg); return; }
  const edit = preview.edits[msg.id];
  if (edit) edit.applied = msg;
}

function onError(msg) {
  preview.errors.push(msg);
  if (msg.id != null) {
    const edit = preview.edits[msg.id];
    logEdit(msg.id, `${edit ? edit.label : "edit " + msg.id} refused: ${msg.message}`, true);
    return;
  }
  $("errors").textContent = msg.message;
  $("errors").className = "";
}

function onHello(msg) {
  preview.hellos++;
  $("errors").textContent = msg.error || "none";
  $("errors").className = msg.error ? "" : "empty";
  drawGraph(msg.graph);
  const box = $("controls");
  box.replaceChildren();
  const ids = msg.controls.map((n) => n.node);
  for (const node of msg.controls) {
    const set = el("fieldset", { id: `node-${node.node}` }, el("legend", {}, `${node.node} (${node.fn})`));
    for (const input of node.inputs) set.append(inputRow(node.node, input, ids));
    box.append(set);
  }
}

function inputRow(node, input, ids) {
  const id = `${node}-${input.arg}`;
  const row = el("div", { class: "input" }, el("label", { for: `ctl-${id}` }, `${input.arg}`));
  row.append(el("div", { class: "wide" }, editor(node, input)));
  const fixed = input.type === "sam2D" || input.type.startsWith("__global");
  if (fixed) { row.append(el("span", {}, "")); return row; }
  const menu = el("select", { id: `rewire-${id}`, title: "rewire this input to a node" },
                  el("option", { value: "" }, input.kind === "node" ? `← ${input.source}` : "rewire…"));
  for (const other of ids) if (other !== node) menu.append(el("option", { value: other }, other));
  menu.addEventListener("change", () => {
    if (!menu.value) return;
    send({ type: "rewire", node, arg: input.arg, source: menu.value }, `rewire ${node}.${input.arg}=${menu.value}`);
  });
  row.append(menu);
  return row;
}

function editor(node, input) {
  const id = `ctl-${node}-${input.arg}`;
  const set = (value, text) => send({ type: "set", node, arg: input.arg, value },
                                    `set ${node}.${input.arg}=${text ?? JSON.stringify(value)}`);
  switch (input.kind) {
    case "float": return floatEditor(id, input, set);
    case "int": {
      const box = el("input", { id, type: "number", step: 1, value: input.value });
      if (input.min != null) { box.min = input.min; box.max = input.max; }
      box.addEventListener("change", () => set(parseInt(box.value, 10)));
      return box;
    }
    case "color": {
      const pick = el("input", { id, type: "color", value: toHex(input.value) });
      pick.addEventListener("input", () => set(fromHex(pick.value)));
      return pick;
    }
    case "vector": return vectorEditor(id, input.value, (v) => set(v));
    case "rows": return rowsEditor(id, input.value, (v) => set(v, `[${v.length} rows]`));
    case "node": return el("span", { id }, `← node ${input.source}`);
    case "attr": return el("span", { id }, `← attribute ${input.source}`);
    case "image": return el("span", { id }, `image ${input.source}`);
    default: return el("span", { id }, JSON.stringify(input.value));
  }
}

// A slider over the documented range with a number field beside it for exact values; values
// are rounded to 6 significant digits so that the text sent equals what a user would type.
function floatEditor(id, input, set) {
  const step = niceStep((input.max - input.min) / 200);
  const slider = el("input", { id, type: "range", min: input.min, max: input.max, step, value: input.value });
  const box = el("input", { id: `${id}-value`, type: "number", step: "any", value: input.value });
  const sendValue = (v) => { v = Number(v.toPrecision(6)); box.value = v; slider.value = v; set(v); };
  slider.addEventListener("input", () => sendValue(Number(slider.value)));
  box.addEventListener("change", () => { if (box.value !== "") sendValue(Number(box.value)); });
  return el("span", { class: "wide" }, slider, box);
}

function niceStep(x) {
  const p = Math.pow(10, Math.floor(Math.log10(x)));
  return [1, 2, 5, 10].map((m) => m * p).find((s) => s >= x) || x;
}

function vectorEditor(id, value, set) {
  const boxes = value.map((v, i) => el("input", { id: `${id}-${i}`, type: "number", step: "any", value: v }));
  for (const b of boxes) b.addEventListener("change", () => set(boxes.map((x) => Number(x.value))));
  return el("span", { id, class: "wide" }, ...boxes);
}

// Ramp stops: one line per row (position and values; a colour picker for (t, r, g, b) rows),
// rows can be added and removed; any change sends the whole list.
function rowsEditor(id, rows, set) {
  const table = el("div", { id, class: "rows" });
  const current = () => [...table.querySelectorAll(".row")].map(
    (r) => [...r.querySelectorAll("input[type=number]")].map((x) => Number(x.value)));
  const draw = (data) => {
    table.replaceChildren();
    data.forEach((row, i) => {
      const boxes = row.map((v) => el("input", { type: "number", step: "any", value: v, onchange: () => set(current()) }));
      const line = el("div", { class: "row wide" }, ...boxes);
      if (row.length === 4) {
        const pick = el("input", { type: "color", value: toHex(row.slice(1)) });
        pick.addEventListener("input", () => {
          fromHex(pick.value).forEach((c, k) => { boxes[k + 1].value = c; });
          set(current());
        });
        line.append(pick);
      }
      line.append(el("button", { type: "button", title: "remove this stop", onclick: () => {
        const d = current(); d.splice(i, 1); if (d.length) { draw(d); set(d); } } }, "−"));
      table.append(line);
    });
    table.append(el("button", { type: "button", onclick: () => {
      const d = current(); d.push([...d[d.length - 1]]); draw(d); set(d); } }, "add stop"));
  };
  draw(rows);
  return table;
}

// Colours in the graph are linear; the picker shows sRGB.
function toHex(rgb) {
  const enc = (c) => Math.round(255 * (c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055));
  return "#" + rgb.map((c) => Math.min(255, Math.max(0, enc(c))).toString(16).padStart(2, "0")).join("");
}

function fromHex(hex) {
  const dec = (s) => s <= 0.04045 ? s / 12.92 : Math.pow((s + 0.055) / 1.055, 2.4);
  return [1, 3, 5].map((i) => Number(dec(parseInt(hex.substr(i, 2), 16) / 255).toPrecision(4)));
}

function updateControl(msg) {
  const box = $(`ctl-${msg.node}-${msg.arg}`);
  if (box && typeof msg.value === "number") {
    box.value = msg.value;
    const exact = $(`ctl-${msg.node}-${msg.arg}-value`);
    if (exact) exact.value = msg.value;
  }
}

// The graph as columns by depth (sources left), links as curves, material outputs outlined.
function drawGraph(graph) {
  const svg = $("graph");
  const ns = "http://www.w3.org/2000/svg";
  svg.replaceChildren();
  const depth = {};
  const byId = Object.fromEntries(graph.nodes.map((n) => [n.id, n]));
  const d = (id, seen = new Set()) => {
    if (depth[id] != null) return depth[id];
    if (seen.has(id) || !byId[id]) return 0;
    seen.add(id);
    return (depth[id] = Math.max(0, ...Object.values(byId[id].links).map((s) => d(s, seen) + 1)));
  };
  graph.nodes.forEach((n) => d(n.id));
  const outputs = new Set(Object.values(graph.materials).flat());
  const rows = {};
  const pos = {};
  for (const n of graph.nodes) {
    const c = depth[n.id];
    rows[c] = (rows[c] || 0) + 1;
    pos[n.id] = { x: 10 + c * 130, y: 10 + (rows[c] - 1) * 34 };
  }
  svg.setAttribute("viewBox", `0 0 ${Math.max(400, 140 + 130 * Math.max(0, ...Object.values(depth)))} ` +
                   `${Math.max(100, 20 + 34 * Math.max(1, ...Object.values(rows)))}`);
  const add = (tag, attrs, text) => {
    const e = document.createElementNS(ns, tag);
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
    if (text) e.textContent = text;
    svg.append(e);
  };
  for (const n of graph.nodes) {
    for (const [arg, src] of Object.entries(n.links)) {
      if (!pos[src]) continue;
      const a = pos[src], b = pos[n.id];
      add("path", { d: `M${a.x + 110},${a.y + 12} C${a.x + 125},${a.y + 12} ${b.x - 15},${b.y + 12} ${b.x},${b.y + 12}` });
    }
  }
  for (const n of graph.nodes) {
    const p = pos[n.id];
    add("rect", { x: p.x, y: p.y, width: 110, height: 24, rx: 4, class: outputs.has(n.id) ? "output" : "" });
    add("text", { x: p.x + 6, y: p.y + 16 }, `${n.id}`);
  }
}

connect();
