"""The Identity dock (docs/workbench-identity.md).

The panel (`panel.py`), its rows (`rows.py`), heads made off the GUI thread (`heads.py`).
"""
