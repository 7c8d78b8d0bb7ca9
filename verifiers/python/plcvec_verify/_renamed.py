"""Old public names that still work until their removal, each with a DeprecationWarning naming the new.

A module lists its old names for static tools under `if TYPE_CHECKING:` (griffe, type checkers and
editors see each as an alias of the new one) and gives them at run time through the module
`__getattr__` (PEP 562) made here: an import or attribute that names the old name works and warns,
once per place in the user's code, as Python's warning filters do by default.
"""
from __future__ import annotations

import sys
import warnings

SINCE, UNTIL = "0.3.0", "0.4.0"


def old_names(module: str, renamed: dict[str, str], fallback=None):
    """A module `__getattr__` for `module`: each old name of `renamed` (old -> new) gives the module's
    new name with a DeprecationWarning; any other name goes to `fallback` (the module's own lazy
    names) or is an AttributeError."""

    def __getattr__(name: str):
        new = renamed.get(name)
        if new is None:
            if fallback is not None:
                return fallback(name)
            raise AttributeError(f"module {module!r} has no attribute {name!r}")
        warnings.warn(f"{module}.{name} is deprecated since {SINCE} and removed in {UNTIL}: use {module}.{new}",
                      DeprecationWarning, stacklevel=2)
        return getattr(sys.modules[module], new)

    return __getattr__
