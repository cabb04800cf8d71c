// The preview page (scripts/serve.py serves it; docs/live.md, "Browser preview"). It shows the
// frames texrender sends and, from the edit schema texrender sends (node, function, each
// input's type, current value or link, default, range and doc), a control per constant input
// and a rewire menu per input; each change goes out as one small WebSocket message, and
// texrender says whether it applies. The page derives no type and checks no value itself.
// window.preview holds what the browser tests (testsuite/live/Inputs/serve_browser.py) read.
"use strict";

const preview = { frames: 0, hellos: 0, lastMeta: null, lastPng: null, sent: [], edits: {},
                  errors: [], applied: [], pageErrors: [] };
window.preview = preview;
let socket = null;
let nextId = 1;
let pendingMeta = null;
let frameUrl = null;
let fileError = null; // the last failed file change texrender reported (until a reload)
const controls = new Map(); // "node\u0000arg" -> { update(value) } of the control shown
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

// A failure of this page's own code is shown in the errors panel, never hidden behind "none".
function pageError(text) {
  preview.pageErrors.push(String(text));
  showErrors();
}
window.addEventListener("error", (ev) => pageError(`page error: ${ev.message}`));
window.addEventListener("unhandledrejection", (ev) => pageError(`page error: ${ev.reason}`));

function showErrors() {
  const lines = [...preview.pageErrors];
  if (fileError) lines.push(fileError);
  $("errors").textContent = lines.length ? lines.join("\n") : "none";
  $("errors").className = lines.length ? "" : "empty";
}

