"""File → New head from photographs (docs/workbench-photofit.md): the wizard (`wizard.py`), its pages
(`photos.py`, `landmarks.py`, `fit.py`, `result.py`), the photo canvas (`canvas.py`) and the session (`session.py`).
"""
