// jsPsych plugins of an Artificial Person rating study (docs/study.md), for jsPsych 7 and 8, classic script:
//
//   jsPsychApStudyTrial  one face (a still, a video, or the live web player) and the questions about it:
//                        the emotion (forced choice, keys and buttons) and ratings on scales (keys and buttons)
//   jsPsychApPage        a page of HTML with buttons, each with an optional key (consent, instructions)
//   jsPsychApTask        runs a function of the experiment's (preloading, saving) with a message on the page
//
// Times named `..._t` are performance.now() of the page, in ms. `rt` is on the player's clock: for a still,
// from the frame it was first drawn in; for a video, the clip's own clock (the frame presented and how long
// since: 0 = the clip's first frame and sample); for the live player, the sound being heard (as
// plugin-artificial-person.js). The rows' columns are listed in study.json ("columns").

var jsPsychApStudyTrial = (function (jspsych) {
  "use strict";
  const { ParameterType } = jspsych;

  const info = {
    name: "ap-study-trial",
    version: "1.0.0",
    parameters: {
      /** The trial: {stimulus, source, presentation, media, file, intended, levels, clock} from study.json. */
      spec: { type: ParameterType.COMPLEX, default: undefined },
      phase: { type: ParameterType.STRING, default: "test" },
      block: { type: ParameterType.STRING, default: "" },
      /** Attention checks: the answer asked for (a choice's value, or a scale point). */
      expected: { type: ParameterType.STRING, default: null },
      /** "identification" and/or "rating", in order. */
      tasks: { type: ParameterType.COMPLEX, default: ["identification"] },
      choices: { type: ParameterType.COMPLEX, default: [] },
      question: { type: ParameterType.HTML_STRING, default: "Which emotion does the face show?" },
      buttons: { type: ParameterType.BOOL, default: true },
      scales: { type: ParameterType.COMPLEX, default: [] },
      /** ms a still stays on the screen (0: until the last answer). */
      static_ms: { type: ParameterType.INT, default: 0 },
      /** The face's width on the page, CSS pixels (null: the file's own). */
      width: { type: ParameterType.INT, default: null },
      /** The folder of the web-export site the live player comes from. */
      live_site: { type: ParameterType.STRING, default: "live/" },
      /** Where the files are (the study's folder; "" on hosts that keep files flat). */
      base: { type: ParameterType.STRING, default: "" },
      /** Object URLs of files already loaded (file → URL). */
      media_cache: { type: ParameterType.COMPLEX, default: {} },
      /** The column each factor level goes into ({factor: column}). */
      level_columns: { type: ParameterType.COMPLEX, default: {} },
    },
  };

  const listings = new Map();
  const modules = new Map();
  let asks = 0;

  function rafTime() {
    return new Promise((resolve) => requestAnimationFrame((t) => resolve(t)));
  }

  function esc(text) {
    return String(text).replace(/[&<>"]/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;" })[c]);
  }

  function number(value) {
    return value === undefined || value === null || value === "" ? null : Number(value);
  }

  /** A still: decoded before it is shown; its onset the frame it is first drawn in. */
  async function showImage(stage, src, width) {
    const img = new Image();
    img.src = src;
    img.alt = "face";
    await img.decode();
    if (width) img.style.width = `${width}px`;
    img.className = "ap-face";
    stage.appendChild(img);
    const onset = await rafTime();
    return {
      kind: "image", element: img, onset_t: onset,
      clockAt: (t) => t - onset,
      release: () => { img.remove(); },
      times: () => ({}),
    };
  }

  /** A video: the clip's clock from the frames the browser presents (requestVideoFrameCallback). */
  async function showVideo(stage, src, width, clock, words) {
    const video = document.createElement("video");
    video.className = "ap-face";
    video.playsInline = true;
    video.preload = "auto";
    video.src = src;
    if (width) video.style.width = `${width}px`;
    stage.appendChild(video);
    await new Promise((resolve, reject) => {
      if (video.readyState >= 3) return resolve();
      video.addEventListener("canplay", resolve, { once: true });
      video.addEventListener("error", () => reject(new Error(`cannot play ${src}`)), { once: true });
    });
    const frames = [];
    let ended_t = null, stopped = false, firstFrame = null;
    const presented = new Promise((resolve) => { firstFrame = resolve; });
    const onFrame = (now, meta) => {
      frames.push({ t: meta.presentationTime, media_ms: meta.mediaTime * 1000 });
      if (frames.length === 1) firstFrame();
      if (!stopped) video.requestVideoFrameCallback(onFrame);
    };
    video.requestVideoFrameCallback(onFrame);
    video.addEventListener("ended", () => { ended_t = performance.now(); stage.dataset.ended = "1"; }, { once: true });
    const play_t = performance.now();
    try {
      await video.play();
    } catch (error) {              // no gesture yet on this page: a click starts it (within the gesture)
      await clickToStart(stage, () => video.play());
    }
    await presented;
    const zeros = () => frames.map((f) => f.t - f.media_ms);
    return {
      kind: "video", element: video, onset_t: frames[0].t, play_t,
      clockAt: (t) => {
        let last = frames[0];
        for (const f of frames) if (f.t <= t) last = f;
        return last.media_ms + (t - last.t);
      },
      release: () => {
        stopped = true;
        video.pause();
        video.removeAttribute("src");
        video.load();
        video.remove();
      },
      times: () => {
        const z = zeros();
        const zero = z.length ? z[0] : null;
        const quality = video.getVideoPlaybackQuality ? video.getVideoPlaybackQuality() : null;
        return {
          play_t, clip_start_t: zero, first_frame_t: frames.length ? frames[0].t : null, ended_t,
          frames: frames.length, dropped_frames: quality ? quality.droppedVideoFrames : null,
          sound: !video.muted, clock_spread_ms: z.length ? Math.max(...z) - Math.min(...z) : null,
          ...clipTimes(zero, clock),
          word_onsets: JSON.stringify((words || []).map((w) => ({ word: w.word, start_ms: w.start_ms,
                                                                  t: zero === null ? null : zero + w.start_ms }))),
        };
      },
    };
  }

  /** The live web player (engine/web/player) on a canvas, its clock the sound being heard. */
  async function showLive(stage, site, id, width, clock) {
    const base = new URL(site, document.baseURI);
    if (!listings.has(base.href)) {
      listings.set(base.href, fetch(new URL("stimuli.json", base)).then((r) => {
        if (!r.ok) throw new Error(`cannot load ${r.url}: ${r.status}`);
        return r.json();
      }));
      modules.set(base.href, import(new URL("player.js", base).href));
    }
    const [{ ArtificialPerson }, listing] = await Promise.all([modules.get(base.href), listings.get(base.href)]);
    const listed = listing.stimuli.find((s) => s.id === String(id));
    if (!listed) throw new Error(`no stimulus '${id}' in ${new URL("stimuli.json", base)}`);
    const canvas = document.createElement("canvas");
    canvas.className = "ap-face";
    canvas.setAttribute("aria-label", "talking head");
    if (width) canvas.style.width = `${width}px`;
    stage.appendChild(canvas);
    const player = new ArtificialPerson(canvas);
    const seen = { play_t: null, ended_t: null, words: [] };
    player.addEventListener("play", (e) => { if (seen.play_t === null) seen.play_t = e.detail.t; });
    player.addEventListener("word", (e) => {
      seen.words.push({ word: e.detail.word, start_ms: e.detail.start_ms, t: e.detail.t });
      stage.dataset.words = String(seen.words.length);
    });
    player.addEventListener("ended", (e) => { seen.ended_t = e.detail.t; stage.dataset.ended = "1"; });
    await player.load(new URL(listed.animation, base).href);
    const context = player.audioContext;
    if (context.state !== "running") {
      await Promise.race([context.resume().catch(() => {}), new Promise((r) => setTimeout(r, 300))]);
      if (context.state !== "running") await clickToStart(stage, () => context.resume());
    }
    const sounding = await player.play();
    const zeros = () => {
      const heard = player.timings.filter((f) => f.heard_ms !== null).map((f) => f.t - f.heard_ms);
      return heard.length ? heard : player.timings.map((f) => f.t - f.drawn_ms);
    };
    const onset = performance.now();
    return {
      kind: "live", element: canvas, onset_t: onset,
      clockAt: (t) => {
        const heard = player.heardPosition();
        if (heard !== null) return heard - (performance.now() - t);
        const last = player.timings[player.timings.length - 1];
        return last ? (last.heard_ms !== null ? last.heard_ms : last.drawn_ms) + (t - last.t) : null;
      },
      release: () => { player.dispose(); canvas.remove(); },
      times: () => {
        const z = zeros();
        const zero = z.length ? z[0] : null;
        return {
          play_t: seen.play_t, clip_start_t: zero, first_frame_t: player.timings.length ? player.timings[0].t : null,
          ended_t: seen.ended_t, frames: player.timings.length, dropped_frames: null,
          sound: sounding && context.state === "running",
          clock_spread_ms: z.length ? Math.max(...z) - Math.min(...z) : null,
          ...clipTimes(zero, clock), word_onsets: JSON.stringify(seen.words),
        };
      },
    };
  }

  function clipTimes(zero, clock) {
    const at = (ms) => (zero === null || ms === null || ms === undefined ? null : zero + ms);
    return {
      audio_start_t: at(number(clock.audio_start_ms)), face_start_t: at(number(clock.video_start_ms)),
      speech_onset_t: at(number(clock.speech_onset_ms)),
    };
  }

  function clickToStart(stage, start) {
    const button = document.createElement("button");
    button.className = "jspsych-btn ap-start";
    button.textContent = "Click to start";
    stage.appendChild(button);
    stage.dataset.state = "waiting";
    return new Promise((resolve) => button.addEventListener("click", () => {
      Promise.resolve(start()).catch(() => {}).then(resolve);
      button.remove();
    }, { once: true }));
  }

  class ApStudyTrialPlugin {
    constructor(jsPsych) {
      this.jsPsych = jsPsych;
    }

    trial(display_element, trial) {
      this._run(display_element, trial).catch((error) => {
        const message = String((error && error.message) || error);
        console.error(`ap-study: stimulus ${trial.spec && trial.spec.stimulus}: ${message}`);
        display_element.innerHTML = `<p class="ap-error">The face could not be shown (${esc(message)}).</p>`;
        this.jsPsych.finishTrial({ ap_row: "trial", stimulus: trial.spec && trial.spec.stimulus, error: message });
      });
    }

    async _run(display_element, trial) {
      const spec = trial.spec;
      display_element.innerHTML =
        `<div class="ap-trial"><div id="ap-stage" data-state="loading" data-stimulus="${esc(spec.stimulus)}" ` +
        `data-presentation="${esc(spec.presentation)}" data-phase="${esc(trial.phase)}"></div>` +
        `<div id="ap-question" data-task=""></div></div>`;
      const stage = display_element.querySelector("#ap-stage");
      const area = display_element.querySelector("#ap-question");
      const src = trial.media_cache[spec.file] || `${trial.base}${spec.file}`;
      let shown;
      if (spec.media === "image") shown = await showImage(stage, src, trial.width);
      else if (spec.media === "video") shown = await showVideo(stage, src, trial.width, spec.clock || {}, spec.words);
      else shown = await showLive(stage, trial.live_site, spec.file, trial.width, spec.clock || {});
      stage.dataset.state = "showing";
      let hidden = null;
      if (spec.media === "image" && trial.static_ms > 0) {
        const hide = (t) => {
          if (hidden !== null) return;
          if (t - shown.onset_t >= trial.static_ms) {
            shown.element.style.visibility = "hidden";
            hidden = t;
            stage.dataset.state = "hidden";
          } else requestAnimationFrame(hide);
        };
        requestAnimationFrame(hide);
      }
      const data = {
        ap_row: "trial", phase: trial.phase, block: trial.block, stimulus: spec.stimulus, source: spec.source,
        presentation: spec.presentation, media: spec.media, file: spec.file, intended: spec.intended,
        expected: trial.expected, onset_t: shown.onset_t,
        duration_ms: number((spec.clock || {}).duration_ms), audio_start_ms: number((spec.clock || {}).audio_start_ms),
        video_start_ms: number((spec.clock || {}).video_start_ms),
        speech_onset_ms: number((spec.clock || {}).speech_onset_ms),
      };
      for (const [name, value] of Object.entries(spec.levels || {})) data[trial.level_columns[name] || name] = value;
      const attention = trial.expected !== null && trial.expected !== undefined;
      let tasks = trial.tasks;
      if (attention) tasks = tasks.includes("identification") ? ["identification"] : ["rating"];
      for (const task of tasks) {
        if (task === "identification") {
          const answer = await this._ask(area, "identification", trial.question, trial.choices, trial.buttons,
                                         attention ? trial.choices.find((c) => c.value === trial.expected) : null);
          data.response = answer.value;
          data.response_key = answer.key;
          data.response_method = answer.method;
          data.response_t = answer.t;
          data.rt = shown.clockAt(answer.t);
          data.correct = attention ? answer.value === trial.expected : answer.value === spec.intended;
        } else {
          const scales = attention ? trial.scales.slice(0, 1) : trial.scales;
          for (const scale of scales) {
            const points = [];
            for (let v = scale.min; v <= scale.max; v += 1) {
              points.push({ value: String(v), label: String(v), key: scale.keys[v - scale.min] || null });
            }
            const asked = attention ? points.find((p) => p.value === String(trial.expected)) : null;
            const answer = await this._ask(area, `rating:${scale.name}`, scale.question, points, true, asked,
                                           scale.anchors);
            data[`rating_${scale.name}`] = Number(answer.value);
            data[`rating_${scale.name}_rt`] = answer.t - answer.shown_t;
            data[`rating_${scale.name}_method`] = answer.method;
            if (attention && !tasks.includes("identification")) {
              data.response = answer.value;
              data.response_t = answer.t;
              data.rt = shown.clockAt(answer.t);
              data.correct = answer.value === String(trial.expected);
            }
          }
        }
      }
      Object.assign(data, shown.times());
      if (hidden !== null) data.offset_t = hidden;
      shown.release();
      display_element.innerHTML = "";
      this.jsPsych.finishTrial(data);
    }

    /** One question: buttons (and keys); resolves with the answer and when it came. */
    _ask(area, task, question, options, buttons, asked, anchors) {
      const keyed = options.filter((o) => o.key);
      const scale = task.startsWith("rating:");
      area.dataset.task = task;
      asks += 1;
      area.dataset.ask = String(asks);
      area.dataset.expected = asked ? asked.value : "";
      const ask = asked ? `<p class="ap-attention">To show that you are reading this, please choose <b>` +
        `${esc(asked.label)}</b>${asked.key ? ` (key ${esc(asked.key.toUpperCase())})` : ""}.</p>` : "";
      const row = options.map((o) => `<button class="jspsych-btn ap-option" data-value="${esc(o.value)}">` +
        `${esc(o.label)}${o.key && !scale ? ` <span class="ap-key">${esc(o.key.toUpperCase())}</span>` : ""}</button>`)
        .join("");
      const ends = scale && anchors && (anchors[0] || anchors[1]) ?
        `<div class="ap-anchors"><span>${esc(anchors[0])}</span><span>${esc(anchors[1])}</span></div>` : "";
      area.innerHTML = `${ask}<p class="ap-prompt">${question}</p>` +
        (buttons || scale ? `<div class="ap-options${scale ? " ap-scale" : ""}">${row}</div>${ends}` : "") +
        (!buttons && !scale ? `<p class="ap-keys">${keyed.map((o) => `${esc(o.key.toUpperCase())}: ${esc(o.label)}`)
          .join(" &nbsp; ")}</p>` : "");
      return new Promise((resolve) => {
        let done = false, listener = null;
        const shown_t = performance.now();
        const answer = (option, method, t, key) => {
          if (done) return;
          done = true;
          if (listener !== null) this.jsPsych.pluginAPI.cancelKeyboardResponse(listener);
          area.dataset.task = "";
          resolve({ value: option.value, key: key || "", method, t, shown_t });
        };
        area.querySelectorAll("button.ap-option").forEach((button) => {
          button.addEventListener("click", (event) => {
            const option = options.find((o) => o.value === button.dataset.value);
            answer(option, "button", event.timeStamp || performance.now(), "");
          });
        });
        if (keyed.length) {
          const listening = performance.now();
          listener = this.jsPsych.pluginAPI.getKeyboardResponse({
            callback_function: (info) => {
              const option = keyed.find((o) => this.jsPsych.pluginAPI.compareKeys(o.key, info.key));
              if (option) answer(option, "key", listening + info.rt, info.key);
            },
            valid_responses: keyed.map((o) => o.key), rt_method: "performance", persist: false,
            allow_held_key: false,
          });
        }
      });
    }
  }

  ApStudyTrialPlugin.info = info;
  return ApStudyTrialPlugin;
})(jsPsychModule);

