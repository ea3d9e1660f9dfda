"""What every verb of the command line shares: the parser, argument types, options, model loading.

Verb modules import from here and from the engine, never from each other,
so each verb can be read (and changed) on its own. Mistakes in the user's
input become :class:`~engine.errors.UserError`, which :func:`engine.cli.main`
prints as one line and turns into exit status 2.

>>> setting("jaw_open=0.5")
('jaw_open', 0.5)
>>> size("640x480")
(640, 480)
"""

from __future__ import annotations

import argparse
import math
import os
import stat
import sys
from pathlib import Path
from typing import NoReturn

from engine.errors import ModelFileError, UserError
from engine.model import Model

PROG = "artificial-person"
VIEW_NAMES = ("front", "side", "three-quarter")


class CliParser(argparse.ArgumentParser):
    """argparse that reports a mistake as one :class:`UserError` instead of usage text and exit."""

    def error(self, message: str) -> NoReturn:
        raise UserError(message)


def say_error(text: str) -> None:
    """Print ``error: <text>`` as one line on stderr (line breaks in ``text`` folded)."""
    print("error: " + " ".join(text.split()), file=sys.stderr)


# -- options many verbs take -------------------------------------------------------

def add_model_option(p: argparse.ArgumentParser) -> None:
    """``-m/--model MODEL``; left out, the shipped default head."""
    p.add_argument("-m", "--model", default=None, metavar="MODEL",
                   help="model description (.xml); default: the shipped head")


def add_set_option(p: argparse.ArgumentParser) -> None:
    """``--set NAME=VALUE ...`` into ``args.settings`` (a list of pairs)."""
    p.add_argument("--set", dest="settings", action="extend", nargs="+", type=setting, default=[],
                   metavar="NAME=VALUE", help="parameter values (may be repeated); others take their default")


def add_library_option(p: argparse.ArgumentParser) -> None:
    """``-L/--library LIBDIR`` (repeatable) into ``args.library``."""
    p.add_argument("-L", "--library", dest="library", action="append", default=[], metavar="LIBDIR",
                   help="a folder of *.lib files (or one file) searched after the shipped library; "
                        "its commands override shipped ones of the same name (may be repeated)")


# -- argument types --------------------------------------------------------------------

def setting(text: str) -> tuple[str, float]:
    """``NAME=VALUE`` with a finite number.

    >>> setting("jaw_open=" + "9" * 401)                                   # doctest: +ELLIPSIS
    Traceback (most recent call last):
    argparse.ArgumentTypeError: jaw_open: the value must be a finite number, not '999...' (401 characters)
    """
    name, sep, value = text.partition("=")
    name = name.strip()
    if not sep or not name:
        raise argparse.ArgumentTypeError(f"{quoted(text)} is not NAME=VALUE (e.g. jaw_open=0.5)")
    try:
        number = float(value)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{quoted(name)}: {quoted(value)} is not a number") from None
    if not math.isfinite(number):                # 'inf', 'nan', or more digits than a float holds (1e309)
        raise argparse.ArgumentTypeError(f"{name if len(name) <= 40 else quoted(name)}: the value must be a "
                                         f"finite number, not {quoted(value)}")
    return name, number


def quoted(text: str, keep: int = 20) -> str:
    """``text`` quoted for a message, its start only when it is long (a 401-digit value is not printed whole).

    >>> quoted("0.5"), quoted("1" * 30)
    ("'0.5'", "'11111111111111111111…' (30 characters)")
    """
    text = str(text)
    return f"'{text}'" if len(text) <= keep + 5 else f"'{text[:keep]}…' ({len(text)} characters)"


def size(text: str) -> tuple[int, int]:
    """``WIDTHxHEIGHT`` in pixels, each 1 … :data:`engine.outputs.render.MAX_SIZE`."""
    from engine.outputs.render import MAX_SIZE

    parts = text.lower().split("x")
    if len(parts) != 2 or not all(p.strip().isdigit() for p in parts):
        raise argparse.ArgumentTypeError(f"'{text}' is not WIDTHxHEIGHT in pixels (e.g. 800x600)")
    width, height = (int(p) for p in parts)
    if not (0 < width <= MAX_SIZE and 0 < height <= MAX_SIZE):
        raise argparse.ArgumentTypeError(f"'{text}': width and height must be 1..{MAX_SIZE} pixels")
    return width, height


def positive_number(text: str) -> float:
    """A finite number above 0."""
    try:
        number = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{quoted(text)} is not a number") from None
    if not math.isfinite(number):                # 'inf', 'nan', or more digits than a float holds (1e309)
        raise argparse.ArgumentTypeError(f"{quoted(text)} must be a finite positive number")
    if number <= 0:
        raise argparse.ArgumentTypeError(f"{quoted(text)} must be a positive number")
    return number


