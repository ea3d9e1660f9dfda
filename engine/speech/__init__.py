"""Speech (§2.1): synthesis with Festival, phones → articulation with coarticulation.

* :mod:`engine.speech.synthesis` — the synthesizer interface: text → waveform,
  phone and word segments (ms); :mod:`engine.speech.festival` its Festival backend.
* :mod:`engine.speech.articulation` — the phone → articulatory-target table
  (``engine/library/articulation/*.phones``).
* :mod:`engine.speech.coarticulation` — targets over time: Cohen–Massaro
  dominance functions, or the paper's plain target interpolation.
* :mod:`engine.speech.prosody` — optional visual prosody (blinks, brows, nods).

See ``docs/speech.md``.
"""
