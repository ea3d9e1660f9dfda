"""The user command interpreter (§2): text with inline commands, split into words and commands.

>>> from engine.script import parse_script
>>> script = parse_script("Hyvää <HeadNod/> päivää")
>>> script.words, [(c.command.name, c.word_index) for c in script.commands]
(['Hyvää', 'päivää'], [('HeadNod', 1)])
"""

from engine.script.inline_commands import Script, anchored_commands, parse_script, word_start_times

__all__ = ["Script", "anchored_commands", "parse_script", "word_start_times"]
