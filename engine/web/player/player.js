// The Artificial Person web player (docs/web-export.md).
//
//   const player = new ArtificialPerson(canvas);
//   await player.load("animation.json");       // the model, the frame table, the audio
//   await player.play();  player.pause();  player.seek(1200);
//   player.addEventListener("word", (e) => console.log(e.detail.word, e.detail.t));
//
// The canvas takes the size the page gives it (CSS: `width: 100%; height: 100%` fills its container) and the
// head is framed in it as `render --view front` frames a picture of that size, again whenever it is resized.
// Events (CustomEvent, detail.t = performance.now() when the player saw it):
//   ready, play, pause, seek, word {word, start_ms, end_ms}, ended, resize {width, height}.
// The clock is the audio's (AudioContext.currentTime, less the output latency) once the sound runs; before
// that, performance.now() since play().
//
// This is the source: sites get engine/web/dist/player.js, this file and the three.js it imports bundled
// into one ES module (engine/web/player_bundle.py), so that a page needs no import map.

import * as THREE from "../vendor/three/build/three.module.min.js";
import { GLTFLoader } from "../vendor/three/examples/jsm/loaders/GLTFLoader.js";

THREE.ColorManagement.enabled = false;   // light colours as they are written, as the engine's renderer does

function linearToSrgb(c) {
  return c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055;
}

// The shading of a physically based look: the engine's own GLSL (engine/outputs/look_shader.py), put in
// here when the site is written (the marker string is replaced by the GLSL as a JSON string), so the browser
// computes every pixel with the renderer's formulas.
const LOOK_SHADER = "{{LOOK_SHADER}}";

// A glTF colour (linear light, from sRGB by the exact curve) as VTK's physically based shading takes the
// same colour: the stored sRGB value to the power 2.2.
function vtkLinear(c) {
  return Math.pow(Math.min(Math.max(linearToSrgb(c), 0), 1), 2.2);
}

export class ArtificialPerson extends EventTarget {
  /** ``options.pixelRatio``: drawing-buffer pixels per CSS pixel (default the screen's, at most 2). */
  constructor(canvas, options = {}) {
    super();
    this.canvas = canvas;
    this.pixelRatio = options.pixelRatio || Math.min(window.devicePixelRatio || 1, 2);
    this.size = null;             // {width, height}: the canvas's CSS size the camera is framed for
    this.position = 0;            // ms on the animation's clock
    this.playing = false;
    this.ready = false;
    this.framesDrawn = 0;
    this.timings = [];            // per frame while playing: performance.now(), position drawn, position heard
    this._waiters = [];
    this._readyWaiters = [];
  }

  /** Load a site's animation JSON (and the model and audio it names); resolves when the first frame is drawn. */
  async load(url = "animation.json") {
    const base = new URL(url, location.href);
    const response = await fetch(base);
    if (!response.ok) throw new Error(`cannot load ${url}: ${response.status}`);
    const animation = await response.json();
    this.animation = animation;
    this.duration = animation.duration_ms;
    this._setUpScene(animation);
    const gltf = await new GLTFLoader().loadAsync(new URL(animation.model, base).href);
    this._setUpModel(gltf, animation);
    this.audioContext = new AudioContext();
    const audio = await fetch(new URL(animation.audio, base));
    this.audioBuffer = await this.audioContext.decodeAudioData(await audio.arrayBuffer());
    this._apply(0);
    this._tick = this._tick.bind(this);
    this._frameRequest = requestAnimationFrame(this._tick);
    await this.nextFrame();
    this.ready = true;
    this._readyWaiters.splice(0).forEach((resolve) => resolve());
    this._emit("ready", {});
    return this;
  }

  /** Resolves once the player is loaded and has drawn its first frame. */
  whenReady() {
    return this.ready ? Promise.resolve() : new Promise((resolve) => this._readyWaiters.push(resolve));
  }

  /** Resolves after the next frame is drawn. */
  nextFrame() {
    return new Promise((resolve) => this._waiters.push(resolve));
  }

