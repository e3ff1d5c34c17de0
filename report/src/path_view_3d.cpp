// SPDX-License-Identifier: Apache-2.0
#include "ncpost/report/path_view_3d.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ncpost/report/html_page.hpp"

namespace ncpost::report {
namespace {

// The viewer: orthographic, Z up; yaw about Z, then the elevation. Data are centred and scaled
// to the unit sphere on the C++ side, so the script only rotates.
constexpr const char* kScript = R"JS(
(function () {
  var views = NCPOST_VIEWS;
  var state = { yaw: -0.7, pitch: 0.55, zoom: 1.0 };
  var drawn = [];
  function shader(gl, type, text) {
    var s = gl.createShader(type); gl.shaderSource(s, text); gl.compileShader(s); return s;
  }
  function setup(v) {
    var canvas = document.getElementById(v.id);
    var gl = canvas.getContext('webgl', { preserveDrawingBuffer: true, antialias: true }) ||
             canvas.getContext('experimental-webgl', { preserveDrawingBuffer: true });
    if (!gl) {
      canvas.setAttribute('data-drawn-pixels', '0');
      canvas.insertAdjacentHTML('afterend', '<p class="note">This browser has no WebGL: the 3D view cannot be drawn.</p>');
      return null;
    }
    var prog = gl.createProgram();
    gl.attachShader(prog, shader(gl, gl.VERTEX_SHADER,
      'attribute vec3 p; attribute vec3 c; uniform mat3 m; uniform vec2 k; varying vec3 vc;' +
      'void main(){ vec3 q = m * p; gl_Position = vec4(q.x * k.x, q.y * k.y, q.z * 0.5, 1.0); vc = c; }'));
    gl.attachShader(prog, shader(gl, gl.FRAGMENT_SHADER,
      'precision mediump float; varying vec3 vc; void main(){ gl_FragColor = vec4(vc, 1.0); }'));
    gl.linkProgram(prog);
    var pos = [], col = [];
    var n = v.p.length / 3;
    for (var i = 1; i < n; ++i) {
      for (var e = i - 1; e <= i; ++e) {
        pos.push(v.p[3 * e], v.p[3 * e + 1], v.p[3 * e + 2]);
        col.push(v.c[3 * i] / 255, v.c[3 * i + 1] / 255, v.c[3 * i + 2] / 255);
      }
    }
    // axis triad at the lower corner of the paths' box: X red, Y green, Z blue
    var o = NCPOST_CORNER;
    [[1, 0, 0], [0, 1, 0], [0, 0, 1]].forEach(function (d) {
      pos.push(o[0], o[1], o[2], o[0] + 0.3 * d[0], o[1] + 0.3 * d[1], o[2] + 0.3 * d[2]);
      col.push(d[0] * 0.8, d[1] * 0.6, d[2] * 0.9, d[0] * 0.8, d[1] * 0.6, d[2] * 0.9);
    });
    function buffer(data, name) {
      var b = gl.createBuffer(); gl.bindBuffer(gl.ARRAY_BUFFER, b);
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(data), gl.STATIC_DRAW);
      var at = gl.getAttribLocation(prog, name); gl.enableVertexAttribArray(at);
      gl.vertexAttribPointer(at, 3, gl.FLOAT, false, 0, 0);
    }
    gl.useProgram(prog);
    buffer(pos, 'p'); buffer(col, 'c');
    return { gl: gl, prog: prog, count: pos.length / 3, canvas: canvas };
  }
  function draw() {
    var cy = Math.cos(state.yaw), sy = Math.sin(state.yaw), cp = Math.cos(state.pitch), sp = Math.sin(state.pitch);
    // columns of the matrix (x, y, z) -> (screen x, screen y, depth)
    var m = [cy, sp * sy, cp * sy, -sy, sp * cy, cp * cy, 0, cp, -sp];
    drawn.forEach(function (d) {
      if (!d) return;
      var gl = d.gl, w = d.canvas.width, h = d.canvas.height, s = 1.2 * state.zoom;
      gl.viewport(0, 0, w, h);
      gl.clearColor(1, 1, 1, 1); gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
      gl.enable(gl.DEPTH_TEST); gl.depthFunc(gl.LEQUAL);
      gl.useProgram(d.prog);
      gl.uniformMatrix3fv(gl.getUniformLocation(d.prog, 'm'), false, new Float32Array(m));
      gl.uniform2f(gl.getUniformLocation(d.prog, 'k'), s * Math.min(1, h / w), s * Math.min(1, w / h));
      gl.drawArrays(gl.LINES, 0, d.count);
    });
  }
  function count() {
    drawn.forEach(function (d) {
      if (!d) return;
      var gl = d.gl, w = d.canvas.width, h = d.canvas.height, px = new Uint8Array(w * h * 4), n = 0;
      gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
      for (var i = 0; i < px.length; i += 4) if (px[i] < 245 || px[i + 1] < 245 || px[i + 2] < 245) ++n;
      d.canvas.setAttribute('data-drawn-pixels', String(n));
    });
  }
  views.forEach(function (v) { drawn.push(setup(v)); });
  draw(); count();
  var dragging = null;
  drawn.forEach(function (d) {
    if (!d) return;
    d.canvas.addEventListener('mousedown', function (e) { dragging = [e.clientX, e.clientY]; d.canvas.style.cursor = 'grabbing'; });
    d.canvas.addEventListener('wheel', function (e) {
      e.preventDefault(); state.zoom *= Math.exp(-e.deltaY * 0.001); draw();
    }, { passive: false });
  });
  window.addEventListener('mouseup', function () {
    dragging = null; drawn.forEach(function (d) { if (d) d.canvas.style.cursor = 'grab'; });
  });
  window.addEventListener('mousemove', function (e) {
    if (!dragging) return;
    state.yaw += (e.clientX - dragging[0]) * 0.01;
    state.pitch = Math.max(-1.57, Math.min(1.57, state.pitch + (e.clientY - dragging[1]) * 0.01));
    dragging = [e.clientX, e.clientY]; draw();
  });
})();
)JS";

}  // namespace

