// The experiment of an Artificial Person rating study (docs/study.md), built by `artificial-person study`.
//
// Needs, before it: jsPsych (7 or 8), plugin-ap-study.js, and the study itself as `window.AP_STUDY`
// (study-data.js), with `window.AP_HOST` ("folder", "jatos", "pavlovia" or "cognition") and `window.AP_BASE`
// (where the files are: "" beside the page). Runs consent → instructions → practice → the trials in the
// participant's order → saving → debrief, and keeps one row per trial (the columns of study.json).
//
// The order is drawn from the participant's seed with the same arithmetic as engine/study/compile.py
// (sequenceFor below, participant_sequence there): recorded in every row, reproducible from it.

(function () {
  "use strict";
  const S = window.AP_STUDY;
  const HOST = window.AP_HOST || "folder";
  const BASE = window.AP_BASE === undefined ? "" : window.AP_BASE;
  const params = new URLSearchParams(window.location.search);
  const CSS = `
    .ap-trial { display: flex; flex-direction: column; align-items: center; gap: 12px; }
    #ap-stage { min-height: 120px; display: flex; align-items: center; justify-content: center; position: relative; }
    .ap-face { display: block; max-width: 90vw; max-height: 60vh; }
    .ap-options { display: flex; flex-wrap: wrap; justify-content: center; gap: 6px; max-width: 860px; }
    .ap-option { min-width: 6em; }
    .ap-scale .ap-option { min-width: 3em; }
    .ap-key { display: inline-block; min-width: 1.2em; padding: 0 4px; margin-left: 4px; border: 1px solid #999;
              border-radius: 3px; font-size: 80%; color: #444; }
    .ap-anchors { display: flex; justify-content: space-between; width: min(480px, 90vw); font-size: 85%; color: #555; }
    .ap-prompt { font-size: 20px; margin: 4px; }
    .ap-attention { font-size: 18px; background: #fff3c4; padding: 6px 10px; border-radius: 4px; }
    .ap-page { max-width: 720px; text-align: left; line-height: 1.5; }
    .ap-page-buttons { text-align: center; margin-top: 24px; }
    .ap-fixation { font-size: 48px; }
    .ap-start { position: absolute; inset: 0; margin: auto; width: 12em; height: 3em; }`;

  // -- the participant's order (the twin of engine/study/compile.py) -------------------------------------
  function fnv1a32(text) {
    let h = 0x811c9dc5;
    for (const byte of new TextEncoder().encode(text)) {
      h ^= byte;
      h = Math.imul(h, 0x01000193) >>> 0;
    }
    return h >>> 0;
  }

  function mulberry32(seed) {
    let a = seed | 0;
    return function () {
      a = (a + 0x6d2b79f5) | 0;
      let t = Math.imul(a ^ (a >>> 15), 1 | a);
      t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
      return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
    };
  }

  function shuffle(items, next) {
    const out = items.slice();
    for (let i = out.length - 1; i > 0; i -= 1) {
      const j = Math.floor(next() * (i + 1));
      [out[i], out[j]] = [out[j], out[i]];
    }
    return out;
  }

  function orderIndex(participant, count) {
    const text = String(participant).trim();
    if (/^[0-9]{1,15}$/.test(text)) return (((Number(text) - 1) % count) + count) % count;
    return fnv1a32(text) % count;
  }

  function blockOf(trial, blocking) {
    return blocking === "none" ? "all" : String(trial[blocking]);
  }

  function sequenceFor(participant) {
    const seed = fnv1a32(`${S.seed}:${participant}`);
    const next = mulberry32(seed);
    const p = S.procedure;
    const order = orderIndex(participant, p.orders.length);
    const indices = S.trials.map((_, i) => i);
    const items = [];
    const practice = [];
    while (practice.length < p.practice) {
      for (const i of shuffle(indices, next).slice(0, p.practice - practice.length)) {
        practice.push({ phase: "practice", spec: i, block: blockOf(S.trials[i], p.blocks), expected: null });
      }
    }
    const test = [];
    for (const block of p.orders[order]) {
      let members = indices.filter((i) => blockOf(S.trials[i], p.blocks) === block);
      let repeated = [];
      for (let r = 0; r < p.repetitions; r += 1) repeated = repeated.concat(members);
      for (const i of shuffle(repeated, next)) test.push({ phase: "test", spec: i, block, expected: null });
    }
    const answers = S.tasks.includes("identification")
      ? S.choices.map((c) => c.value).filter((v) => v !== "other")
      : Array.from({ length: S.scales[0].max - S.scales[0].min + 1 }, (_, k) => String(S.scales[0].min + k));
    if (!answers.length) answers.push("other");
    for (let k = 0; k < p.attention_checks; k += 1) {
      const i = Math.floor(next() * S.trials.length);
      const expected = answers[Math.floor(next() * answers.length)];
      const position = test.length ? 1 + Math.floor(next() * test.length) : 0;
      test.splice(position, 0, { phase: "attention", spec: i, block: blockOf(S.trials[i], p.blocks), expected });
    }
    items.push(...practice, ...test);
    return { seed, order, items };
  }

  // -- the data: one row per trial, the study's columns -----------------------------------------------------
  function cell(value) {
    if (value === null || value === undefined) return "";
    if (typeof value === "boolean") return value ? "1" : "0";
    if (typeof value === "number") return Number.isFinite(value) ? String(Math.round(value * 1000) / 1000) : "";
    const text = typeof value === "object" ? JSON.stringify(value) : String(value);
    return /[",\n\r]/.test(text) ? `"${text.replace(/"/g, '""')}"` : text;
  }

  function toCsv(rows) {
    const lines = [S.columns.join(",")];
    for (const row of rows) lines.push(S.columns.map((c) => cell(row[c])).join(","));
    return lines.join("\r\n") + "\r\n";
  }

  function safeName(text) {
    return String(text).replace(/[^A-Za-z0-9_-]+/g, "_").slice(0, 64) || "participant";
  }

  function download(text, name) {
    const blob = new Blob([text], { type: "text/csv" });
    const link = document.createElement("a");
    link.href = URL.createObjectURL(blob);
    link.download = name;
    document.body.appendChild(link);
    link.click();
    link.remove();
  }

  // -- hosts -------------------------------------------------------------------------------------------------
  function hostReady() {
    if (HOST === "jatos") {
      if (typeof window.jatos === "undefined") return Promise.reject(new Error("jatos.js is not loaded"));
      return new Promise((resolve) => window.jatos.onLoad(resolve));
    }
    if (HOST === "pavlovia" && typeof window.jsPsychPavlovia === "undefined") {
      return Promise.reject(new Error("the Pavlovia plugin is missing: put jspsych-7-pavlovia-2022.1.1.js " +
                                      "(from pavlovia.org) in lib/vendors/ beside index.html"));
    }
    return Promise.resolve();
  }

  function givenParticipant() {
    for (const name of ["participant", "PROLIFIC_PID", "SONA_ID", "workerId"]) {
      const value = params.get(name);
      if (value && value.trim()) return { id: value.trim().slice(0, 64), source: "url" };
    }
    if (HOST === "jatos") {
      const q = window.jatos.urlQueryParameters || {};
      if (q.participant) return { id: String(q.participant).slice(0, 64), source: "url" };
      return { id: String(window.jatos.studyResultId), source: "host" };
    }
    return null;
  }

  function randomParticipant() {
    const bytes = new Uint8Array(4);
    crypto.getRandomValues(bytes);
    return { id: Array.from(bytes, (b) => b.toString(16).padStart(2, "0")).join(""), source: "random" };
  }

  /** Folder and lab: ask for the participant's number before anything else (a plain form). */
  function askParticipant() {
    return new Promise((resolve) => {
      const target = document.body;
      target.innerHTML = `<form id="ap-participant" class="ap-page" style="margin: 15vh auto;">` +
        `<p><label>Participant number or code <input name="participant" autofocus required maxlength="64" ` +
        `pattern="[A-Za-z0-9_\\-]+"></label></p><p><button class="jspsych-btn" type="submit">Start</button></p></form>`;
      target.querySelector("form").addEventListener("submit", (event) => {
        event.preventDefault();
        const value = target.querySelector("input").value.trim();
        target.innerHTML = "";
        resolve({ id: value, source: "entered" });
      });
    });
  }

  async function save(csv, participant, show) {
    const name = `${safeName(S.name)}_${safeName(participant)}.csv`;
    if (HOST === "jatos") {
      show("Sending the data …");
      if (typeof window.jatos.uploadResultFile === "function") await window.jatos.uploadResultFile(csv, name);
      await window.jatos.submitResultData(csv);
      return { saved: "jatos", file: name };
    }
    if (HOST === "cognition" || HOST === "pavlovia") return { saved: HOST, file: name };
    if (params.get("lab")) {
      show("Saving the data …");
      try {
        const response = await fetch(`save?participant=${encodeURIComponent(participant)}`, {
          method: "POST", headers: { "Content-Type": "text/csv" }, body: csv,
        });
        const answer = await response.json();
        if (!response.ok) throw new Error(answer.error || response.status);
        return { saved: "lab", file: answer.file };
      } catch (error) {
        console.error(`ap-study: the lab server did not save the data (${error.message || error}); downloaded`);
      }
    }
    download(csv, name);
    return { saved: "download", file: name };
  }

  // -- preloading ----------------------------------------------------------------------------------------------
  async function preload(show, cache) {
    const files = [...new Set(S.trials.filter((t) => t.media !== "live").map((t) => t.file))];
    let done = 0;
    const viaFetch = /^https?:$/.test(window.location.protocol);
    await Promise.all(files.map(async (file) => {
      const url = `${BASE}${file}`;
      if (/\.(mp4|webm)$/i.test(file) && viaFetch) {
        const response = await fetch(url);
        if (!response.ok) throw new Error(`cannot load ${url}: ${response.status}`);
        cache[file] = URL.createObjectURL(await response.blob());
      } else if (!/\.(mp4|webm)$/i.test(file)) {
        const img = new Image();
        img.src = url;
        await img.decode();
      }
      done += 1;
      show(`${done} of ${files.length}`);
    }));
    return { preloaded: files.length };
  }

  // -- the timeline --------------------------------------------------------------------------------------------
  function page(name, html, buttons, extra) {
    return Object.assign({ type: jsPsychApPage, page: name, html, buttons: buttons || [] }, extra || {});
  }

  function trialNodes(items, cache) {
    const p = S.procedure;
    const columns = S.level_columns;
    const nodes = [];
    for (const item of items) {
      if (p.fixation_ms > 0) {
        nodes.push(page("fixation", '<div class="ap-fixation">+</div>', [], { duration: p.fixation_ms }));
      }
      nodes.push({
        type: jsPsychApStudyTrial, spec: S.trials[item.spec], phase: item.phase, block: item.block,
        expected: item.expected, tasks: S.tasks, choices: S.choices, question: S.question, buttons: S.buttons,
        scales: S.scales, static_ms: p.static_ms, width: S.width, live_site: `${BASE}live/`, base: BASE,
        media_cache: cache, level_columns: columns, post_trial_gap: p.gap_ms,
      });
    }
    return nodes;
  }

  async function run(participant) {
    const { seed, order, items } = sequenceFor(participant.id);
    const cache = {};
    let consented = false, counter = 0, saved = null;
    const jsPsych = initJsPsych({
      on_trial_finish: (data) => {
        if (data.ap_row === "trial") {
          counter += 1;
          data.trial = counter;
        }
      },
    });
    window.APStudy.jsPsych = jsPsych;
    jsPsych.data.addProperties({
      study: S.name, study_id: S.study_id, set_manifest_sha256: S.set_manifest_sha256, participant: participant.id,
      participant_source: participant.source, participant_seed: seed, order, host: HOST,
      block_order: S.procedure.orders[order].join(";"),
    });
    const rows = () => jsPsych.data.get().filter({ ap_row: "trial" }).values();
    window.APStudy.rows = rows;
    window.APStudy.csv = () => toCsv(rows());
    const agree = [{ label: S.pages.agree, value: "agree", key: "y" }, { label: S.pages.decline, value: "decline",
                                                                          key: "n" }];
    const onward = [{ label: "Continue", value: "continue", key: " " }];
    const practice = items.filter((i) => i.phase === "practice");
    const test = items.filter((i) => i.phase !== "practice");
    const inner = [
      page("instructions", S.pages.instructions, onward),
      { type: jsPsychApTask, message: "Loading the faces …", run: (show) => preload(show, cache) },
      ...trialNodes(practice, cache),
      ...(practice.length ? [page("practice_end", S.pages.practice_end, onward)] : []),
      ...trialNodes(test, cache),
      { type: jsPsychApTask, message: "Saving …", run: async (show) => {
        saved = await save(toCsv(rows()), participant.id, show);
        return saved;
      } },
    ];
    if (HOST === "pavlovia") {
      inner.push({ type: window.jsPsychPavlovia, command: "finish", participantId: participant.id,
                   dataFilter: () => toCsv(rows()) });
    }
    const ending = HOST === "jatos" ? [{ label: "Finish", value: "finish", key: " " }] : [];
    inner.push(page("debrief", S.pages.debrief + (HOST === "folder" ?
      '<p class="ap-page-buttons"><button class="jspsych-btn" id="ap-save-again">Save the data again</button></p>' :
      ""), ending, {
      on_load: () => {
        const again = document.querySelector("#ap-save-again");
        if (again) again.addEventListener("click", () => download(toCsv(rows()), saved.file));
        document.body.dataset.apDone = saved ? saved.saved : "unsaved";
      },
      on_finish: () => { if (HOST === "jatos") window.jatos.endStudy(); },
    }));
    const timeline = [];
    if (HOST === "pavlovia") timeline.push({ type: window.jsPsychPavlovia, command: "init" });
    timeline.push(page("consent", S.pages.consent, agree, {
      on_finish: (data) => { consented = data.response === "agree"; },
    }));
    timeline.push({ timeline: inner, conditional_function: () => consented });
    timeline.push({
      timeline: [page("declined", S.pages.declined, [], {
        on_load: () => {
          document.body.dataset.apDone = "declined";
          if (HOST === "jatos") window.jatos.endStudy(false, "declined");
        },
      })],
      conditional_function: () => !consented,
    });
    await jsPsych.run(timeline);
  }

  function fail(error) {
    const message = String((error && error.message) || error);
    console.error(`ap-study: ${message}`);
    document.body.innerHTML = `<p class="ap-error" style="margin: 20vh auto; max-width: 40em;">This study cannot ` +
      `start: ${message.replace(/[<&]/g, "")}</p>`;
  }

  async function boot() {
    const style = document.createElement("style");
    style.textContent = CSS;
    document.head.appendChild(style);
    if (S.live && window.location.protocol === "file:") {
      throw new Error("the live player needs the folder served over HTTP: run python3 run-lab.py here");
    }
    await hostReady();
    const participant = givenParticipant() || (HOST === "folder" ? await askParticipant() : randomParticipant());
    await run(participant);
  }

  window.APStudy = { sequenceFor, toCsv, fnv1a32, mulberry32, orderIndex };
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", () => boot().catch(fail));
  else boot().catch(fail);
})();