  /** Play from the current position; resolves true when the sound runs, false when the browser holds it. */
  async play() {
    if (this.playing) return true;
    if (this.position >= this.duration) this.position = 0;
    this.playing = true;
    this._from = this.position;
    this._wallStart = performance.now();
    this._lastEvent = this.position - 1e-6;
    this._source = null;
    this._emit("play", { at_ms: this.position });
    try {
      await Promise.race([this.audioContext.resume(), new Promise((r) => setTimeout(r, 300))]);
    } catch (error) { /* no sound: the animation runs on performance.now() */ }
    if (!this.playing || this.audioContext.state !== "running") return this.audioContext.state === "running";
    const source = this.audioContext.createBufferSource();
    source.buffer = this.audioBuffer;
    source.connect(this.audioContext.destination);
    const lead = 0.05;                         // s: the sound starts this long after start() is called
    this._audioWhen = this.audioContext.currentTime + lead;
    this._audioFrom = this.position;           // the sound starts where the picture is now, which waits for it
    this._from = this.position;
    this._wallStart = performance.now() + lead * 1000;
    if (this._audioFrom < this.audioBuffer.duration * 1000) {
      source.start(this._audioWhen, this._audioFrom / 1000);
      this._source = source;
    }
    return true;
  }

  pause() {
    if (!this.playing) return;
    this._stopSound();
    this.playing = false;
    this._emit("pause", { at_ms: this.position });
  }

  /** Show the frame at ``ms`` (the player keeps playing from there if it was playing). */
  seek(ms) {
    const playing = this.playing;
    if (playing) this.pause();
    this.position = Math.min(Math.max(Number(ms) || 0, 0), this.duration);
    this._apply(this.position);
    this._emit("seek", { at_ms: this.position });
    if (playing) this.play();
  }

  /** Frames drawn since load and how long the player has run (ms): the frame rate it holds. */
  stats() {
    return { frames: this.framesDrawn, since_ms: performance.now() - this._firstFrameAt };
  }

  // -- the clock -----------------------------------------------------------------------------

  /** Where the sound being heard now is, on the animation's clock (ms); null before the sound runs. */
  heardPosition() {
    const context = this.audioContext;
    if (!this._source || context.state !== "running") return null;
    const stamp = context.getOutputTimestamp ? context.getOutputTimestamp() : {};
    let heard;
    if (stamp.contextTime > 0 && stamp.performanceTime > 0) {
      // the context time at the speaker now: the output's last stamp, carried forward on performance.now()
      heard = stamp.contextTime + (performance.now() - stamp.performanceTime) / 1000;
    } else {
      heard = context.currentTime - (context.outputLatency || 0);
    }
    return heard >= this._audioWhen ? this._audioFrom + (heard - this._audioWhen) * 1000 : null;
  }

  _clock() {
    const heard = this.heardPosition();
    return heard !== null ? heard : this._from + (performance.now() - this._wallStart);
  }

  /** Stop for good: the sound, the frame loop, the audio context and the GL context (a page that shows
   * stimulus after stimulus makes a player for each and disposes of the last). */
  dispose() {
    this.pause();
    this.disposed = true;
    if (this._frameRequest !== undefined) cancelAnimationFrame(this._frameRequest);
    if (this._observer) this._observer.disconnect();
    if (this.audioContext) this.audioContext.close().catch(() => {});
    if (this.renderer) {
      this.renderer.dispose();
      this.renderer.forceContextLoss();
    }
  }

  _tick() {
    if (this.disposed) return;
    this._frameRequest = requestAnimationFrame(this._tick);
    if (this.playing) {
      const position = Math.max(this._clock(), this.position);   // never backwards
      this.position = Math.min(position, this.duration);
      this._apply(this.position);
      const heard = this.heardPosition();
      if (this.timings.length < 100000) this.timings.push({ t: performance.now(), drawn_ms: this.position, heard_ms: heard });
      this._wordEvents(this.position);
      if (this.position >= this.duration) {
        this._stopSound();
        this.playing = false;
        this._emit("ended", { at_ms: this.position });
      }
    }
    this.renderer.render(this.scene, this.camera);
    if (this.framesDrawn === 0) this._firstFrameAt = performance.now();
    this.framesDrawn += 1;
    this._waiters.splice(0).forEach((resolve) => resolve());
  }