var jsPsychApPage = (function (jspsych) {
  "use strict";
  const { ParameterType } = jspsych;
  const info = {
    name: "ap-page",
    version: "1.0.0",
    parameters: {
      /** The page's name, recorded. */
      page: { type: ParameterType.STRING, default: "" },
      html: { type: ParameterType.HTML_STRING, default: "" },
      /** [{label, value, key}]: no buttons, no end (the last page) unless a duration is given. */
      buttons: { type: ParameterType.COMPLEX, default: [] },
      /** ms after which the page ends by itself (0: never). */
      duration: { type: ParameterType.INT, default: 0 },
    },
  };

  class ApPagePlugin {
    constructor(jsPsych) {
      this.jsPsych = jsPsych;
    }

    trial(display_element, trial) {
      const buttons = trial.buttons.map((b) => `<button class="jspsych-btn ap-page-button" data-value="${b.value}">` +
        `${b.label}${b.key ? ` <span class="ap-key">${b.key === " " ? "space" : b.key.toUpperCase()}</span>` : ""}` +
        `</button>`).join(" ");
      display_element.innerHTML = `<div class="ap-page" id="ap-page" data-page="${trial.page}">${trial.html}` +
        `<div class="ap-page-buttons">${buttons}</div></div>`;
      const start = performance.now();
      if (trial.duration > 0) {
        this.jsPsych.pluginAPI.setTimeout(() => {
          display_element.innerHTML = "";
          this.jsPsych.finishTrial({ ap_row: "page", page: trial.page });
        }, trial.duration);
        return;
      }
      if (!trial.buttons.length) return;
      let listener = null;
      const finish = (value, method) => {
        if (listener !== null) this.jsPsych.pluginAPI.cancelKeyboardResponse(listener);
        display_element.innerHTML = "";
        this.jsPsych.finishTrial({ ap_row: "page", page: trial.page, response: value, response_method: method,
                                   rt: performance.now() - start });
      };
      display_element.querySelectorAll("button.ap-page-button").forEach((button) => {
        button.addEventListener("click", () => finish(button.dataset.value, "button"));
      });
      const keyed = trial.buttons.filter((b) => b.key);
      if (keyed.length) {
        listener = this.jsPsych.pluginAPI.getKeyboardResponse({
          callback_function: (k) => {
            const b = keyed.find((x) => this.jsPsych.pluginAPI.compareKeys(x.key, k.key));
            if (b) finish(b.value, "key");
          },
          valid_responses: keyed.map((b) => b.key), rt_method: "performance", persist: false, allow_held_key: false,
        });
      }
    }
  }

  ApPagePlugin.info = info;
  return ApPagePlugin;
})(jsPsychModule);

