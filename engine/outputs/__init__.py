"""What the animation becomes: pictures, videos with audio, tables, glTF, configuration folders.

* ``render.py`` (with ``camera.py``, ``part_layout.py``, ``part_materials.py``,
  ``png_file.py``) draws poses offscreen with VTK, imported inside its functions,
  so importing this package loads no rendering library; ``raster.py`` draws
  text and marks into images with numpy.
* ``video_writer.py`` renders frames into an MP4 with the audio (ffmpeg);
  ``video_probe.py`` reads videos back; ``video_tools.py`` finds ffmpeg.
* ``speech_files.py`` writes everything one utterance becomes (video, WAV,
  low-level commands, phones, tracks, landmarks) together, sampling the
  timeline once.
* ``gltf_export.py`` writes the model with morph targets (and a skeleton);
  ``configuration_export.py`` writes a model with the library files it uses.

>>> from engine.outputs.render import render_model
"""
