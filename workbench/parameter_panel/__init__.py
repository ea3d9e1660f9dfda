"""The Parameters dock: one slider per parameter of the tree (`panel.py`, its rows in `slider.py`)."""
