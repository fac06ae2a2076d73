"""The package's exceptions: every error creepbench raises is a :class:`CreepbenchError`.

The compiled module raises these classes too (it imports them from here), so there is one
hierarchy whichever half of the package an error comes from.
"""

from __future__ import annotations

__all__ = ["CreepbenchError", "RunError", "SceneError"]


class CreepbenchError(Exception):
    """Every error of the package: catch this one to catch them all."""


class SceneError(CreepbenchError, ValueError):
    """Invalid input (a scene key, a file, an argument), with exactly the CLI's message.

    ``field`` is the dotted field (prefixed by the file for a scene file, e.g.
    ``scenes/a.toml: contact.fn_n``), ``value`` the value as given, ``allowed`` what is allowed.
    """

    field: str
    value: str
    allowed: str

    def __init__(self, message: str, field: str = "", value: str = "", allowed: str = "") -> None:
        super().__init__(message)
        self.field = field
        self.value = value
        self.allowed = allowed


class RunError(CreepbenchError, RuntimeError):
    """A model, the gate or a file failed while running (an in-process model's own exception is
    its ``__cause__``)."""