function connect() {
  const token = new URLSearchParams(location.search).get("token");
  socket = new WebSocket(`ws://${location.host}/ws` + (token ? `?token=${encodeURIComponent(token)}` : ""));
  socket.binaryType = "blob";
  socket.onopen = () => setConnection("connected", true);
  socket.onclose = () => { setConnection("disconnected: reload the page", false); };
  socket.onmessage = (ev) => {
    try {
      if (typeof ev.data !== "string") { showFrame(ev.data); return; }
      const msg = JSON.parse(ev.data);
      const handler = { hello: onHello, frame: (m) => { pendingMeta = m; },
                        applied: onApplied, error: onError }[msg.type];
      if (handler) handler(msg);
    } catch (e) {
      pageError(`page error: ${e && e.stack ? e.stack.split("\n")[0] : e}`);
    }
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
  preview.applied.push(msg);
  const control = controls.get(`${msg.node}\u0000${msg.arg}`);
  if (msg.id == null && control && "value" in msg) control.update(msg.value);
  const edit = preview.edits[msg.id];
  if (msg.id != null && edit) edit.applied = msg;
}

function onError(msg) {
  preview.errors.push(msg);
  if (msg.id != null) {
    const edit = preview.edits[msg.id];
    logEdit(msg.id, `${edit ? edit.label : "edit " + msg.id} refused: ${msg.message}`, true);
    return;
  }
  fileError = msg.message;
  showErrors();
}

function onHello(msg) {
  preview.hellos++;
  fileError = msg.error || null;
  showErrors();
  const schema = msg.schema;
  if (!schema || !Array.isArray(schema.nodes)) throw new Error("the server sent no edit schema");
  preview.schema = schema;
  drawGraph(schema);
  const box = $("controls");
  box.replaceChildren();
  controls.clear();
  const ids = schema.nodes.map((n) => n.id);
  for (const node of schema.nodes) {
    const title = `${node.id} (${node.fn})`;
    const set = el("fieldset", { id: `node-${node.id}` }, el("legend", { title: node.file || "" }, title));
    for (const input of node.inputs) set.append(inputRow(node.id, input, ids));
    box.append(set);
  }
}

// Arrays (ramp stops) and images are data of the graph, not wiring: no rewire menu for them.
const isArray = (type) => type.startsWith("__global");
const vectorWidth = (type) => ({ float2: 2, float3: 3, float4: 4 })[type] || 0;

function inputRow(node, input, ids) {
  const id = `${node}-${input.name}`;
  const label = el("label", { for: `ctl-${id}` }, input.name);
  if (input.doc) label.title = input.doc + (input.range ? ` (range ${input.range})` : "");
  const row = el("div", { class: "input" }, label);
  row.append(el("div", { class: "wide" }, editor(node, input)));
  if (input.type === "sam2D" || isArray(input.type)) { row.append(el("span", {}, "")); return row; }
  const menu = el("select", { id: `rewire-${id}`, title: "rewire this input to a node" },
                  el("option", { value: "" }, "node" in input ? `← ${input.node}` : "rewire…"));
  for (const other of ids) if (other !== node) menu.append(el("option", { value: other }, other));
  menu.addEventListener("change", () => {
    if (!menu.value) return;
    send({ type: "rewire", node, arg: input.name, source: menu.value }, `rewire ${node}.${input.name}=${menu.value}`);
  });
  row.append(menu);
  return row;
}

// The editor of one input, by the type texrender gave; its update(value) shows an edit made by
// another page.
function editor(node, input) {
  const id = `ctl-${node}-${input.name}`;
  const set = (value, text) => send({ type: "set", node, arg: input.name, value },
                                    `set ${node}.${input.name}=${text ?? JSON.stringify(value)}`);
  const remember = (e, update) => { controls.set(`${node}\u0000${input.name}`, { update }); return e; };
  if ("node" in input) return el("span", { id }, `← node ${input.node}`);
  if ("attr" in input) return el("span", { id }, `← attribute ${input.attr}`);
  if ("image" in input) return el("span", { id }, `image ${input.image}`);
  const value = input.value;
  if (input.type === "float" && typeof value === "number") {
    const e = floatEditor(id, input, set);
    return remember(e, (v) => { e.querySelectorAll("input").forEach((x) => { x.value = v; }); });
  }
  if (input.type === "int" && typeof value === "number") {
    const box = el("input", { id, type: "number", step: 1, value });
    if (input.min != null) box.min = input.min;
    if (input.max != null) box.max = input.max;
    box.addEventListener("change", () => { if (box.value !== "") set(Number(box.value)); });
    return remember(box, (v) => { box.value = v; });
  }
  const width = vectorWidth(input.type);
  if (width && Array.isArray(value) && value.length === width) {
    // A colour picker beside the numbers where the documented range is 0..1 (an RGB value).
    const colour = width === 3 && input.min === 0 && input.max === 1;
    const e = vectorEditor(id, value, colour, (v) => set(v));
    return remember(e, (v) => e.show(v));
  }
  if (isArray(input.type) && Array.isArray(value)) {
    return rowsEditor(id, value, (v) => set(v, `[${v.length} rows]`));
  }
  return el("span", { id, class: "fixed" }, JSON.stringify(value));
}

// A slider over the documented range (or one around the value where the table gives none) with
// a number field beside it for exact values; values are rounded to 6 significant digits so that
// the text sent equals what a user would type.
function floatEditor(id, input, set) {
  const [min, max] = sliderRange(input.min, input.max, input.value);
  const step = niceStep((max - min) / 200);
  const slider = el("input", { id, type: "range", min, max, step, value: input.value });
  const box = el("input", { id: `${id}-value`, type: "number", step: "any", value: input.value });
  const sendValue = (v) => { v = Number(v.toPrecision(6)); box.value = v; slider.value = v; set(v); };
  slider.addEventListener("input", () => sendValue(Number(slider.value)));
  box.addEventListener("change", () => { if (box.value !== "") sendValue(Number(box.value)); });
  return el("span", { class: "wide" }, slider, box);
}

function sliderRange(lo, hi, v) {
  if (lo == null) lo = v >= 0 ? 0 : 2 * v;
  if (hi == null) hi = Math.max(lo + 1, 2 * Math.abs(v), 1);
  return [Math.min(lo, v), Math.max(hi, v)];
}

function niceStep(x) {
  if (!(x > 0)) return "any";
  const p = Math.pow(10, Math.floor(Math.log10(x)));
  return [1, 2, 5, 10].map((m) => m * p).find((s) => s >= x) || x;
}

function vectorEditor(id, value, colour, set) {
  const boxes = value.map((v, i) => el("input", { id: `${id}-${i}`, type: "number", step: "any", value: v }));
  const span = el("span", { id, class: "wide" }, ...boxes);
  let pick = null;
  if (colour) {
    pick = el("input", { id: `${id}-colour`, type: "color", value: toHex(value) });
    pick.addEventListener("input", () => {
      const v = fromHex(pick.value);
      boxes.forEach((b, i) => { b.value = v[i]; });
      set(v);
    });
    span.append(pick);
  }
  for (const b of boxes) b.addEventListener("change", () => {
    if (boxes.some((x) => x.value === "")) return; // a field being retyped
    const v = boxes.map((x) => Number(x.value));
    if (pick) pick.value = toHex(v);
    set(v);
  });
  span.show = (v) => { boxes.forEach((b, i) => { b.value = v[i]; }); if (pick) pick.value = toHex(v); };
  return span;
}

// Ramp stops: one line per row (a row of numbers, or one number for a __global const float*);
// a colour picker for (t, r, g, b) rows; rows can be added and removed; any change sends the
// whole list.
function rowsEditor(id, rows, set) {
  const table = el("div", { id, class: "rows" });
  const scalar = rows.length > 0 && !Array.isArray(rows[0]);
  const current = () => [...table.querySelectorAll(".row")].map((r) => {
    const v = [...r.querySelectorAll("input[type=number]")].map((x) => Number(x.value));
    return scalar ? v[0] : v;
  });
  const draw = (data) => {
    table.replaceChildren();
    data.forEach((row, i) => {
      const cells = scalar ? [row] : row;
      const changed = () => { if (![...table.querySelectorAll("input[type=number]")].some((x) => x.value === "")) set(current()); };
      const boxes = cells.map((v) => el("input", { type: "number", step: "any", value: v, onchange: changed }));
      const line = el("div", { class: "row wide" }, ...boxes);
      if (!scalar && row.length === 4) {
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
      const d = current();
      const last = d[d.length - 1];
      d.push(Array.isArray(last) ? [...last] : last);
      draw(d); set(d); } }, "add stop"));
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

// The graph as columns by depth (sources left), links as curves, material outputs outlined.
function drawGraph(schema) {
  const svg = $("graph");
  const ns = "http://www.w3.org/2000/svg";
  svg.replaceChildren();
  const graph = {
    nodes: schema.nodes.map((n) => ({ id: n.id, links: Object.fromEntries(
      n.inputs.filter((i) => "node" in i).map((i) => [i.name, i.node])) })),
    materials: schema.materials || {},
  };
  const depth = {};
  const byId = Object.fromEntries(graph.nodes.map((n) => [n.id, n]));
  // Iterative: a deep graph (a Blender export of a long chain) must not overflow the stack.
  const d = (root) => {
    const stack = [[root, 0]];
    const onPath = new Set();
    while (stack.length) {
      const [id, state] = stack.pop();
      if (depth[id] != null || !byId[id]) { if (!byId[id]) depth[id] = 0; continue; }
      const srcs = Object.values(byId[id].links).filter((s) => byId[s] && !onPath.has(s));
      if (state === 0) {
        onPath.add(id);
        stack.push([id, 1]);
        for (const s of srcs) if (depth[s] == null) stack.push([s, 0]);
      } else {
        onPath.delete(id);
        depth[id] = Math.max(0, ...srcs.map((s) => (depth[s] ?? 0) + 1));
      }
    }
    return depth[root];
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