  _wordEvents(position) {
    for (const word of this.animation.words) {
      if (word.start_ms > this._lastEvent && word.start_ms <= position) this._emit("word", { ...word });
    }
    this._lastEvent = position;
  }

  _stopSound() {
    if (this._source) {
      try { this._source.stop(); } catch (error) { /* never started */ }
      this._source.disconnect();
      this._source = null;
    }
  }

  _emit(type, detail) {
    this.dispatchEvent(new CustomEvent(type, { detail: { ...detail, t: performance.now() } }));
  }

  // -- the scene -----------------------------------------------------------------------------

  _setUpScene(animation) {
    const c = animation.camera;
    this.renderer = new THREE.WebGLRenderer({ canvas: this.canvas, antialias: true, alpha: true });
    this.renderer.setPixelRatio(this.pixelRatio);
    this.renderer.outputColorSpace = THREE.LinearSRGBColorSpace;
    this.renderer.setClearColor(0x000000, 0);
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(c.fov_degrees, c.width / c.height, c.near, c.far);
    this.camera.up.fromArray(c.up);
    this.scene.add(this.camera);
    this._fitCanvas(c);
    const background = animation.background;
    if (background) this.canvas.style.background = `linear-gradient(to top, ${background.bottom}, ${background.top})`;
    if (animation.look) return;     // a physically based look: its lights are the shader's uniforms
    // The engine's key, fill and rim lights ride with the camera, aimed at what it looks at (a directional
    // light's direction is all that counts, so they stay right when the camera moves in or out).
    const aim = new THREE.Object3D();
    const distance = new THREE.Vector3().fromArray(c.position).distanceTo(new THREE.Vector3().fromArray(c.target));
    aim.position.set(0, 0, -distance);
    this.camera.add(aim);
    for (const light of animation.lights) {
      const directional = new THREE.DirectionalLight(0xffffff, light.intensity * Math.PI);
      const [x, y, z] = light.camera_position;
      directional.position.set(x * distance, y * distance, z * distance - distance);
      directional.target = aim;
      this.camera.add(directional);
    }
    this.scene.add(new THREE.AmbientLight(0xffffff, Math.PI));
  }

  // -- the canvas's size and the framing -------------------------------------------------------

  /** Size the drawing buffer to the canvas's size on the page, frame the head for it, and again on resize. */
  _fitCanvas(c) {
    const canvas = this.canvas;
    if (!canvas.hasAttribute("width") && !canvas.hasAttribute("height")) {
      canvas.width = c.width;               // the site's size (--size) where the page sets none
      canvas.height = c.height;
    }
    // A canvas the page gives no size takes it from its own width and height: pin it there, so that the
    // drawing buffer (pixelRatio × the CSS size) does not make it grow.
    const before = this._cssSize();
    const [width, height] = [canvas.width, canvas.height];
    canvas.width = width * 2;
    canvas.height = height * 2;
    const grows = before !== null && this._cssSize() !== null && this._cssSize().width !== before.width;
    canvas.width = width;
    canvas.height = height;
    if (grows) {
      canvas.style.width = `${before.width}px`;
      canvas.style.height = `${before.height}px`;
    }
    const size = this._cssSize() || { width: c.width, height: c.height };
    this._resize(size.width, size.height);
    if (typeof ResizeObserver === "function") {
      this._observer = new ResizeObserver((entries) => {
        const box = entries[entries.length - 1].contentRect;
        if (box.width > 0 && box.height > 0 && !this.disposed) {
          this._resize(box.width, box.height);
          this.renderer.render(this.scene, this.camera);     // at once: no frame of the old size is shown
        }
      });
      this._observer.observe(canvas);
    }
  }

