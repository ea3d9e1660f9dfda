"""Playing an animation with its sound: the player (`player.py`) and the sound output (`audio_output.py`)."""
