// The report page: reads the embedded result and buffers, fills the region
// table (sortable), features, estimates, timings and mesh facts, and links
// the table, the 3D view and the selection panel. When done it sets
// <body data-state="ready" data-region-rows="N" data-webgl="yes|no"
// data-canvas-rect="x,y,w,h">. The URL's hash can ask for a selection
// (#select=REGION_ID, a link to a region) and a pick at canvas pixel X,Y
// (#pick=X,Y, answered in data-pick-face and data-pick-region). #bench=N
// times N orbit frames and N picks (data-frame-ms, data-pick-ms) and the
// load (data-load-ms, from navigation to ready) for bench/report/.
"use strict";

function decodeBuffer(id, ArrayType) {
  const node = document.getElementById(id);
  if (!node) return null;
  const text = atob(node.textContent.trim());
  const bytes = new Uint8Array(text.length);
  for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
  return new ArrayType(bytes.buffer);
}

function fmt(x) {
  if (typeof x === "string" && x !== "" && !isNaN(Number(x))) x = Number(x);  // int64 as text
  if (typeof x !== "number") return String(x);
  if (Number.isInteger(x)) return String(x);
  const a = Math.abs(x);
  return a !== 0 && (a < 1e-3 || a >= 1e6) ? x.toExponential(3) : String(Number(x.toPrecision(5)));
}

function vec(v) { return v ? `(${fmt(v.x ?? 0)}, ${fmt(v.y ?? 0)}, ${fmt(v.z ?? 0)})` : "-"; }

// "SURFACE_TYPE_CYLINDER" -> "cylinder".
function word(name, prefix) { return String(name).replace(prefix, "").toLowerCase().replace(/_/g, " "); }

const DEG = 180 / Math.PI;

// The region's surface parameters as [label, value] pairs.
function surfaceParams(region) {
  if (region.plane) return [["point", vec(region.plane.point)], ["normal", vec(region.plane.normal)]];
  if (region.cylinder) {
    const c = region.cylinder;
    return [["radius", fmt(c.radius)], ["axis", vec(c.axis_direction)], ["through", vec(c.axis_origin)]];
  }
  if (region.cone) {
    const c = region.cone;
    return [["half angle", fmt(c.half_angle * DEG) + "\u00b0"], ["apex", vec(c.apex)],
            ["axis", vec(c.axis_direction)]];
  }
  if (region.sphere) return [["radius", fmt(region.sphere.radius)], ["centre", vec(region.sphere.center)]];
  if (region.torus) {
    const t = region.torus;
    return [["major radius", fmt(t.major_radius)], ["minor radius", fmt(t.minor_radius)],
            ["centre", vec(t.center)], ["axis", vec(t.axis_direction)]];
  }
  if (region.quadric) return [["coefficients", (region.quadric.coefficients || []).map(fmt).join(" ")]];
  return [];
}

function shortParams(region) {
  const p = surfaceParams(region);
  if (region.plane) return "n = " + p[1][1];
  if (region.quadric) return "quadric";
  return p.slice(0, 2).map(([k, v]) => `${k} ${v}`).join(", ");
}

function cell(row, text, numeric) {
  const td = row.insertCell();
  td.textContent = text;
  if (numeric) td.className = "num";
  return td;
}

function factRows(table, rows) {
  const body = table.tBodies[0];
  body.textContent = "";
  for (const [key, value] of rows) {
    const tr = body.insertRow();
    const th = document.createElement("th");
    th.textContent = key;
    tr.appendChild(th);
    cell(tr, value, false);
  }
}

class Report {
  constructor(data) {
    this.data = data;
    this.result = data.result;
    this.regions = this.result.regions || [];
    this.colors = decodeBuffer("meshseg-colors", Uint8Array) || new Uint8Array(0);
    this.indexOfId = new Map(this.regions.map((r, i) => [r.id, i]));
    this.selected = -1;
    this.viewer = null;
  }

  swatch(index) {
    const s = document.createElement("span");
    s.className = "swatch";
    const c = this.colors.subarray(3 * index, 3 * index + 3);
    s.style.background = `rgb(${c[0]}, ${c[1]}, ${c[2]})`;
    return s;
  }

  regionLink(id) {
    const index = this.indexOfId.get(id);
    const a = document.createElement("a");
    a.className = "region-link";
    a.textContent = id < 0 ? "border" : String(id);
    if (index !== undefined) {
      a.prepend(this.swatch(index));
      a.addEventListener("click", () => this.select(index));
    }
    return a;
  }

  fillRegions() {
    const body = document.querySelector("#regions tbody");
    this.rows = this.regions.map((r, i) => {
      const tr = document.createElement("tr");
      tr.dataset.region = i;
      const id = cell(tr, "", true);
      id.append(this.swatch(i), String(r.id));
      cell(tr, word(r.type, "SURFACE_TYPE_"));
      cell(tr, fmt(r.face_count), true);
      cell(tr, fmt(r.area), true);
      cell(tr, fmt(r.rms_distance), true);
      cell(tr, fmt(r.max_distance), true);
      cell(tr, shortParams(r));
      tr.addEventListener("click", () => this.select(i));
      body.appendChild(tr);
      return tr;
    });
    document.getElementById("region-count").textContent = `(${this.regions.length})`;
    for (const th of document.querySelectorAll("#regions th")) {
      th.addEventListener("click", () => this.sortBy(th));
    }
  }

