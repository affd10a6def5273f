// A small WebGL 2 viewer for the report: a triangle mesh (or a point cloud)
// coloured per region, boundary curves as lines, orbit / pan / zoom, and
// picking by rendering element ids into an offscreen buffer, so a hover or a
// click costs one extra draw and one pixel read whatever the face count.
//
// Triangles are drawn unindexed (three vertices per face) so gl_VertexID / 3
// is the face id: the face's label comes from a texture, its normal from the
// screen-space derivatives of the position. No per-vertex colour or normal
// buffers are needed.
"use strict";

// Matrices, vectors, shaders and textures: gl.js, loaded before this file.

// Viewer(canvas, model, handlers)
//   model.positions  Float32Array, xyz per vertex (centred on the bounding box)
//   model.triangles  Uint32Array, 3 vertex ids per face, or null for points
//   model.labels     Int32Array, region index per face (or point), -1 = none
//   model.colors     Uint8Array, rgb per region index
//   model.sharp / model.smooth  Uint32Array, vertex id pairs of curve segments
//   handlers.hover(element, regionIndex, x, y)  the pointer moved (-1 off the model)
//   handlers.select(regionIndex)                a click without a drag
class Viewer {
  constructor(canvas, model, handlers) {
    const gl = canvas.getContext("webgl2", {antialias: true, preserveDrawingBuffer: true});
    if (!gl) throw new Error("this browser offers no WebGL 2");
    this.gl = gl;
    this.canvas = canvas;
    this.model = model;
    this.handlers = handlers;
    this.showCurves = true;
    this.selected = -1;
    this.hovered = -1;
    this.points = model.triangles === null;
    this.elementCount = this.points ? model.positions.length / 3 : model.triangles.length / 3;
    this.width = Math.min(4096, gl.getParameter(gl.MAX_TEXTURE_SIZE));
    this.mesh = compile(gl, VERTEX_SHADER, FRAGMENT_SHADER);
    this.lines = compile(gl, LINE_VERTEX_SHADER, LINE_FRAGMENT_SHADER);
    this.upload();
    this.resetView();
    this.attachInput();
    // Redrawn at once, not on the next frame: resize callbacks run before the
    // page is painted, so no frame shows the old image stretched.
    new ResizeObserver(() => { this.pickValid = false; this.draw(); }).observe(canvas);
  }

  upload() {
    const gl = this.gl, m = this.model;
    const expanded = this.points ? m.positions : new Float32Array(m.triangles.length * 3);
    if (!this.points) {
      for (let i = 0; i < m.triangles.length; ++i) {
        const v = m.triangles[i] * 3;
        expanded[3 * i] = m.positions[v];
        expanded[3 * i + 1] = m.positions[v + 1];
        expanded[3 * i + 2] = m.positions[v + 2];
      }
    }
    this.meshBuffer = this.vertexArray(this.mesh, expanded);
    this.lineBuffer = this.vertexArray(this.lines, m.positions);
    this.sharpIndices = this.indexBuffer(m.sharp);
    this.smoothIndices = this.indexBuffer(m.smooth);
    this.labelTexture = arrayTexture(gl, this.width, this.elementCount, gl.R32I, gl.RED_INTEGER,
                                     gl.INT, Int32Array, 1, (d) => d.set(m.labels));
    const regions = m.colors.length / 3;
    this.paletteTexture = arrayTexture(gl, this.width, regions, gl.RGBA8, gl.RGBA,
                                       gl.UNSIGNED_BYTE, Uint8Array, 4, (d) => {
      for (let i = 0; i < regions; ++i) {
        d.set(m.colors.subarray(3 * i, 3 * i + 3), 4 * i);
        d[4 * i + 3] = 255;
      }
    });
    let radius = 0;
    for (let i = 0; i < m.positions.length; i += 3) {
      radius = Math.max(radius, Math.hypot(m.positions[i], m.positions[i + 1], m.positions[i + 2]));
    }
    this.radius = radius || 1;
  }

  vertexArray(program, positions) {
    const gl = this.gl;
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const buffer = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
    gl.bufferData(gl.ARRAY_BUFFER, positions, gl.STATIC_DRAW);
    gl.enableVertexAttribArray(program.position);
    gl.vertexAttribPointer(program.position, 3, gl.FLOAT, false, 0, 0);
    gl.bindVertexArray(null);
    return vao;
  }

