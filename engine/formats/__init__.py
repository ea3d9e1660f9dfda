"""File formats: model files (XML + HDF5), meshes, glTF reading, XML helpers, atomic writes.

Every file the toolkit writes carries a format version and goes to disk
atomically (``atomic.py``); readers refuse what they do not know with a
:class:`~engine.errors.UserError` naming the file and line.

>>> from engine.formats.model_files import load_model, save_model
"""