  /** The canvas's content box in CSS pixels (null while it is not laid out). */
  _cssSize() {
    const style = getComputedStyle(this.canvas);
    const width = parseFloat(style.width), height = parseFloat(style.height);
    return width > 0 && height > 0 ? { width, height } : null;
  }

  _resize(width, height) {
    if (this.size && this.size.width === width && this.size.height === height) return;
    this.size = { width, height };
    this.renderer.setSize(width, height, false);
    this._frame(width, height);
    this._emit("resize", { width, height });
  }

  /** Aim the camera as `render --view` does for a width × height picture (engine/web/web_camera.py): on the
   * view's axis, as far from the focal point as the framed head needs to fit, across and up, with the margin. */
  _frame(width, height) {
    const c = this.animation.camera, f = c.framing;
    const target = new THREE.Vector3().fromArray(c.target);
    const back = new THREE.Vector3().fromArray(c.position).sub(target);
    let distance = back.length(), near = c.near, far = c.far;
    if (f) {
      const tanX = f.tan_half_height * width / height;
      distance = Math.max(f.distance_up, 0.001, ...f.sides.map(([a, b]) => b + a / tanX));
      near = Math.max(distance - f.in_front - 0.01, distance * 0.01);
      far = distance + f.behind + 0.01;
    }
    this.camera.position.copy(target).addScaledVector(back.normalize(), distance);
    this.camera.lookAt(target);
    this.camera.aspect = width / height;
    this.camera.near = near;
    this.camera.far = far;
    this.camera.updateProjectionMatrix();
  }

  _setUpModel(gltf, animation) {
    this.scene.add(gltf.scene);
    this.morphMeshes = [];
    this.joints = {};
    gltf.scene.traverse((object) => {
      if (object.isBone && object.userData.parameter) {
        this.joints[object.userData.parameter] = {
          bone: object, extras: object.userData,
          rotation: object.quaternion.clone(), translation: object.position.clone(),
        };
      }
      if (object.isMesh) {
        object.frustumCulled = false;
        object.material = this._material(object, animation.parts || {});
        if (object.morphTargetDictionary) this.morphMeshes.push(object);
      }
    });
  }

  _material(mesh, parts) {
    if (this.animation.look) return this._lookMaterial(mesh, this.animation.look);
    const original = mesh.material;
    const part = parts[(original.name || "").split(".")[0]] || { ambient: 0.18, diffuse: 0.85, specular: 0.12, power: 12 };
    const colour = original.color.clone();
    colour.setRGB(linearToSrgb(colour.r), linearToSrgb(colour.g), linearToSrgb(colour.b));
    const colours = mesh.geometry.getAttribute("color");
    if (colours) {
      for (let i = 0; i < colours.count; i++) {
        colours.setXYZ(i, linearToSrgb(colours.getX(i)), linearToSrgb(colours.getY(i)), linearToSrgb(colours.getZ(i)));
      }
      colours.needsUpdate = true;
    }
    if (original.map) original.map.colorSpace = THREE.NoColorSpace;
    // VTK's Phong highlight ks·(R·V)^p, as three.js's normalised Blinn–Phong draws it: the exponent on
    // N·H is about four times that on R·V, and three.js scales its highlight by (shininess + 2) / 8.
    const shininess = 4 * part.power;
    const specular = part.specular * 8 / (shininess + 2);
    const material = new THREE.MeshPhongMaterial({
      color: colour.multiplyScalar(part.diffuse), map: original.map || null, vertexColors: Boolean(colours),
      specular: new THREE.Color(specular, specular, specular), shininess, side: THREE.DoubleSide,
    });
    // ambient light: the part's ambient share of its own colour, as the engine's renderer lights it
    material.onBeforeCompile = (shader) => {
      shader.uniforms.ambientShare = { value: part.ambient / Math.max(part.diffuse, 1e-6) };
      shader.fragmentShader = "uniform float ambientShare;\n" + shader.fragmentShader.replace(
        "#include <lights_fragment_begin>",
        "#include <lights_fragment_begin>\n irradiance *= ambientShare;");
    };
    return material;
  }

