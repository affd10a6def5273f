// WebGL 2 helpers of the report viewer (viewer.js): 4x4 matrices and 3-vectors,
// the shaders (faces coloured by their label texture, picking ids, lines), program
// compilation and 1-D arrays stored as 2-D textures.
"use strict";

const FOV_Y = 0.6;  // vertical field of view, radians

const Mat4 = {
  perspective(fovy, aspect, near, far) {
    const f = 1 / Math.tan(fovy / 2), nf = 1 / (near - far);
    return new Float32Array([f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) * nf, -1,
                             0, 0, 2 * far * near * nf, 0]);
  },
  // The view matrix of a camera at `eye` with orthonormal axes right, up, back.
  view(eye, right, up, back) {
    const d = (a) => -(a[0] * eye[0] + a[1] * eye[1] + a[2] * eye[2]);
    return new Float32Array([right[0], up[0], back[0], 0, right[1], up[1], back[1], 0,
                             right[2], up[2], back[2], 0, d(right), d(up), d(back), 1]);
  },
  multiply(a, b) {
    const out = new Float32Array(16);
    for (let c = 0; c < 4; ++c) {
      for (let r = 0; r < 4; ++r) {
        let s = 0;
        for (let k = 0; k < 4; ++k) s += a[k * 4 + r] * b[c * 4 + k];
        out[c * 4 + r] = s;
      }
    }
    return out;
  },
};

const Vec3 = {
  add: (a, b, s = 1) => [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]],
  scale: (a, s) => [a[0] * s, a[1] * s, a[2] * s],
  cross: (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]],
  normalize(a) {
    const n = Math.hypot(a[0], a[1], a[2]) || 1;
    return [a[0] / n, a[1] / n, a[2] / n];
  },
  // `v` rotated by `angle` radians about the unit `axis` (Rodrigues).
  rotate(v, axis, angle) {
    const c = Math.cos(angle), s = Math.sin(angle);
    const d = (axis[0] * v[0] + axis[1] * v[1] + axis[2] * v[2]) * (1 - c);
    const x = Vec3.cross(axis, v);
    return [v[0] * c + x[0] * s + axis[0] * d, v[1] * c + x[1] * s + axis[1] * d,
            v[2] * c + x[2] * s + axis[2] * d];
  },
};

const VERTEX_SHADER = `#version 300 es
uniform mat4 u_view;
uniform mat4 u_projection;
uniform int u_points;
uniform float u_point_size;
in vec3 a_position;
out vec3 v_view_position;
flat out int v_element;
void main() {
  vec4 p = u_view * vec4(a_position, 1.0);
  v_view_position = p.xyz;
  v_element = u_points == 1 ? gl_VertexID : gl_VertexID / 3;
  gl_Position = u_projection * p;
  gl_PointSize = u_point_size;
}`;

// Shading and picking share the vertex shader; u_pick writes element id + 1.
const FRAGMENT_SHADER = `#version 300 es
precision highp float;
precision highp int;
precision highp isampler2D;
uniform isampler2D u_labels;     // label per element, row-major, width u_width
uniform sampler2D u_palette;     // colour per region index, row-major, width u_width
uniform int u_width;
uniform int u_points;
uniform int u_pick;
uniform int u_selected;          // region index, -1 = none
uniform int u_hovered;
in vec3 v_view_position;
flat in int v_element;
out vec4 out_color;
ivec2 At(int i) { return ivec2(i % u_width, i / u_width); }
void main() {
  if (u_pick == 1) {
    int id = v_element + 1;
    out_color = vec4(float(id & 255), float((id >> 8) & 255), float((id >> 16) & 255),
                     float((id >> 24) & 255)) / 255.0;
    return;
  }
  int region = texelFetch(u_labels, At(v_element), 0).r;
  vec3 base = region < 0 ? vec3(0.55) : texelFetch(u_palette, At(region), 0).rgb;
  float light = 1.0;
  if (u_points == 0) {
    vec3 n = normalize(cross(dFdx(v_view_position), dFdy(v_view_position)));
    light = 0.35 + 0.65 * abs(n.z);
  }
  vec3 color = base * light;
  if (u_selected >= 0 && region != u_selected) color = mix(color, vec3(dot(color, vec3(0.33))), 0.7);
  if (region >= 0 && region == u_hovered) color = mix(color, vec3(1.0), 0.25);
  out_color = vec4(color, 1.0);
}`;

const LINE_VERTEX_SHADER = `#version 300 es
uniform mat4 u_view;
uniform mat4 u_projection;
in vec3 a_position;
void main() { gl_Position = u_projection * u_view * vec4(a_position, 1.0); }`;

const LINE_FRAGMENT_SHADER = `#version 300 es
precision mediump float;
uniform vec3 u_color;
out vec4 out_color;
void main() { out_color = vec4(u_color, 1.0); }`;

function compile(gl, vertexSource, fragmentSource) {
  const program = gl.createProgram();
  for (const [type, source] of [[gl.VERTEX_SHADER, vertexSource],
                                [gl.FRAGMENT_SHADER, fragmentSource]]) {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
      throw new Error("shader: " + gl.getShaderInfoLog(shader));
    }
    gl.attachShader(program, shader);
  }
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
    throw new Error("program: " + gl.getProgramInfoLog(program));
  }
  const uniforms = {};
  const count = gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS);
  for (let i = 0; i < count; ++i) {
    const name = gl.getActiveUniform(program, i).name;
    uniforms[name] = gl.getUniformLocation(program, name);
  }
  return {program, uniforms, position: gl.getAttribLocation(program, "a_position")};
}

// A 1-D array as a 2-D texture `width` texels wide (one row per `width`).
function arrayTexture(gl, width, count, internalFormat, format, type, ArrayType, components,
                      fill) {
  const height = Math.max(1, Math.ceil(count / width));
  const data = new ArrayType(width * height * components);
  fill(data);
  const texture = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
  gl.texImage2D(gl.TEXTURE_2D, 0, internalFormat, width, height, 0, format, type, data);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  return texture;
}
