"""The user command interpreter (§2): text with inline commands, split into words and commands.

>>> from engine.script import parse_script
>>> [c.name for c in parse_script("Hyvää <HeadNod/> päivää").commands]
['HeadNod']
"""

from engine.script.inline_commands import Script, anchored_commands, parse_script, word_start_times

__all__ = ["Script", "anchored_commands", "parse_script", "word_start_times"]
