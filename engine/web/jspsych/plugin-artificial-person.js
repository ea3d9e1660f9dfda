// jsPsych 8 plugin: one stimulus of an Artificial Person stimulus-set site, played live in the page
// (docs/web-jspsych.md). Load after jsPsych, as a classic script:
//
//   <script src="jspsych/dist/index.browser.min.js"></script>
//   <script src="plugin-artificial-person.js"></script>
//   ... timeline.push({ type: jsPsychArtificialPerson, stimulus: "0001", choices: ["f", "j"] });
//
// The site is a folder made by `artificial-person web-export --stimuli SET -o SITE/` (its stimuli.json and
// player.js, the player bundled with three.js in one ES module: the page needs no import map).
//
// Times: `t` values are performance.now() in ms, as the page saw them; `_ms` values are on the
// stimulus's own clip clock (0 = the clip's first sound sample, where its face starts too unless the
// manifest says otherwise). `rt` is the key press on the clip clock, measured on the player's
// clock (the sound being heard), not from when the trial began.

var jsPsychArtificialPerson = (function (jspsych) {
  "use strict";

  const { ParameterType } = jspsych;

  const info = {
    name: "artificial-person",
    version: "1.0.0",
    parameters: {
      /** The stimulus's id, as in the set's manifest.csv and the site's stimuli.json. */
      stimulus: { type: ParameterType.STRING, default: undefined },
      /** The site's folder, relative to the page ("" when the page is in the site, as the example is). */
      site: { type: ParameterType.STRING, default: "" },
      /** Keys that count as a response ("ALL_KEYS", "NO_KEYS", or a list such as ["f", "j"]). */
      choices: { type: ParameterType.KEYS, default: "ALL_KEYS" },
      /** HTML shown below the head. */
      prompt: { type: ParameterType.HTML_STRING, default: null },
      /** End the trial at the first response (else at the stimulus's end, once there is a response). */
      response_ends_trial: { type: ParameterType.BOOL, default: true },
      /** End the trial when the stimulus has played, with or without a response. */
      trial_ends_after_stimulus: { type: ParameterType.BOOL, default: false },
      /** End the trial this many ms after the stimulus starts playing (null: no limit). */
      trial_duration: { type: ParameterType.INT, default: null },
      /** The head's size on the page, [width, height]: CSS pixels, or CSS lengths such as ["100%", "70vh"]
       *  (null: the site's size, e.g. 600×800). The head is framed for the size it gets, as render frames it. */
      // (COMPLEX: jsPsych 8 refuses null for an array parameter, and turns an array given to an INT one into NaN)
      canvas_size: { type: ParameterType.COMPLEX, default: null },
    },
    data: {
      /** The stimulus's id. */
      stimulus: { type: ParameterType.STRING },
      /** The key pressed (null: none). */
      response: { type: ParameterType.STRING },
      /** ms from the clip's start to the key press, on the player's clock (null: no response). */
      rt: { type: ParameterType.FLOAT },
      /** ms from the speech's onset (the manifest's speech_onset_ms) to the key press. */
      rt_speech: { type: ParameterType.FLOAT },
      /** From the manifest, on the clip clock: where the sound, the face and the speech start. */
      audio_start_ms: { type: ParameterType.FLOAT },
      video_start_ms: { type: ParameterType.FLOAT },
      speech_onset_ms: { type: ParameterType.FLOAT },
      duration_ms: { type: ParameterType.FLOAT },
      /** performance.now() of: play() called; the clip's start heard (the player's clock at 0, from its first
       *  frame with sound). */
      play_t: { type: ParameterType.FLOAT },
      clip_start_t: { type: ParameterType.FLOAT },
      /** performance.now() of the sound's, the face's and the speech's start (clip_start_t + the manifest's ms). */
      audio_start_t: { type: ParameterType.FLOAT },
      face_start_t: { type: ParameterType.FLOAT },
      speech_onset_t: { type: ParameterType.FLOAT },
      /** Each word as the page showed its start: {word, start_ms (clip clock), t (performance.now())}. */
      word_onsets: { type: ParameterType.COMPLEX, array: true },
      /** performance.now() of the player's end (null: the trial ended first) and of the key press. */
      ended_t: { type: ParameterType.FLOAT },
      response_t: { type: ParameterType.FLOAT },
      /** Whether the sound ran (false: the browser held it, and the clock was performance.now()). */
      sound: { type: ParameterType.BOOL },
      /** How far the clip's 0 on performance.now() moved over the frames (max − min, ms): the sound's clock
       *  against the page's; a fraction of a ms where the audio output keeps time. */
      clock_spread_ms: { type: ParameterType.FLOAT },
      /** Frames the player drew while playing. */
      frames: { type: ParameterType.INT },
      // and the manifest row's factor levels, each in a column of its own (text, av_offset_ms, ...;
      // a factor named as one of the above becomes factor_NAME)
    },
  };

  // Data names jsPsych or this plugin use: a factor of the same name goes in as "factor_NAME".
  const RESERVED = new Set(["rt", "response", "stimulus", "trial_type", "trial_index", "time_elapsed",
    "internal_node_id", ...Object.keys(info.data)]);
  // Manifest columns that are not factor levels (av_offset_ms and snr_db are kept: a factor or the set's value).
  const NOT_LEVELS = new Set(["id", "duration_ms", "audio_start_ms", "video_start_ms", "alignment_ms",
    "speech_onset_ms", "word_onsets_ms", "words", "expression_apex_ms", "still_ms"]);

  const listings = new Map();     // site URL -> promise of its stimuli.json
  const players = new Map();      // site URL -> promise of player.js's module

  function siteUrl(site) {
    const url = new URL(site || ".", document.baseURI);
    if (!url.pathname.endsWith("/")) url.pathname += "/";
    return url;
  }

  function listing(site) {
    const key = site.href;
    if (!listings.has(key)) {
      listings.set(key, fetch(new URL("stimuli.json", site)).then((response) => {
        if (!response.ok) throw new Error(`cannot load ${response.url}: ${response.status}`);
        return response.json();
      }));
    }
    return listings.get(key);
  }

  function playerModule(site) {
    const key = site.href;
    if (!players.has(key)) players.set(key, import(new URL("player.js", site).href));
    return players.get(key);
  }

  function levelsOf(manifest) {
    const levels = {};
    for (const [name, value] of Object.entries(manifest)) {
      if (NOT_LEVELS.has(name) || name.startsWith("file_") || name.startsWith("sha256_")) continue;
      levels[name] = value;
    }
    return levels;
  }

  function number(text) {
    return text === undefined || text === "" ? null : Number(text);
  }

  /** The clip clock's 0 as performance.now() saw it, per frame the player drew while playing: from the
   *  sound being heard (the player's clock) where the sound ran, else from the position drawn. */
  function clipZeros(player) {
    const heard = player.timings.filter((f) => f.heard_ms !== null).map((f) => f.t - f.heard_ms);
    if (heard.length) return heard;
    return player.timings.filter((f) => f.drawn_ms < player.duration).map((f) => f.t - f.drawn_ms);
  }

  /** Where the player's clock (ms on the clip clock) was at performance.now() = ``t``: the sound heard now, carried
   *  back to ``t``; after the sound has stopped, the last frame's, carried forward. */
  function clockAt(player, t) {
    const heard = player.heardPosition();
    if (heard !== null) return heard - (performance.now() - t);
    const frames = player.timings.filter((f) => f.heard_ms !== null);
    const last = frames.length ? frames[frames.length - 1] : player.timings[player.timings.length - 1];
    if (!last) return null;
    return (last.heard_ms !== null ? last.heard_ms : last.drawn_ms) + (t - last.t);
  }

  /** Whether the audio context runs, or starts within a moment (browsers that allow sound resume at once). */
  async function soundRuns(context) {
    if (context.state === "running") return true;
    await Promise.race([context.resume().catch(() => {}), new Promise((resolve) => setTimeout(resolve, 300))]);
    return context.state === "running";
  }

  /** Stop the player for good: its sound, its frame loop and its GL context (a trial makes a new one). */
  function release(player) {
    player.dispose();
  }

  class ArtificialPersonPlugin {
    constructor(jsPsych) {
      this.jsPsych = jsPsych;
    }

    trial(display_element, trial) {
      // Not async: jsPsych waits for finishTrial(); a failure is shown, logged and ends the trial.
      this._run(display_element, trial).catch((error) => {
        console.error(`artificial-person: stimulus ${trial.stimulus}: ${error.message || error}`);
        display_element.innerHTML = `<p class="ap-error">The stimulus could not be shown (${String(error.message || error)
          .replace(/[<&]/g, "")}).</p>`;
        this.jsPsych.finishTrial({ stimulus: trial.stimulus, error: String(error.message || error) });
      });
    }

    async _run(display_element, trial) {
      display_element.innerHTML =
        '<div id="jspsych-artificial-person" data-state="loading" data-words="0" ' +
        'style="position: relative; display: inline-block; visibility: hidden;">' +
        '<canvas aria-label="talking head" style="display: block;"></canvas>' +
        '<button class="jspsych-btn" style="display: none; position: absolute; inset: 0; margin: auto; ' +
        'width: 12em; height: 3em;">Click to start</button></div>' +
        (trial.prompt !== null ? `<div id="jspsych-artificial-person-prompt">${trial.prompt}</div>` : "");
      const stage = display_element.querySelector("#jspsych-artificial-person");
      const canvas = stage.querySelector("canvas");
      const start = stage.querySelector("button");
      if (trial.canvas_size) {
        const length = (value) => (typeof value === "number" ? `${value}px` : String(value));
        canvas.style.width = length(trial.canvas_size[0]);
        canvas.style.height = length(trial.canvas_size[1]);
        if (String(trial.canvas_size[0]).endsWith("%")) stage.style.display = "block";   // as wide as the page
      }

      const site = siteUrl(trial.site);
      const [{ ArtificialPerson }, set] = await Promise.all([playerModule(site), listing(site)]);
      const listed = set.stimuli.find((s) => s.id === String(trial.stimulus));
      if (!listed) throw new Error(`no stimulus '${trial.stimulus}' in ${new URL("stimuli.json", site)}`);
      const manifest = listed.manifest || {};

      const player = new ArtificialPerson(canvas);
      const seen = { play_t: null, ended_t: null, words: [] };
      player.addEventListener("play", (e) => { if (seen.play_t === null) seen.play_t = e.detail.t; });
      player.addEventListener("word", (e) => {
        seen.words.push({ word: e.detail.word, start_ms: e.detail.start_ms, t: e.detail.t });
        stage.dataset.words = String(seen.words.length);
      });
      await player.load(new URL(listed.animation, site).href);
      const background = player.animation.background;
      if (background) stage.style.background = `linear-gradient(to top, ${background.bottom}, ${background.top})`;
      stage.style.visibility = "visible";

      let response = null, ended = false, finished = false, listener = null;
      const finish = () => {
        if (finished) return;
        finished = true;
        if (listener !== null) this.jsPsych.pluginAPI.cancelKeyboardResponse(listener);
        const zeros = clipZeros(player);
        const zero = zeros.length ? zeros[0] : null;
        const at = (ms) => (zero === null || ms === null ? null : zero + ms);
        const speech = number(manifest.speech_onset_ms);
        const data = {
          stimulus: listed.id,
          response: response ? response.key : null,
          rt: response ? response.clock_ms : null,
          rt_speech: response && response.clock_ms !== null && speech !== null ? response.clock_ms - speech : null,
          audio_start_ms: number(manifest.audio_start_ms),
          video_start_ms: number(manifest.video_start_ms),
          speech_onset_ms: speech,
          duration_ms: player.duration,
          play_t: seen.play_t,
          clip_start_t: zero,
          audio_start_t: at(number(manifest.audio_start_ms)),
          face_start_t: at(number(manifest.video_start_ms)),
          speech_onset_t: at(speech),
          word_onsets: seen.words,
          ended_t: seen.ended_t,
          response_t: response ? response.t : null,
          sound: player.timings.some((f) => f.heard_ms !== null),
          clock_spread_ms: zeros.length ? Math.max(...zeros) - Math.min(...zeros) : null,
          frames: player.timings.length,
        };
        for (const [name, value] of Object.entries(levelsOf(manifest))) {
          data[RESERVED.has(name) ? `factor_${name}` : name] = value;
        }
        release(player);
        stage.dataset.state = "done";
        this.jsPsych.finishTrial(data);
      };

      player.addEventListener("ended", (e) => {
        seen.ended_t = e.detail.t;
        ended = true;
        stage.dataset.state = "ended";
        if (trial.trial_ends_after_stimulus || response !== null) finish();
      });

      // Sound needs a gesture in some browsers (a page the participant has not yet clicked or typed in): then
      // the head waits, still, for a click, rather than start moving in silence.
      if (!(await soundRuns(player.audioContext))) {
        start.style.display = "block";      // not `hidden`: jspsych.css displays .jspsych-btn
        stage.dataset.state = "waiting";
        await new Promise((resolve) => start.addEventListener("click", () => {
          player.audioContext.resume().catch(() => {});           // within the gesture
          resolve();
        }, { once: true }));
        start.style.display = "none";
      }
      if (!(await player.play())) {         // the sound still held: the clock is performance.now() (sound: false)
        console.warn(`artificial-person: stimulus ${listed.id} plays without sound`);
      }
      if (finished) return;
      stage.dataset.state = ended ? "ended" : "playing";

      if (trial.choices !== "NO_KEYS") {
        const listening = performance.now();
        listener = this.jsPsych.pluginAPI.getKeyboardResponse({
          callback_function: (key) => {
            const t = listening + key.rt;
            response = { key: key.key, t, clock_ms: clockAt(player, t) };
            if (trial.response_ends_trial || ended) finish();
          },
          valid_responses: trial.choices,
          rt_method: "performance",
          persist: false,
          allow_held_key: false,
        });
      }
      if (trial.trial_duration !== null) this.jsPsych.pluginAPI.setTimeout(finish, trial.trial_duration);
    }
  }

  ArtificialPersonPlugin.info = info;
  return ArtificialPersonPlugin;
})(jsPsychModule);
