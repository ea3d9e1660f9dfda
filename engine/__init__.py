"""Artificial Person engine: the science, with no Qt and no VTK at import.

The toolkit of Frydrych, Kätsyri, Dobšák and Sams, *Toolkit for Animation of
Finnish Talking Head* (2003): a parameterised face
deformed by weighted rigid and non-rigid transforms (§2.2), driven by
commands (§2.3) and speech (§2.1).

>>> import engine
>>> head = engine.load_model()                    # the default head, mm, facing +Z
>>> [p.name for p in head.parameters][:3]
['neck_lean', 'head_turn', 'head_nod']
>>> P = head.deform(jaw_open=0.6, head_turn=0.2)  # (N, 3) vertex positions
"""

from importlib.metadata import PackageNotFoundError, version

from engine.errors import ModelFileError, ParameterError, UserError
from engine.formats.model_files import load_model, save_model
from engine.model import InfluenceRegion, Model, Parameter, ParameterTree
from engine.paths import default_model_path

__all__ = [
    "InfluenceRegion", "Model", "ModelFileError", "Parameter", "ParameterError", "ParameterTree",
    "UserError", "default_model_path", "load_model", "save_model",
]


def _version() -> str:
    """The installed distribution's version (``pyproject.toml``'s, through the package metadata). A checkout
    run without installing (``PYTHONPATH=.``) reads its ``pyproject.toml`` (``0.1.0+source``); else ``0+unknown``."""
    try:
        return version("artificial-person")
    except PackageNotFoundError:
        import tomllib
        from pathlib import Path

        try:
            project = tomllib.loads((Path(__file__).parent.parent / "pyproject.toml").read_text(encoding="utf-8"))
            return f"{project['project']['version']}+source"
        except (OSError, ValueError, KeyError):
            return "0+unknown"


__version__ = _version()
