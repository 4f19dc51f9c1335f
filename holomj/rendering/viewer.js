/* holomj report page: the interactive 3D view of the scene's GLB (three.js, see vendor/).
 *
 * Reads the page's #viewer-glb (base64 GLB) and #viewer-objects (JSON: object id -> facts),
 * draws the scene in #viewer-canvas, and exposes window.holomjViewer:
 *   ready                 a Promise resolved after the first frame (rejected when no WebGL)
 *   firstFrameMs          ms from navigation start to the first frame drawn
 *   timings               ms from navigation start: script, context (WebGL), decoded and
 *                         parsed (the GLB)
 *   objectIds()           the ids of the objects in the view
 *   select(id)            select an object as a click does; returns its facts (null: unknown)
 *   pick(x, y)            what a click at canvas pixel (x, y) selects (its id or null)
 *   screenPosition(id)    canvas pixel of an object's centre (for simulated clicks)
 *   setLayer(name, on)    'colliders', 'ceilings' or 'small' (the checkboxes)
 *   lookAt(eye, target)   place the camera (three.js frame: Y up; x, z, -y of MuJoCo's)
 *   pixelStats()          {lit, std}: share of pixels off the background, their spread
 *   timeFrame()           ms to draw one frame (and read it back)
 * Nothing is fetched: the page works from file:// offline.
 */
