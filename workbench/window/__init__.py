"""The main window and what frames the tools: menus and actions, docks and task layouts, files, autosave.

`main_window.py` assembles the pieces; `actions.py` declares the commands; `layouts.py` and
`task_layouts.py` arrange the docks; `file_controller.py` opens, saves and exports, with
`recent_files.py` and `export_folder_dialog.py`; `recovery.py` autosaves; `status_bar.py`,
`parts_menu.py`, `tool_options.py` and `dock_scroller.py` are the window's own widgets.
"""
