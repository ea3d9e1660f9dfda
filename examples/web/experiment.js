// The example experiment (docs/web-jspsych.md): every stimulus of the site's set once, in random
// order; after each, which of two words was the sentence's first (f: the left one, j: the right one).
// At the end the data are shown as CSV, with a button to save them.

const jsPsych = initJsPsych({ on_finish: showData });

function firstWord(stimulus) {
  return (stimulus.manifest.words || "").split(";")[0];
}

/** Each stimulus with its first word and another sentence's first word, on random sides. */
function trialsOf(stimuli) {
  const firsts = [...new Set(stimuli.map(firstWord))];
  return stimuli.map((stimulus) => {
    const right = firstWord(stimulus);
    const others = firsts.filter((w) => w !== right);
    const foil = others.length ? jsPsych.randomization.sampleWithoutReplacement(others, 1)[0] : "?";
    const [left_word, right_word] = jsPsych.randomization.shuffle([right, foil]);
    return { id: stimulus.id, left_word, right_word, correct_key: left_word === right ? "f" : "j" };
  });
}

function showData() {
  const rows = jsPsych.data.get().filter({ trial_type: "artificial-person" });
  const csv = rows.csv();
  const target = jsPsych.getDisplayElement();
  target.innerHTML = `<div style="text-align: left; max-width: 90vw;">
    <p>Thank you. ${rows.filter({ correct: true }).count()} of ${rows.count()} correct.</p>
    <p><button class="jspsych-btn" id="save">Save the data (CSV)</button></p>
    <pre id="data" style="font-size: 11px; white-space: pre-wrap;"></pre></div>`;
  target.querySelector("#data").textContent = csv;
  target.querySelector("#save").addEventListener("click", () => rows.localSave("csv", "artificial-person-data.csv"));
}

async function start() {
  const listing = await (await fetch("stimuli.json")).json();
  const instructions = {
    type: jsPsychHtmlKeyboardResponse,
    stimulus: "<p>You will see and hear a face say a short sentence.</p>" +
      "<p>Then choose which word you heard <b>first</b>: press <b>F</b> for the word on the left, " +
      "<b>J</b> for the word on the right. You may answer while the face is still speaking.</p>" +
      "<p>Press the space bar to begin.</p>",
    choices: [" "],
  };
  const trial = {
    type: jsPsychArtificialPerson,
    stimulus: jsPsych.timelineVariable("id"),
    choices: ["f", "j"],
    canvas_size: [300, 400],
    prompt: () => `<p style="font-size: 22px;"><b>${jsPsych.evaluateTimelineVariable("left_word")}</b> (F)
      &nbsp;&nbsp; or &nbsp;&nbsp; <b>${jsPsych.evaluateTimelineVariable("right_word")}</b> (J)?</p>`,
    data: {
      left_word: jsPsych.timelineVariable("left_word"),
      right_word: jsPsych.timelineVariable("right_word"),
      correct_key: jsPsych.timelineVariable("correct_key"),
    },
    on_finish: (data) => { data.correct = data.response === data.correct_key; },
    post_trial_gap: 500,
  };
  jsPsych.run([instructions,
               { timeline: [trial], timeline_variables: trialsOf(listing.stimuli), randomize_order: true }]);
}

start();
