/* SPDX-License-Identifier: MIT */
/*
 * edaha's take-home page (issue 28, docs/page.md): the tree in this file on the kiosk's
 * paper, turning under the mouse or a finger and swaying in its "wind". The scripts before
 * this one are three.js, its GLTFLoader and its OrbitControls (Debian's libjs-three, r111).
 * What the page says comes from the JSON in #edaha-data and only ever reaches the page as
 * textContent: none of it is markup.
 */
(function () {
	"use strict";
	var root = document.documentElement;
	var data = JSON.parse(document.getElementById("edaha-data").textContent);
	var words = data.words;
	/* the box fills the window but for this margin; the zoom's limits */
	var MARGIN = 1.12, ZOOM = [0.35, 8];
	/* the kiosk's light (ui/render.c's light_dir, in view space) and its terms */
	var LIGHT = [-0.4418339, 0.7069342, 0.5522924], AMBIENT = 0.45, DIRECT = 0.7;

	function show(id, text) {
		var e = document.getElementById(id);

		e.textContent = text;
		e.hidden = !text;
	}

	/* "#" in a pattern is the tree's number; no number: no words */
	function numbered(pattern, n) {
		return n > 0 ? pattern.split("#").join(String(n)) : "";
	}

	/* the page's state for whoever looks at it (tests/export/page.sh): loading, ready,
	 * failed */
	function state(s) {
		root.setAttribute("data-state", s);
	}

	root.lang = data.lang;
	document.title = numbered(words.title, data.number) || words.untitled;
	document.body.style.backgroundColor = "rgb(" + data.paper.join(",") + ")";
	show("number", numbered(words.number, data.number));
	show("date", data.date);
	show("hint", words.hint);
	state("loading");

	function fail(text, e) {
		show("note", text);
		state("failed");
		if (e)
			console.warn("edaha: " + (e && e.message ? e.message : String(e)));
	}

	if (!window.THREE || !THREE.GLTFLoader || !THREE.OrbitControls)
		return fail(words.failed);

	function bytes(b64) {
		var s = atob(b64), a = new Uint8Array(s.length);

		for (var i = 0; i < s.length; i++)
			a[i] = s.charCodeAt(i);
		return a.buffer;
	}

	/*
	 * The screen's colours: each channel c of a material's colour, and of the leaves'
	 * colours a vertex (spring, autumn), shown as c^k, the k of data.tint for its material
	 * ("leaves-autumn" is the leaves'), as the kiosk shows them (ui/leaf_tint.h).
	 */
	function tint_of(name) {
		var t = data.tint || {};

		return t[name] || t[String(name).split("-")[0]] || null;
	}

	function tint_color(c, k) {
		c.r = Math.pow(c.r, k[0]);
		c.g = Math.pow(c.g, k[1]);
		c.b = Math.pow(c.b, k[2]);
	}

	/* COLOR_0 as GLTFLoader gives it: r111 keeps normalised bytes as they are stored */
	function tint_vertices(geometry, k) {
		var a = geometry.attributes.color, most = 1, get, set;

		if (!a || geometry.userData.edahaTinted)
			return;
		if (a.normalized)
			most = a.array instanceof Uint8Array ? 255 : a.array instanceof Uint16Array ? 65535 : 1;
		get = [a.getX, a.getY, a.getZ];
		set = [a.setX, a.setY, a.setZ];
		for (var i = 0; i < a.count; i++)
			for (var c = 0; c < 3; c++) {
				var v = Math.pow(get[c].call(a, i) / most, k[c]) * most;

				set[c].call(a, i, most > 1 ? Math.round(v) : v);
			}
		geometry.userData.edahaTinted = true;
		a.needsUpdate = true;
	}

	/*
	 * The kiosk's look: a colour times 0.45 + 0.7 * the light's Lambert term (ui/gl/
	 * render_shaders.c), the light turning with the camera. three.js's Lambert material
	 * under an ambient light of 0.45 and a directional one of 0.7 computes just that.
	 */
	function kiosk_material(m, geometry) {
		var k = new THREE.MeshLambertMaterial(), t = tint_of(m.name);

		k.name = m.name;
		k.color.copy(m.color);
		if (t) {
			tint_color(k.color, t);
			if (m.vertexColors)
				tint_vertices(geometry, t);
		}
		k.side = m.side;
		k.vertexColors = m.vertexColors;
		k.morphTargets = m.morphTargets;
		k.morphNormals = m.morphNormals;
		return k;
	}

	/* The rest pose's box from the positions alone: r111's computeBoundingBox adds a
	 * quantised morph target's stored integers as if they were metres. */
	function rest_box(scene) {
		var box = new THREE.Box3(), b = new THREE.Box3();

		scene.updateMatrixWorld(true);
		scene.traverse(function (o) {
			if (!o.isMesh)
				return;
			b.setFromBufferAttribute(o.geometry.attributes.position);
			b.applyMatrix4(o.matrixWorld);
			box.union(b);
		});
		return box;
	}

	function start(gltf) {
		var scene = gltf.scene, renderer, camera, controls, mixer = null;
		var clock = new THREE.Clock(), box = rest_box(scene);
		var centre = box.getCenter(new THREE.Vector3()), size = box.getSize(new THREE.Vector3());
		var radius = Math.max(size.length() / 2, 1e-3);

		if (box.isEmpty())
			return fail(words.failed);
		try {
			renderer = new THREE.WebGLRenderer({ antialias: true });
		} catch (e) {
			return fail(words.nogl, e);
		}
		renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
		renderer.setSize(window.innerWidth, window.innerHeight);
		document.body.insertBefore(renderer.domElement, document.body.firstChild);

		scene.background = new THREE.Color(data.paper[0] / 255, data.paper[1] / 255,
						   data.paper[2] / 255);
		scene.traverse(function (o) {
			if (!o.isMesh)
				return;
			o.material = kiosk_material(o.material, o.geometry);
			/* r111's bounds of a morphed mesh are not its own (rest_box): never culled */
			o.frustumCulled = false;
		});
		/* orthographic, as the kiosk's: the tree the visitor turned there, turning the
		 * same way here */
		camera = new THREE.OrthographicCamera(-1, 1, 1, -1, radius / 10, radius * 6);
		scene.add(new THREE.AmbientLight(0xffffff, AMBIENT));
		var sun = new THREE.DirectionalLight(0xffffff, DIRECT);
		sun.position.set(LIGHT[0], LIGHT[1], LIGHT[2]);
		camera.add(sun);
		camera.add(sun.target); /* at the camera: the light turns with it */
		scene.add(camera);

		/* The front view, as on the kiosk: from +z, the tree's box filling the window
		 * but for a margin. */
		function frame() {
			var a = window.innerWidth / Math.max(window.innerHeight, 1);
			var h = MARGIN * Math.max(size.y / 2, size.x / 2 / a, 1e-3);

			camera.left = -h * a;
			camera.right = h * a;
			camera.top = h;
			camera.bottom = -h;
			camera.updateProjectionMatrix();
		}
		function front() {
			camera.zoom = 1;
			camera.position.set(centre.x, centre.y, centre.z + 3 * radius);
			frame();
		}
		front();
		/* Turning about the box's middle, no panning, so the tree cannot be lost; from a
		 * third of its size to eight times it; from no lower under the ground nor higher
		 * above it than the kiosk lets the pen go (its pitch limits, src/core/camera.h). */
		controls = new THREE.OrbitControls(camera, renderer.domElement);
		controls.target.copy(centre);
		controls.enablePan = false;
		controls.enableKeys = false;
		controls.enableDamping = true;
		controls.dampingFactor = 0.12;
		controls.rotateSpeed = 0.7;
		controls.minZoom = ZOOM[0];
		controls.maxZoom = ZOOM[1];
		controls.minPolarAngle = (90 - data.pitch[1]) * Math.PI / 180;
		controls.maxPolarAngle = (90 - data.pitch[0]) * Math.PI / 180;
		controls.update();

		var clip = THREE.AnimationClip.findByName(gltf.animations, "wind");
		if (clip) {
			mixer = new THREE.AnimationMixer(scene);
			mixer.clipAction(clip).play();
		}

		window.addEventListener("resize", function () {
			renderer.setSize(window.innerWidth, window.innerHeight);
			frame();
		});

		/*
		 * For tests (tests/export/page.sh), not reachable from the page's data: where the
		 * camera is and how far the wind has played; and the tree at rest in the front
		 * view, as the kiosk's headless run shows it.
		 */
		var frames = 0, still = false;
		window.edahaView = function () {
			return { azimuth: controls.getAzimuthalAngle(), polar: controls.getPolarAngle(),
				 zoom: camera.zoom, time: mixer ? mixer.time : 0, frames: frames };
		};
		window.edahaStill = function () {
			still = true;
			scene.traverse(function (o) {
				if (o.morphTargetInfluences)
					for (var i = 0; i < o.morphTargetInfluences.length; i++)
						o.morphTargetInfluences[i] = 0;
			});
			/* a turn still easing out ends now (damping off: the rest at once), then
			 * the front again */
			controls.enableDamping = false;
			controls.update();
			front();
			controls.update();
			controls.enableDamping = true;
		};

		function tick() {
			requestAnimationFrame(tick);
			if (mixer && !still)
				mixer.update(Math.min(clock.getDelta(), 0.1));
			controls.update();
			renderer.render(scene, camera);
			if (++frames === 1)
				state("ready");
		}
		tick();
	}

	try {
		new THREE.GLTFLoader().parse(bytes(document.getElementById("edaha-model").textContent),
					     "", start, function (e) { fail(words.failed, e); });
	} catch (e) {
		fail(words.failed, e);
	}
})();
