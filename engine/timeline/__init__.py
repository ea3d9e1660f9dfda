"""The timeline (§2.3): low-level command keys → the value of every parameter at any time.

* :mod:`engine.timeline.timeline` — :class:`Timeline`, sampled from activations.
* :mod:`engine.timeline.tracks` — the tracks CSV written from samples and read
  back as a :class:`~engine.timeline.tracks.TracksTable` that plays like a timeline.
* :mod:`engine.timeline.animation_files` — a command file or a tracks CSV
  opened as something to play.
* :mod:`engine.timeline.command_curves` — the curve each parameter of one
  library command follows (what the library editor plots).
* :mod:`engine.timeline.expressions` — the expressions and action units a
  model can show, each with its preview timeline (the expression gallery).

>>> from engine.timeline import Timeline
"""

from engine.timeline.timeline import Timeline

__all__ = ["Timeline"]