def frame_rate(text: str) -> float:
    """Frames per second: a number above 0 and at most :data:`engine.commands.limits.MAX_FPS`.

    >>> frame_rate("25")
    25.0
    """
    from engine.commands.limits import LimitProblem, check_fps

    try:
        return check_fps(positive_number(text))
    except LimitProblem as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def time_ms(text: str) -> float:
    """A time in ms: a finite number within ±:data:`engine.commands.limits.MAX_TIME_MS`."""
    from engine.commands.limits import LimitProblem, check_time

    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{quoted(text)} is not a number of milliseconds") from None
    try:
        return check_time(value, "the time")
    except LimitProblem as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def non_negative(text: str) -> float:
    """A finite number, 0 or more."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{quoted(text)} is not a number") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"{quoted(text)} must be a finite number, 0 or more")
    if value < 0:
        raise argparse.ArgumentTypeError(f"{quoted(text)} must be 0 or more")
    return value


def seed(text: str) -> int:
    """A random seed: a whole number from 0 to 2**32 - 1."""
    return _whole_number(text, 0, 2**32 - 1, "must be from 0 to 4294967295")


def positive_int(text: str) -> int:
    """A whole number, 1 or more."""
    return _whole_number(text, 1, None, "must be at least 1")


def _whole_number(text: str, lowest: int, highest: int | None, out_of_range: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{quoted(text)} is not a whole number" + (
            " (it has more digits than a number here can have)" if text.strip().lstrip("+-").isdigit() else "")
        ) from None
    if value < lowest or (highest is not None and value > highest):
        raise argparse.ArgumentTypeError(f"{quoted(text)} {out_of_range}")
    return value


# -- helpers ---------------------------------------------------------------------------------

def load_model_argument(model_path: str | None) -> Model:
    """Load ``-m MODEL`` (the default head for ``None``); anything the loader lets escape becomes one error line."""
    from lxml import etree

    from engine.formats.model_files import load_model
    from engine.paths import default_model_path

    try:
        return load_model(model_path)
    except etree.LxmlError as exc:  # e.g. schema validation choking on an unexpanded entity
        where = model_path if model_path is not None else default_model_path()
        raise ModelFileError(f"cannot read the model description: {exc}", file=where) from None
    except (ValueError, TypeError) as exc:  # malformed numbers or arrays in a damaged file
        where = model_path if model_path is not None else default_model_path()
        raise ModelFileError(f"damaged model: {exc}", file=where) from None


def parameter_values(model: Model, settings: list[tuple[str, float]]) -> dict[str, float]:
    """``--set`` pairs as a dict (the last one wins), checked against the model's ranges."""
    values = dict(settings)
    model.check_values(values)
    return values


def require_suffix(path: str, allowed: tuple[str, ...], what: str) -> Path:
    """``path`` as a :class:`Path` if its extension is one of ``allowed`` and it can be a file
    (:func:`output_file`), else a :class:`UserError`."""
    out = Path(path)
    if out.suffix.lower() not in allowed:
        raise UserError(f"unknown output extension '{out.suffix or out.name}' for {what} "
                        f"(use {either(allowed)})", file=out)
    return output_file(path)


def output_file(path: str | Path, what: str = "the output") -> Path:
    """``path`` as a :class:`Path` if a file may be written there: nothing is there yet, or a regular file.

    A folder (or a name ending in ``/``), a device (``/dev/null``) or a named pipe is a
    :class:`UserError`: the writers would put files beside it (``/dev/null.xml``) or replace it.

    >>> output_file("/dev/null")
    Traceback (most recent call last):
    engine.errors.UserError: /dev/null: the output must be a file, not a device or a pipe
    """
    shown = str(path)
    if shown.endswith(("/", os.sep)):
        raise UserError(f"{what} must be a file name, not a folder", file=shown)
    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError):      # not there (or a name the writer will refuse, naming why): a new file
        return Path(path)
    if stat.S_ISDIR(mode):
        raise UserError(f"{what} must be a file, not a folder", file=shown)
    if not stat.S_ISREG(mode):
        raise UserError(f"{what} must be a file, not a device or a pipe", file=shown)
    return Path(path)


def model_output(path: str | Path) -> Path:
    """``-o MODEL``: the description (``.xml``) :func:`~engine.formats.model_files.save_model` writes for
    ``path``, once ``path`` and both its files (``.xml``, ``.h5``) are checked by :func:`output_file`."""
    from engine.formats.model_files import model_file_paths

    output_file(path, "the model")
    description, arrays = model_file_paths(path)
    output_file(arrays, "the model's arrays")
    return output_file(description, "the model")


def either(options: tuple[str, ...]) -> str:
    """``'a'``, ``'a or b'``, ``'a, b or c'``.

    >>> either((".obj", ".ply", ".npz"))
    '.obj, .ply or .npz'
    """
    return options[0] if len(options) == 1 else ", ".join(options[:-1]) + " or " + options[-1]


def read_text_file(path: str) -> str:
    """The text of a UTF-8 file named on the command line (``--file F``), or one located error line."""
    from engine.formats.text_files import read_bounded_text

    try:
        return read_bounded_text(path, error=UserError, what="text")
    except OSError as exc:
        raise UserError(f"cannot read the text: {exc.strerror or exc}", file=path) from None
    except UnicodeDecodeError:
        raise UserError("the text file is not UTF-8", file=path) from None
