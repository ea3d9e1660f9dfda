"""The command language of §2.3: library files, command files, the translator.

>>> from engine import load_model
>>> from engine.commands import load_library, read_commands, translate, low_level_xml
>>> activations = translate(read_commands("script.xml"), load_library(), load_model())   # doctest: +SKIP
>>> print(low_level_xml(activations))                                                    # doctest: +SKIP

The timeline that samples the result lives in :mod:`engine.timeline.timeline`.
See ``docs/commands.md`` for the formats and rules.
"""

from engine.commands.command_definition import CommandDefinition, Curve
from engine.commands.command_files import (
                            Activation,
                            HighLevelCommand,
                            low_level_xml,
                            parse_commands_text,
                            read_commands,
                            write_low_level,
)
from engine.commands.interpolation import INTERPOLATIONS, interpolate
from engine.commands.library import Library, load_library
from engine.commands.library_format import load_library_file, parse_library_text
from engine.commands.procedures import PROCEDURES, register_procedure
from engine.commands.translator import translate

__all__ = [
                            "INTERPOLATIONS",
                            "PROCEDURES",
                            "Activation",
                            "CommandDefinition",
                            "Curve",
                            "HighLevelCommand",
                            "Library",
                            "interpolate",
                            "load_library",
                            "load_library_file",
                            "low_level_xml",
                            "parse_commands_text",
                            "parse_library_text",
                            "read_commands",
                            "register_procedure",
                            "translate",
                            "write_low_level",
]