var jsPsychApTask = (function (jspsych) {
  "use strict";
  const { ParameterType } = jspsych;
  const info = {
    name: "ap-task",
    version: "1.0.0",
    parameters: {
      /** async (show) => data: the work; show(text) puts a line on the page. */
      run: { type: ParameterType.FUNCTION, default: undefined },
      message: { type: ParameterType.HTML_STRING, default: "" },
    },
  };

  class ApTaskPlugin {
    constructor(jsPsych) {
      this.jsPsych = jsPsych;
    }

    trial(display_element, trial) {
      display_element.innerHTML = `<div class="ap-page" id="ap-task"><p>${trial.message}</p>` +
        `<p id="ap-task-status"></p></div>`;
      const status = display_element.querySelector("#ap-task-status");
      const show = (text) => { status.textContent = text; };
      Promise.resolve().then(() => trial.run(show)).then((data) => {
        this.jsPsych.finishTrial({ ap_row: "task", ...(data || {}) });
      }, (error) => {
        console.error(`ap-study: ${error && error.message ? error.message : error}`);
        this.jsPsych.finishTrial({ ap_row: "task", error: String(error && error.message ? error.message : error) });
      });
    }
  }

  ApTaskPlugin.info = info;
  return ApTaskPlugin;
})(jsPsychModule);
