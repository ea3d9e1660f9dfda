// The head in a page of another framework (PsychoJS, lab.js, a page of your own): a stimulus of a
// `web-export --stimuli` site in a same-origin <iframe>, played and heard through the frame's
// window.ArtificialPerson, its event times carried onto this page's performance.now().
// docs/web-jspsych.md, "PsychoJS". A classic script: it defines showStimulusInFrame.
//
//   const head = await showStimulusInFrame(document.body, "site/", "0001", { left: 100, top: 50 });
//   const record = await head.play();    // {stimulus, play_t, clip_start_t, word_onsets: [{word, start_ms, t}], ended_t}
//   head.remove();

/** Open stimulus ``id`` of the site at ``site`` (a folder URL, same origin) paused at 0 in a frame in ``container``. */
async function showStimulusInFrame(container, site, id, place = {}) {
  const base = new URL(site, document.baseURI);
  const frame = document.createElement("iframe");
  frame.src = new URL(`index.html?stimulus=${encodeURIComponent(id)}&t=0`, base).href;
  frame.title = "talking head";
  frame.allow = "autoplay";
  Object.assign(frame.style, { border: "0", position: place.left !== undefined ? "absolute" : "static",
                               left: `${place.left || 0}px`, top: `${place.top || 0}px` });
  frame.width = place.width || 600;
  frame.height = place.height || 800;
  container.appendChild(frame);
  await new Promise((resolve) => frame.addEventListener("load", resolve, { once: true }));
  const inner = frame.contentWindow;
  while (typeof inner.ArtificialPerson !== "object") await new Promise((resolve) => setTimeout(resolve, 20));
  const player = inner.ArtificialPerson;
  await player.whenReady();
  // The frame has a clock of its own (another time origin): its performance.now() + this shift is ours.
  const shift = inner.performance.timeOrigin - performance.timeOrigin;
  const ours = (t) => t + shift;

  function play() {
    return new Promise((resolve) => {
      const record = { stimulus: id, play_t: null, clip_start_t: null, word_onsets: [], ended_t: null, sound: null };
      player.addEventListener("play", (e) => { record.play_t = ours(e.detail.t); }, { once: true });
      const onWord = (e) => record.word_onsets.push({ word: e.detail.word, start_ms: e.detail.start_ms, t: ours(e.detail.t) });
      player.addEventListener("word", onWord);
      player.addEventListener("ended", (e) => {
        player.removeEventListener("word", onWord);
        record.ended_t = ours(e.detail.t);
        const heard = player.timings.find((f) => f.heard_ms !== null);
        record.clip_start_t = heard ? ours(heard.t - heard.heard_ms) : null;
        resolve(record);
      }, { once: true });
      player.play().then((sounding) => { record.sound = sounding; });
    });
  }

  return { frame, player, play, ours, remove: () => frame.remove() };
}