  sortBy(th) {
    const key = th.dataset.key, numeric = th.dataset.type === "number";
    const ascending = th.getAttribute("aria-sort") !== "ascending";
    for (const other of document.querySelectorAll("#regions th")) other.removeAttribute("aria-sort");
    th.setAttribute("aria-sort", ascending ? "ascending" : "descending");
    const value = (i) => {
      const r = this.regions[i];
      if (key === "params") return shortParams(r);
      return numeric ? Number(r[key] ?? 0) : String(r[key] ?? "");
    };
    const order = this.rows.map((_, i) => i).sort((a, b) => {
      const va = value(a), vb = value(b);
      const c = numeric ? va - vb : va.localeCompare(vb);
      return (ascending ? c : -c) || a - b;
    });
    const body = document.querySelector("#regions tbody");
    for (const i of order) body.appendChild(this.rows[i]);
  }

  fillFeatures() {
    const list = document.getElementById("features");
    const features = this.result.features || [];
    document.getElementById("feature-count").textContent = `(${features.length})`;
    if (features.length === 0) list.innerHTML = '<li class="muted">none recognised</li>';
    for (const f of features) {
      const li = document.createElement("li");
      let text = word(f.type, "FEATURE_TYPE_");
      if (/FILLET|BLEND/.test(f.type)) text += ` r = ${fmt(f.radius)} ${f.convex ? "convex" : "concave"}`;
      if (f.type === "FEATURE_TYPE_LINEAR_EXTRUSION") text += ` along ${vec(f.direction)}`;
      if (f.type === "FEATURE_TYPE_REVOLUTION") text += ` about ${vec(f.direction)} through ${vec(f.point)}`;
      li.append(text + ": regions ");
      (f.regions || []).forEach((id, k) => { if (k) li.append(", "); li.append(this.regionLink(id)); });
      list.appendChild(li);
    }
  }

  fillFacts() {
    const e = this.result.estimates || {};
    factRows(document.getElementById("estimates"),
             Object.keys(e).map((k) => [k.replace(/_/g, " "), typeof e[k] === "object" ? vec(e[k]) : fmt(e[k])]));
    const timings = this.data.timings || [];
    factRows(document.getElementById("timings"), timings.length
        ? timings.map((t) => [t.stage, fmt(t.seconds) + " s"])
        : [["not recorded", "timings are kept in reports written by `meshseg segment --report`"]]);
    const m = this.result.mesh || {};
    const curves = this.result.curves || [];
    const sharp = curves.filter((c) => c.sharp).length;
    const rows = Object.keys(m).map((k) => [k.replace(/_/g, " "), typeof m[k] === "object" ? vec(m[k]) : fmt(m[k])]);
    rows.push(["curves", `${curves.length} (${sharp} sharp, ${curves.length - sharp} smooth)`],
              ["loops", fmt((this.result.loops || []).length)],
              ["corners", fmt((this.result.corners || []).length)],
              ["adjacent region pairs", fmt((this.result.adjacency || []).length)]);
    if (this.data.geometry.note) rows.push(["3D view", this.data.geometry.note]);
    factRows(document.getElementById("mesh-info"), rows);
  }

  // Selects region `index` (-1 = none) in the table, the view and the panel.
  select(index) {
    this.selected = index;
    for (const tr of this.rows) tr.classList.toggle("selected", Number(tr.dataset.region) === index);
    if (index >= 0) this.rows[index].scrollIntoView({block: "nearest"});
    if (this.viewer) this.viewer.setSelected(index);
    const panel = document.getElementById("selection");
    panel.textContent = "";
    if (index < 0) {
      panel.innerHTML = '<p class="muted">Click a face or a table row to select its region.</p>';
      return;
    }
    const r = this.regions[index];
    const h = document.createElement("h3");
    h.append(this.swatch(index), `Region ${r.id}: ${word(r.type, "SURFACE_TYPE_")}`);
    panel.appendChild(h);
    const table = document.createElement("table");
    table.className = "facts";
    table.appendChild(document.createElement("tbody"));
    factRows(table, [...surfaceParams(r), ["rms distance", fmt(r.rms_distance)],
                     ["max distance", fmt(r.max_distance)], ["faces", fmt(r.face_count)],
                     ["area", fmt(r.area)]]);
    panel.appendChild(table);
  }