  indexBuffer(indices) {
    if (!indices || indices.length === 0) return null;
    const gl = this.gl;
    const buffer = gl.createBuffer();
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, buffer);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, indices, gl.STATIC_DRAW);
    return {buffer, count: indices.length};
  }

  resetView() {
    this.target = [0, 0, 0];
    // Looking from the first octant, z up.
    this.back = Vec3.normalize([1, -1.3, 0.9]);
    this.up = Vec3.normalize(Vec3.cross(Vec3.cross(this.back, [0, 0, 1]), this.back));
    // The bounding sphere fits the vertical field of view with a margin.
    this.distance = 1.1 * this.radius / Math.sin(FOV_Y / 2);
    this.requestDraw();
  }

  setSelected(region) { this.selected = region; this.requestDraw(false); }
  setShowCurves(show) { this.showCurves = show; this.requestDraw(false); }

  // Redraws on the next frame; `moved` (the camera or canvas changed) also
  // invalidates the picking buffer.
  requestDraw(moved = true) {
    if (moved) this.pickValid = false;
    if (this.drawPending) return;
    this.drawPending = true;
    requestAnimationFrame(() => { this.drawPending = false; this.draw(); });
  }

  matrices() {
    const c = this.canvas;
    const ratio = window.devicePixelRatio || 1;
    const w = Math.max(1, Math.round(c.clientWidth * ratio));
    const h = Math.max(1, Math.round(c.clientHeight * ratio));
    if (c.width !== w || c.height !== h) { c.width = w; c.height = h; }
    const right = Vec3.cross(this.up, this.back);
    const eye = Vec3.add(this.target, this.back, this.distance);
    const near = Math.max(this.distance - 2 * this.radius, this.distance * 1e-3);
    const far = this.distance + 2 * this.radius;
    return {view: Mat4.view(eye, right, this.up, this.back),
            projection: Mat4.perspective(FOV_Y, w / h, near, far), w, h};
  }

  // Draws the model; with `pick`, element ids into the bound framebuffer.
  draw(pick = false) {
    const gl = this.gl;
    const {view, projection, w, h} = this.matrices();
    gl.viewport(0, 0, w, h);
    gl.enable(gl.DEPTH_TEST);
    gl.clearColor(pick ? 0 : 0.933, pick ? 0 : 0.945, pick ? 0 : 0.957, pick ? 0 : 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    const p = this.mesh, u = p.uniforms;
    gl.useProgram(p.program);
    gl.uniformMatrix4fv(u.u_view, false, view);
    gl.uniformMatrix4fv(u.u_projection, false, projection);
    gl.uniform1i(u.u_points, this.points ? 1 : 0);
    gl.uniform1f(u.u_point_size, Math.max(2, (window.devicePixelRatio || 1) * 3));
    gl.uniform1i(u.u_pick, pick ? 1 : 0);
    gl.uniform1i(u.u_width, this.width);
    gl.uniform1i(u.u_selected, this.selected);
    gl.uniform1i(u.u_hovered, this.hovered);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.labelTexture);
    gl.uniform1i(u.u_labels, 0);
    gl.activeTexture(gl.TEXTURE1);
    gl.bindTexture(gl.TEXTURE_2D, this.paletteTexture);
    gl.uniform1i(u.u_palette, 1);
    // Faces a little behind their edges, so curves on them stay visible.
    gl.enable(gl.POLYGON_OFFSET_FILL);
    gl.polygonOffset(1, 1);
    gl.bindVertexArray(this.meshBuffer);
    gl.drawArrays(this.points ? gl.POINTS : gl.TRIANGLES, 0, this.points ? this.elementCount
                                                                          : 3 * this.elementCount);
    gl.disable(gl.POLYGON_OFFSET_FILL);
    if (!pick && this.showCurves) this.drawCurves(view, projection);
    gl.bindVertexArray(null);
  }

  drawCurves(view, projection) {
    const gl = this.gl, p = this.lines;
    gl.useProgram(p.program);
    gl.uniformMatrix4fv(p.uniforms.u_view, false, view);
    gl.uniformMatrix4fv(p.uniforms.u_projection, false, projection);
    gl.bindVertexArray(this.lineBuffer);
    for (const [indices, color] of [[this.sharpIndices, [0.05, 0.05, 0.08]],
                                    [this.smoothIndices, [0.98, 0.98, 0.98]]]) {
      if (!indices) continue;
      gl.uniform3fv(p.uniforms.u_color, color);
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, indices.buffer);
      gl.drawElements(gl.LINES, indices.count, gl.UNSIGNED_INT, 0);
    }
  }

  // Returns the element (face or point) under canvas pixel (x, y) in CSS
  // pixels, or -1.
  pick(x, y) {
    const gl = this.gl;
    const ratio = window.devicePixelRatio || 1;
    const {w, h} = this.matrices();
    if (!this.pickTarget || this.pickTarget.w !== w || this.pickTarget.h !== h) {
      const fb = gl.createFramebuffer(), color = gl.createRenderbuffer(), depth = gl.createRenderbuffer();
      gl.bindRenderbuffer(gl.RENDERBUFFER, color);
      gl.renderbufferStorage(gl.RENDERBUFFER, gl.RGBA8, w, h);
      gl.bindRenderbuffer(gl.RENDERBUFFER, depth);
      gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, w, h);
      gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
      gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, color);
      gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, depth);
      this.pickTarget = {fb, w, h};
      this.pickValid = false;
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.pickTarget.fb);
    if (!this.pickValid) {
      gl.disable(gl.BLEND);
      this.draw(true);
      this.pickValid = true;
    }
    const px = new Uint8Array(4);
    gl.readPixels(Math.floor(x * ratio), Math.floor(h - 1 - y * ratio), 1, 1, gl.RGBA,
                  gl.UNSIGNED_BYTE, px);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return (px[0] | (px[1] << 8) | (px[2] << 16) | (px[3] << 24)) - 1;
  }

  regionOf(element) { return element >= 0 ? this.model.labels[element] : -1; }

  attachInput() {
    const c = this.canvas;
    let drag = null;
    c.addEventListener("contextmenu", (e) => e.preventDefault());
    c.addEventListener("pointerdown", (e) => {
      drag = {x: e.clientX, y: e.clientY, pan: e.shiftKey || e.button !== 0, moved: false};
      c.setPointerCapture(e.pointerId);
      c.classList.add("dragging");
    });
    c.addEventListener("pointermove", (e) => {
      const rect = c.getBoundingClientRect();
      if (!drag) {
        const element = this.pick(e.clientX - rect.left, e.clientY - rect.top);
        const region = this.regionOf(element);
        if (region !== this.hovered) { this.hovered = region; this.requestDraw(false); }
        this.handlers.hover(element, region, e.clientX - rect.left, e.clientY - rect.top);
        return;
      }
      const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
      if (Math.abs(dx) + Math.abs(dy) > 2) drag.moved = true;
      drag.x = e.clientX;
      drag.y = e.clientY;
      if (drag.pan) {
        const perPixel = 2 * this.distance * Math.tan(FOV_Y / 2) / Math.max(1, c.clientHeight);
        const right = Vec3.cross(this.up, this.back);
        this.target = Vec3.add(Vec3.add(this.target, right, -dx * perPixel), this.up, dy * perPixel);
      } else {
        const right = Vec3.cross(this.up, this.back);
        // Drag right turns the model right (camera about its up axis); drag
        // down tips it towards the viewer (about the camera's right axis).
        const yaw = -dx * 0.008, pitch = -dy * 0.008;
        const back = Vec3.normalize(Vec3.rotate(Vec3.rotate(this.back, this.up, yaw), right, pitch));
        const newRight = Vec3.normalize(Vec3.cross(Vec3.rotate(this.up, right, pitch), back));
        this.back = back;
        this.up = Vec3.cross(back, newRight);
      }
      this.requestDraw();
    });
    c.addEventListener("pointerup", (e) => {
      c.classList.remove("dragging");
      if (drag && !drag.moved && e.button === 0) {
        const rect = c.getBoundingClientRect();
        this.handlers.select(this.regionOf(this.pick(e.clientX - rect.left, e.clientY - rect.top)));
      }
      drag = null;
    });
    c.addEventListener("pointerleave", () => {
      if (this.hovered !== -1) { this.hovered = -1; this.requestDraw(false); }
      this.handlers.hover(-1, -1, 0, 0);
    });
    c.addEventListener("wheel", (e) => {
      e.preventDefault();
      this.distance = Math.min(50 * this.radius, Math.max(1e-3 * this.radius,
                               this.distance * Math.exp(e.deltaY * 0.0015)));
      this.requestDraw();
    }, {passive: false});
    c.addEventListener("dblclick", () => this.resetView());
  }
}