std::string path_view_3d(const std::vector<PathView3d>& views, const ColourScale& scale, const std::string& bar_title) {
  // one centre and scale for all views, so that they overlay when turned together; framed on the
  // bulk of the path (2nd to 98th percentile of each coordinate), so that a far approach move
  // does not shrink the part to a corner (it runs off the canvas; the wheel zooms out)
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (int k = 0; k < 3; ++k) {
    std::vector<double> c;
    for (const auto& v : views)
      for (const auto& p : v.points) c.push_back(k == 0 ? p.x : k == 1 ? p.y : p.z);
    if (c.empty()) continue;
    const auto at = [&](double q) {
      auto it = c.begin() + static_cast<long>(q * static_cast<double>(c.size() - 1));
      std::nth_element(c.begin(), it, c.end());
      return *it;
    };
    lo[k] = at(0.02);
    hi[k] = at(0.98);
  }
  double centre[3] = {0, 0, 0}, radius = 1.0;
  if (std::isfinite(lo[0])) {
    double r2 = 0;
    for (int k = 0; k < 3; ++k) {
      centre[k] = 0.5 * (lo[k] + hi[k]);
      r2 += 0.25 * (hi[k] - lo[k]) * (hi[k] - lo[k]);
    }
    radius = std::max(std::sqrt(r2), 1e-6);
  }
  std::string data = "[";
  std::string html = "<div class=\"plots\">";
  for (std::size_t i = 0; i < views.size(); ++i) {
    const PathView3d& v = views[i];
    std::string p, c;
    for (std::size_t k = 0; k < v.points.size(); ++k) {
      const double q[3] = {v.points[k].x, v.points[k].y, v.points[k].z};
      for (int a = 0; a < 3; ++a) p += fmt::format("{}{:.4f}", p.empty() ? "" : ",", (q[a] - centre[a]) / radius);
      int rgb[3];
      colour_rgb(scale.fraction(k < v.values.size() ? v.values[k] : 0.0), rgb);
      c += fmt::format("{}{},{},{}", c.empty() ? "" : ",", rgb[0], rgb[1], rgb[2]);
    }
    data += fmt::format("{}{{\"id\":\"{}\",\"p\":[{}],\"c\":[{}]}}", i ? "," : "", v.id, p, c);
    html += fmt::format(
        "<div class=\"plot\"><div>{}</div><canvas class=\"path3d\" id=\"{}\" width=\"460\" height=\"400\">"
        "</canvas></div>",
        escape(v.title), escape(v.id));
  }
  data += "]";
  html += "<div class=\"plot\">" + colour_bar_svg(scale, 400, bar_title) + "</div></div>\n";
  html +=
      "<p class=\"note\">Drag to turn both views, wheel to zoom. Axes at the lower corner: X red, Y green, Z blue "
      "(workpiece frame W). " +
      fmt::format("{:.4g} mm across the frame.", 2 * radius) + "</p>\n";
  std::string script = kScript;
  script.replace(script.find("NCPOST_VIEWS"), 12, data);
  std::string corner = "[";
  for (int k = 0; k < 3; ++k)
    corner += fmt::format("{}{:.4f}", k ? "," : "", std::isfinite(lo[k]) ? (lo[k] - centre[k]) / radius : -0.5);
  script.replace(script.find("NCPOST_CORNER"), 13, corner + "]");
  return html + "<script>" + script + "</script>\n";
}

}  // namespace ncpost::report