  hover(element, index, x, y) {
    const tip = document.getElementById("tooltip");
    if (index < 0) { tip.hidden = true; return; }
    const r = this.regions[index];
    tip.textContent = "";
    const title = document.createElement("div");
    title.append(this.swatch(index), `region ${r.id} \u00b7 ${word(r.type, "SURFACE_TYPE_")}`);
    tip.appendChild(title);
    for (const [k, v] of [...surfaceParams(r), ["rms", fmt(r.rms_distance)], ["max", fmt(r.max_distance)]]) {
      const line = document.createElement("div");
      line.textContent = `${k}: ${v}`;
      tip.appendChild(line);
    }
    const kind = this.data.geometry.kind === "points" ? "point" : "face";
    const foot = document.createElement("div");
    foot.className = "muted";
    foot.textContent = `${kind} ${element}`;
    tip.appendChild(foot);
    tip.style.left = `${x + 14}px`;
    tip.style.top = `${y + 14}px`;
    tip.hidden = false;
  }

  followHash(hash) {
    const params = new URLSearchParams(hash.replace(/^#/, ""));
    if (params.has("select")) {
      const index = this.indexOfId.get(Number(params.get("select")));
      if (index !== undefined) this.select(index);
    }
    if (params.has("bench") && this.viewer) this.bench(Number(params.get("bench")));
    if (params.has("pick") && this.viewer) {
      const [x, y] = params.get("pick").split(",").map(Number);
      const element = this.viewer.pick(x, y);
      const index = this.viewer.regionOf(element);
      document.body.dataset.pickFace = String(element);
      document.body.dataset.pickRegion = String(index >= 0 ? this.regions[index].id : -1);
    }
  }

  bench(n) {
    const v = this.viewer, gl = v.gl, body = document.body.dataset;
    body.loadMs = String(Math.round(performance.now()));
    let t = performance.now();
    for (let i = 0; i < n; ++i) {
      v.back = Vec3.normalize(Vec3.rotate(v.back, v.up, 0.05));
      v.draw();
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));  // waits for the frame
    }
    body.frameMs = (((performance.now() - t) / n)).toFixed(1);
    t = performance.now();
    for (let i = 0; i < n; ++i) {
      v.back = Vec3.normalize(Vec3.rotate(v.back, v.up, 0.05));
      v.pickValid = false;  // the worst case: the first pick after the view moved
      v.pick(v.canvas.clientWidth / 2, v.canvas.clientHeight / 2);
    }
    body.pickMs = (((performance.now() - t) / n)).toFixed(1);
  }

  startViewer() {
    const g = this.data.geometry;
    const message = document.getElementById("view-message");
    if (g.kind === "none") {
      message.textContent = g.note;
      message.hidden = false;
      return "no";
    }
    const model = {
      positions: decodeBuffer("meshseg-positions", Float32Array),
      triangles: g.kind === "points" ? null : decodeBuffer("meshseg-triangles", Uint32Array),
      labels: decodeBuffer("meshseg-labels", Int32Array),
      colors: this.colors,
      sharp: decodeBuffer("meshseg-sharp", Uint32Array),
      smooth: decodeBuffer("meshseg-smooth", Uint32Array),
    };
    try {
      this.viewer = new Viewer(document.getElementById("canvas"), model, {
        hover: (element, index, x, y) => this.hover(element, index, x, y),
        select: (index) => this.select(index),
      });
      this.viewer.draw();
    } catch (err) {
      message.textContent = `The 3D view needs WebGL 2 (${err.message}); the tables below are complete.`;
      message.hidden = false;
      return "no";
    }
    const curves = document.getElementById("show-curves");
    curves.disabled = !(model.sharp || model.smooth);
    curves.addEventListener("change", () => this.viewer.setShowCurves(curves.checked));
    document.getElementById("reset-view").addEventListener("click", () => this.viewer.resetView());
    return "yes";
  }
}

function main() {
  const data = JSON.parse(document.getElementById("meshseg-report").textContent);
  const report = new Report(data);
  document.title = `meshseg report: ${data.title}`;
  document.getElementById("title").textContent = `meshseg report: ${data.title}`;
  const m = data.result.mesh || {};
  const e = data.result.estimates || {};
  document.getElementById("summary").textContent =
      `${report.regions.length} regions \u00b7 ${fmt(m.face_count ?? 0)} faces \u00b7 ` +
      `${(data.result.features || []).length} features \u00b7 noise \u03c3 ${fmt(e.noise_sigma ?? 0)} \u00b7 ` +
      `distance tolerance ${fmt(e.distance_tolerance ?? 0)}`;
  report.fillRegions();
  report.fillFeatures();
  report.fillFacts();
  document.getElementById("clear-selection").addEventListener("click", () => report.select(-1));
  document.body.dataset.webgl = report.startViewer();
  document.body.dataset.regionRows = String(report.rows.length);
  const rect = document.getElementById("canvas").getBoundingClientRect();
  document.body.dataset.canvasRect = [rect.left, rect.top, rect.width, rect.height].map(Math.round).join(",");
  report.followHash(location.hash);
  document.body.dataset.state = "ready";
}

try {
  main();
} catch (err) {
  document.body.dataset.state = "error";
  document.getElementById("summary").textContent = `This report could not be shown: ${err.message}`;
}