(function () {
  'use strict';
  var T = window.HOLOMJ_THREE;
  var api = {ready: null, firstFrameMs: null, error: null, selected: null, timings: {}};
  function mark(name) { api.timings[name] = Math.round(performance.now()); }
  mark('script');
  window.holomjViewer = api;
  var box = document.getElementById('viewer-canvas');
  var status = document.getElementById('viewer-status');
  var panel = document.getElementById('viewer-info');
  var facts = JSON.parse(document.getElementById('viewer-objects').textContent || '{}');
  var BACKGROUND = 0xe9edf1;

  function say(text) { if (status) { status.textContent = text; } }

  function fail(message) {
    api.error = message;
    say('3D view unavailable: ' + message + ' (the images below still show the scene)');
    document.body.setAttribute('data-viewer', 'failed');
    return Promise.reject(new Error(message));
  }

  function decode(text) {
    // atob is synchronous and fast; fetch() of a data: URL queues behind the page's parsing
    var raw = atob(text.trim());
    var bytes = new Uint8Array(raw.length);
    for (var i = 0; i < raw.length; i++) { bytes[i] = raw.charCodeAt(i); }
    return bytes.buffer;
  }

  if (!T || !box) { api.ready = fail('the viewer script did not load'); return; }

  // Cheap to draw, so that it stays interactive on software GL (SwiftShader, llvmpipe): no
  // MSAA, Lambert shading, two lights (the scene's own lights stay in the GLB for other tools).
  // One WebGL context only: making one costs a second or more on software GL.
  var renderer;
  try {
    renderer = new T.WebGLRenderer({antialias: false, preserveDrawingBuffer: true});
  } catch (e) {
    api.ready = fail('this browser has no WebGL');
    return;
  }
  renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
  renderer.outputColorSpace = T.SRGBColorSpace;
  renderer.toneMapping = T.NeutralToneMapping;
  renderer.setClearColor(BACKGROUND, 1);
  box.appendChild(renderer.domElement);
  mark('context');
  var scene = new T.Scene();
  scene.background = new T.Color(BACKGROUND);
  scene.add(new T.HemisphereLight(0xffffff, 0x8a8070, 2.2));
  var sun = new T.DirectionalLight(0xffffff, 1.2);
  sun.position.set(0.3, 1.0, 0.45);
  scene.add(sun);
  var camera = new T.PerspectiveCamera(50, 1, 0.05, 500);
  var controls = new T.OrbitControls(camera, renderer.domElement);
  controls.enableDamping = false;
  controls.screenSpacePanning = true;
  var layers = {colliders: [], ceilings: [], small: []};
  var objects = {};
  var highlight = null;
  var home = null;

  function size() {
    var w = box.clientWidth || 800;
    var h = box.clientHeight || 560;
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  }

  function draw() { renderer.render(scene, camera); }

  function lambert(material, cache) {
    if (Array.isArray(material)) { return material.map(function (m) { return lambert(m, cache); }); }
    if (!cache[material.uuid]) {
      var collider = material.name === 'holomj/collider';
      cache[material.uuid] = new T.MeshLambertMaterial({
        name: material.name,
        color: material.color,
        map: material.map || null,
        emissive: material.emissive,
        transparent: material.transparent,
        opacity: material.opacity,
        depthWrite: collider ? false : material.depthWrite,
        side: T.DoubleSide,
        // colliders share faces with the visuals: draw them just in front, without stripes
        polygonOffset: collider,
        polygonOffsetFactor: collider ? -1 : 0,
        polygonOffsetUnits: collider ? -4 : 0,
      });
    }
    return cache[material.uuid];
  }

  function tag(node) { return (node.userData && node.userData.holomj) || null; }

  function owner(node) {
    for (var n = node; n; n = n.parent) {
      var t = tag(n);
      if (t && (t.kind === 'object' || t.kind === 'door' || t.kind === 'window')) { return n; }
    }
    return null;
  }

  function frame(root) {
    var bounds = new T.Box3();
    root.traverse(function (n) {
      var t = tag(n);
      if (n.isMesh && n.visible && !(t && t.kind === 'ceiling')) { bounds.expandByObject(n); }
    });
    if (bounds.isEmpty()) { bounds.setFromObject(root); }
    var centre = bounds.getCenter(new T.Vector3());
    var extent = bounds.getSize(new T.Vector3());
    var reach = Math.max(extent.x, extent.z, 2 * extent.y, 1.0);
    home = {
      target: centre.clone(),
      position: centre.clone().add(new T.Vector3(0.45 * reach, 0.7 * reach, 0.6 * reach)),
    };
    camera.near = Math.max(0.02, reach / 2000);
    camera.far = reach * 20;
    resetView();
  }

  function resetView() {
    if (!home) { return; }
    camera.position.copy(home.position);
    controls.target.copy(home.target);
    camera.updateProjectionMatrix();
    controls.update();
    draw();
  }

  function visibleIn(node) {
    for (var n = node; n; n = n.parent) { if (!n.visible) { return false; } }
    return true;
  }

  function setLayer(name, on) {
    (layers[name] || []).forEach(function (n) { n.visible = !!on; });
    var box = document.getElementById('layer-' + name);
    if (box) { box.checked = !!on; }
    if (api.selected && objects[api.selected] && !visibleIn(objects[api.selected])) {
      select(null);
    }
    draw();
  }

  function row(label, value) {
    var tr = document.createElement('tr');
    var th = document.createElement('th');
    var td = document.createElement('td');
    th.textContent = label;
    td.textContent = value;
    tr.appendChild(th);
    tr.appendChild(td);
    return tr;
  }

  function describe(id) {
    var node = objects[id];
    var t = node ? tag(node) : null;
    var f = facts[id] || {};
    if (!t && !facts[id]) { return null; }
    var out = {id: id, kind: (t && t.kind) || f.kind || 'object'};
    ['category', 'asset', 'room', 'mass_kg', 'static', 'support', 'stable', 'verdict', 'reasons']
      .forEach(function (k) {
        if (f[k] !== undefined) { out[k] = f[k]; } else if (t && t[k] !== undefined) { out[k] = t[k]; }
      });
    return out;
  }

  function select(id) {
    if (highlight) { scene.remove(highlight); highlight = null; }
    api.selected = null;
    panel.innerHTML = '';
    panel.removeAttribute('data-selected');
    if (id === null || id === undefined || !objects[id]) {
      panel.textContent = 'Click an object to see what it is.';
      draw();
      return null;
    }
    var info = describe(id);
    api.selected = id;
    panel.setAttribute('data-selected', id);
    var title = document.createElement('div');
    title.className = 'viewer-title';
    title.textContent = id;
    panel.appendChild(title);
    var table = document.createElement('table');
    if (info.kind !== 'object') { table.appendChild(row('kind', info.kind)); }
    if (info.category) { table.appendChild(row('category', info.category)); }
    if (info.asset) { table.appendChild(row('asset', info.asset)); }
    if (info.room) { table.appendChild(row('room', info.room)); }
    if (typeof info.mass_kg === 'number') { table.appendChild(row('mass', info.mass_kg.toFixed(2) + ' kg')); }
    if (info.static !== undefined) { table.appendChild(row('simulated', info.static ? 'static' : 'free')); }
    if (info.support) { table.appendChild(row('on', info.support)); }
    if (info.verdict) { table.appendChild(row('stability', info.verdict)); }
    if (info.reasons && info.reasons.length) { table.appendChild(row('why', info.reasons.join('; '))); }
    panel.appendChild(table);
    var bounds = new T.Box3().setFromObject(objects[id]);
    highlight = new T.Box3Helper(bounds, info.stable === false ? 0xd62828 : 0x1d70d6);
    scene.add(highlight);
    draw();
    return info;
  }

  var raycaster = new T.Raycaster();

  function pick(x, y) {
    var rect = renderer.domElement.getBoundingClientRect();
    var ndc = new T.Vector2((x / rect.width) * 2 - 1, -(y / rect.height) * 2 + 1);
    raycaster.setFromCamera(ndc, camera);
    var hits = raycaster.intersectObjects(scene.children, true);
    for (var i = 0; i < hits.length; i++) {
      var o = hits[i].object;
      if (!o.isMesh || !visibleIn(o) || o === highlight) { continue; }
      var t = tag(o);
      if (t && t.kind === 'colliders') { o = o.parent; }
      var n = owner(o);
      if (n) { return tag(n).id; }
    }
    return null;
  }

  function screenPosition(id) {
    var node = objects[id];
    if (!node) { return null; }
    var c = new T.Box3().setFromObject(node).getCenter(new T.Vector3()).project(camera);
    var rect = renderer.domElement.getBoundingClientRect();
    return {x: (c.x + 1) / 2 * rect.width, y: (1 - c.y) / 2 * rect.height};
  }

  function pixelStats() {
    var gl = renderer.getContext();
    var w = gl.drawingBufferWidth;
    var h = gl.drawingBufferHeight;
    var px = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    var bg = [(BACKGROUND >> 16) & 255, (BACKGROUND >> 8) & 255, BACKGROUND & 255];
    var lit = 0;
    var sum = 0;
    var sq = 0;
    for (var i = 0; i < px.length; i += 4) {
      var off = Math.abs(px[i] - bg[0]) + Math.abs(px[i + 1] - bg[1]) + Math.abs(px[i + 2] - bg[2]);
      if (off > 12) { lit++; }
      var v = (px[i] + px[i + 1] + px[i + 2]) / 3;
      sum += v;
      sq += v * v;
    }
    var n = px.length / 4;
    var mean = sum / n;
    return {lit: lit / n, std: Math.sqrt(Math.max(0, sq / n - mean * mean)), width: w, height: h};
  }

  api.select = select;
  api.pick = pick;
  api.screenPosition = screenPosition;
  api.setLayer = setLayer;
  api.pixelStats = pixelStats;
  api.objectIds = function () { return Object.keys(objects).filter(function (k) { return tag(objects[k]).kind === 'object'; }); };
  api.resetView = resetView;
  api.timeFrame = function () {
    var t = performance.now();
    draw();
    var gl = renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    return performance.now() - t;
  };
  api.lookAt = function (position, target) {
    camera.position.set(position[0], position[1], position[2]);
    controls.target.set(target[0], target[1], target[2]);
    controls.update();
    draw();
  };

  var down = null;
  renderer.domElement.addEventListener('pointerdown', function (e) { down = [e.clientX, e.clientY]; });
  renderer.domElement.addEventListener('pointerup', function (e) {
    if (!down || Math.abs(e.clientX - down[0]) + Math.abs(e.clientY - down[1]) > 5) { return; }
    var rect = renderer.domElement.getBoundingClientRect();
    select(pick(e.clientX - rect.left, e.clientY - rect.top));
  });
  controls.addEventListener('change', draw);
  window.addEventListener('resize', function () { size(); draw(); });
  ['colliders', 'ceilings', 'small'].forEach(function (name) {
    var input = document.getElementById('layer-' + name);
    if (input) { input.addEventListener('change', function () { setLayer(name, input.checked); }); }
  });
  var reset = document.getElementById('viewer-reset');
  if (reset) { reset.addEventListener('click', resetView); }

  size();
  say('loading the scene…');
  api.ready = Promise.resolve()
    .then(function () {
      var buffer = decode(document.getElementById('viewer-glb').textContent);
      mark('decoded');
      return new Promise(function (resolve, reject) {
        new T.GLTFLoader().parse(buffer, '', resolve, reject);
      });
    })
    .then(function (gltf) {
      mark('parsed');
      var root = gltf.scene;
      root.traverse(function (n) {
        var t = tag(n);
        if (!t) { return; }
        if (t.kind === 'object' || t.kind === 'door' || t.kind === 'window') { objects[t.id] = n; }
        if (t.kind === 'colliders') { layers.colliders.push(n); n.visible = false; }
        if (t.kind === 'ceiling') { layers.ceilings.push(n); n.visible = false; }
        if (t.kind === 'object' && t.support) { layers.small.push(n); }
      });
      var lights = [];
      var cheap = {};
      root.traverse(function (n) {
        if (n.isLight) { lights.push(n); }
        if (n.isMesh) { n.material = lambert(n.material, cheap); }
      });
      lights.forEach(function (n) { n.parent.remove(n); });
      scene.add(root);
      frame(root);
      // wait for the frame to be drawn (GL queues its work): read one pixel back
      var gl = renderer.getContext();
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
      api.firstFrameMs = Math.round(performance.now());
      document.body.setAttribute('data-viewer', 'ready');
      say('drag to orbit, right-drag to pan, scroll to zoom; click an object');
      select(null);
      return api;
    }, function (err) {
      return fail('cannot read the scene: ' + (err && err.message ? err.message : err));
    });
  api.ready.catch(function () {});
})();
