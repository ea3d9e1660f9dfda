"""Today's face-capture streams drive the head: Live Link Face (ARKit), OpenFace 2, MediaPipe.

Readers, one module per producer, turn a file into a :class:`~engine.capture.stream.CaptureStream`
(frame times and named channels; :func:`~engine.capture.readers.read_capture` picks the reader by
the header); :func:`~engine.capture.retarget.retarget` maps it onto a model with the tables of
:mod:`engine.capture.mapping_tables`; :func:`~engine.capture.animate.animate_capture` writes the
tracks table or a video (``artificial-person capture animate``). See ``docs/capture-streams.md``.

>>> from engine import load_model
>>> from engine.capture.readers import read_capture
>>> from engine.capture.retarget import retarget
>>> mapped = retarget(read_capture("take.csv"), load_model())                # doctest: +SKIP
>>> mapped.parameters[:3], mapped.clamped, mapped.warnings                    # doctest: +SKIP
"""
