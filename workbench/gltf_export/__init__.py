"""File → Export → glTF: the choices dialog (`dialog.py`) and the export run off the GUI thread (`exporter.py`)."""