  /** A material drawn by the look's shader: three.js poses, skins and textures the mesh, the engine's GLSL
   * lights it (the same uniforms, the same baked occlusion, the colours made linear as VTK makes them). */
  _lookMaterial(mesh, look) {
    const original = mesh.material;
    const part = (original.name || "").split(".")[0];
    const values = { ...look.uniforms, ...(look.materials[part] || look.materials[Object.keys(look.materials)[0]]) };
    const colour = original.color.clone();
    colour.setRGB(vtkLinear(colour.r), vtkLinear(colour.g), vtkLinear(colour.b));
    const colours = mesh.geometry.getAttribute("color");
    if (colours) {
      for (let i = 0; i < colours.count; i++) {
        colours.setXYZ(i, vtkLinear(colours.getX(i)), vtkLinear(colours.getY(i)), vtkLinear(colours.getZ(i)));
      }
      colours.needsUpdate = true;
    }
    if (original.map) original.map.colorSpace = THREE.SRGBColorSpace;   // decoded to linear, as VTK does
    const material = new THREE.MeshStandardMaterial({
      color: colour, map: original.map || null, vertexColors: Boolean(colours), side: THREE.DoubleSide,
    });
    const lights = look.settings.lights.length;
    material.onBeforeCompile = (shader) => {
      for (const [name, value] of Object.entries(values)) {
        shader.uniforms[name] = { value: Array.isArray(value) ? new THREE.Vector3().fromArray(value) : value };
      }
      shader.vertexShader = shader.vertexShader
        .replace("void main() {", "attribute float _occlusion;\nvarying float vLookOcclusion;\nvoid main() {")
        .replace("#include <begin_vertex>", "#include <begin_vertex>\n\tvLookOcclusion = _occlusion;");
      shader.fragmentShader = shader.fragmentShader
        .replace("void main() {", `varying float vLookOcclusion;\n#define LOOK_LIGHTS ${lights}\n${LOOK_SHADER}\nvoid main() {`)
        .replace("#include <lights_physical_fragment>", "")
        .replace("#include <lights_fragment_begin>", "")
        .replace("#include <lights_fragment_maps>", "")
        .replace("#include <lights_fragment_end>", "")
        .replace("#include <opaque_fragment>",
          "gl_FragColor = vec4(lookShade(diffuseColor.rgb, normal, normalize(vViewPosition), vLookOcclusion), diffuseColor.a);");
    };
    material.customProgramCacheKey = () => `look:${lights}`;
    return material;
  }

  /** Pose the head at ``ms``: every channel interpolated linearly between its frames. */
  _apply(ms) {
    const a = this.animation;
    const f = Math.min(Math.max(ms / a.frame_ms, 0), Math.max(a.frames - 1, 0));
    const i = Math.floor(f), j = Math.min(i + 1, a.frames - 1), w = f - i;
    for (const channel of a.channels) {
      const q = channel.values[i] * (1 - w) + channel.values[j] * w;
      const value = channel.default + channel.step * q;
      if (channel.kind === "morph") {
        const weight = (value - channel.default) / (channel.target_value - channel.default);
        for (const mesh of this.morphMeshes) {
          const k = mesh.morphTargetDictionary[channel.parameter];
          if (k !== undefined) mesh.morphTargetInfluences[k] = weight;
        }
      } else {
        this._moveJoint(channel.parameter, value);
      }
    }
  }

  _moveJoint(name, value) {
    const joint = this.joints[name];
    if (!joint) return;
    const x = new THREE.Vector3(1, 0, 0);
    if (joint.extras.degrees_per_unit !== undefined) {
      const turn = new THREE.Quaternion().setFromAxisAngle(x, THREE.MathUtils.degToRad(value * joint.extras.degrees_per_unit));
      joint.bone.quaternion.copy(joint.rotation).multiply(turn);
    } else {
      const along = x.applyQuaternion(joint.rotation).multiplyScalar(value * joint.extras.mm_per_unit / 1000);
      joint.bone.position.copy(joint.translation).add(along);
    }
  }
}
