"""What the window shows and edits: the model document with its undo stack, the view state, the playhead.

`model_document.py` holds the model, its file and its undo stack; `undo_commands.py` turns each engine
edit into a command that keeps the inverse the engine returns; `view_state.py` is what is seen (parts,
selection, wireframe); `playhead.py` is the time shown. No Qt widget here.
"""
