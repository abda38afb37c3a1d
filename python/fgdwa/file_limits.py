"""Limits on what a file may hold, so that no file can crash, hang or exhaust memory.

Every YAML document the package reads goes through :func:`load_yaml`, every
``.npy`` array through :func:`load_npy` and every ``.npz`` member through
:func:`read_npz_member`; each refuses a file over a limit below with an
``FgdwaError`` naming the file, before the work that would blow up is done:

* YAML: :data:`MAX_YAML_BYTES` of text, read no further than that;
  :data:`MAX_YAML_DEPTH` levels of nesting; :data:`MAX_YAML_ALIASES` alias uses
  (``*name``); :data:`MAX_YAML_NODES` nodes with every alias expanded, counted as
  the document is composed, so a "billion laughs" bomb stops after a few
  thousand events.
* Arrays: :data:`MAX_ARRAY_BYTES` per array, read from the zip directory and
  from the ``.npy`` header before any data is decompressed (:func:`load_npy`,
  :func:`read_npz_member`); a reader opens only the ``.npz`` members it needs.

The numbers a scenario or BARN file gives are held to the limits further down
(resolution, map cells, coordinates, lengths, durations, counts); the scenario
readers (``fgdwa.io.scenario_values``) and the BARN loader
(``fgdwa.io.barn_data``) apply them. docs/scenarios.md and docs/barn.md list
them. Messages show a value through :func:`short_repr`, which never formats
more than a few dozen elements of it.
"""

from __future__ import annotations

import math
import os
import reprlib
import contextlib
import zipfile
from pathlib import Path
from typing import Any, Optional, Union

import numpy as np
import yaml

from fgdwa._core import FgdwaError

# --- YAML text ----------------------------------------------------------------------
MAX_YAML_BYTES = 8 * 2**20  # bytes of YAML text (8 MiB: an ASCII map of 2800 x 2800 characters)
MAX_YAML_DEPTH = 64  # nested sequences and mappings
MAX_YAML_ALIASES = 10_000  # alias uses (*name) in one document
MAX_YAML_NODES = 1_000_000  # scalars, sequences and mappings, every alias expanded

# --- arrays -------------------------------------------------------------------------
MAX_ARRAY_BYTES = 2**30  # bytes of one .npy array or .npz member, decompressed (1 GiB)
_NPY_HEADER_SLACK = 2**16  # bytes a .npy header may add to its data (numpy caps headers at 10 000)

# --- numbers a scenario or BARN file may give ----------------------------------------
MIN_RESOLUTION = 1e-4  # m per map cell
MAX_RESOLUTION = 1e3  # m per map cell
MAX_MAP_CELLS = 10**8  # cells of one map layer (10 000 x 10 000)
MAX_COORDINATE = 1e6  # m: |x| and |y| of any position, the map's corners included
MAX_LENGTH = 1e6  # m: any length (radius, range, tolerance, standard deviation, size)
MAX_DURATION = 3600.0  # s: any time or duration (control period, horizon, delay, phase, time limit)
MAX_SPEED = 1e3  # m/s
MAX_ANGULAR_RATE = 1e3  # rad/s
MAX_ACCELERATION = 1e4  # m/s^2 and rad/s^2
MAX_MAGNITUDE = 1e6  # |value| of any other number (a critic's parameter, a phase in degrees, ...)
MAX_BEAMS = 100_000  # lidar beams per scan
MAX_STEPS = 100_000  # control cycles of one episode (max_steps)
MAX_COUNT = 100_000  # items of any list a file gives (moving obstacles, waypoints, rectangles, ...)


# =====================================================================================
# Messages
# =====================================================================================

class _BoundedRepr(reprlib.Repr):
    """reprlib with a few elements per level and a few levels: shared or recursive
    structures (what YAML aliases build) cost a bounded amount to show."""

    def __init__(self, limit: int):
        super().__init__()
        self.maxlevel = 3
        self.maxtuple = self.maxlist = self.maxarray = self.maxdict = 6
        self.maxset = self.maxfrozenset = self.maxdeque = 6
        self.maxstring = self.maxother = self.maxlong = max(limit, 12)

    def repr_int(self, x, level):
        if abs(x).bit_length() > 256:  # Python refuses str() of ints over 4300 digits
            return f"<an integer of {abs(x).bit_length()} bits>"
        return super().repr_int(x, level)

    def repr_bytes(self, x, level):
        return repr(x[: self.maxstring])


def short_repr(value: Any, limit: int = 80) -> str:
    """repr(value) in at most ``limit`` characters, formatting a bounded part of it."""
    try:
        text = _BoundedRepr(limit).repr(value)
    except Exception:  # a value whose repr fails still gets named
        text = f"<{type(value).__name__}>"
    return clip(text, limit)


def clip(text: str, limit: int = 200) -> str:
    """``text`` cut to ``limit`` characters, with "..." where it was cut."""
    text = str(text)
    return text if len(text) <= limit else text[: max(limit - 3, 0)] + "..."


def is_file(path: Union[str, os.PathLike]) -> bool:
    """Path.is_file() that says False for names the system cannot take (too long, NUL)."""
    try:
        return Path(path).is_file()
    except (OSError, ValueError):
        return False


# =====================================================================================
# YAML
# =====================================================================================

class YamlLimitError(yaml.YAMLError):
    """A document over one of the YAML limits; ``mark`` says where reading stopped."""

    def __init__(self, problem: str, mark=None):
        super().__init__(problem)
        self.problem = problem
        self.mark = mark


class LimitedSafeLoader(yaml.SafeLoader):
    """yaml.SafeLoader that counts, while composing, the nesting depth, the alias uses
    and the nodes of the document with every alias expanded, and stops at a limit.

    PyYAML builds an alias as a shared reference, so a bomb costs little to load;
    it is whatever walks the result (a check, a message) that would expand it.
    Counting expanded nodes here bounds all of them at once."""

    def __init__(self, stream):
        super().__init__(stream)
        self._depth = 0  # open sequences and mappings, aliases expanded
        self._reach = 0  # the deepest self._depth within the node being composed
        self._aliases = 0
        self._nodes = 0
        self._sizes = {}  # id(anchored node) -> (its nodes, its height), aliases expanded

    def _count(self, nodes: int, mark, through_alias: bool) -> None:
        self._nodes += nodes
        if self._nodes > MAX_YAML_NODES:
            how = " through its aliases (*name)" if through_alias or self._aliases else ""
            raise YamlLimitError(f"the document expands to more than {MAX_YAML_NODES} nodes{how}: "
                                 f"refused (the limit is fgdwa.file_limits.MAX_YAML_NODES)", mark)

    def _reach_to(self, depth: int, mark, through_alias: bool) -> None:
        if depth > MAX_YAML_DEPTH:
            how = " once its aliases (*name) are expanded" if through_alias else ""
            raise YamlLimitError(f"sequences and mappings nested more than {MAX_YAML_DEPTH} deep{how}: refused "
                                 f"(the limit is fgdwa.file_limits.MAX_YAML_DEPTH)", mark)
        self._reach = max(self._reach, depth)

    def compose_node(self, parent, index):
        event = self.peek_event()
        if isinstance(event, yaml.AliasEvent):
            self._aliases += 1
            if self._aliases > MAX_YAML_ALIASES:
                raise YamlLimitError(f"more than {MAX_YAML_ALIASES} alias uses (*name): refused (the limit is "
                                     f"fgdwa.file_limits.MAX_YAML_ALIASES)", event.start_mark)
            node = super().compose_node(parent, index)  # the anchored node, or an error for an unknown alias
            size = self._sizes.get(id(node))
            if size is None:
                raise YamlLimitError(f"the alias *{clip(event.anchor, 40)} is used inside the node it names "
                                     f"(a structure that holds itself): refused", event.start_mark)
            nodes, height = size
            self._count(nodes, event.start_mark, True)
            self._reach_to(self._depth + height, event.start_mark, True)
            return node
        start, outer_reach = self._depth, self._reach
        self._reach = start
        if isinstance(event, (yaml.SequenceStartEvent, yaml.MappingStartEvent)):
            self._depth += 1
            self._reach_to(self._depth, event.start_mark, False)
        self._count(1, event.start_mark, False)
        before = self._nodes
        node = super().compose_node(parent, index)
        self._depth = start
        if getattr(event, "anchor", None) is not None:
            self._sizes[id(node)] = (self._nodes - before + 1, self._reach - start)
        self._reach = max(outer_reach, self._reach)
        return node


def _size_error(size: int, where: str, limit: int) -> FgdwaError:
    return FgdwaError(f"{where}: {size} bytes of text or more, over the limit of {limit} "
                      f"(fgdwa.file_limits.MAX_YAML_BYTES): refused")


def read_text(path: Union[str, os.PathLike], where: str, max_bytes: Optional[int] = None) -> str:
    """The UTF-8 text of a file of at most ``max_bytes`` bytes (default MAX_YAML_BYTES),
    reading no more than that."""
    max_bytes = MAX_YAML_BYTES if max_bytes is None else max_bytes
    with open(path, "rb") as handle:
        data = handle.read(max_bytes + 1)
    if len(data) > max_bytes:
        raise _size_error(len(data), where, max_bytes)
    return data.decode("utf-8")


def load_yaml(text: str, where: str, loader: type = LimitedSafeLoader) -> Any:
    """The YAML document ``text`` read by ``loader`` (a LimitedSafeLoader), every
    problem an FgdwaError naming ``where`` and, when it can, the line and column."""
    if not isinstance(text, str):
        raise FgdwaError(f"{where}: expected YAML text, got {type(text).__name__}")
    size = len(text) if len(text) > MAX_YAML_BYTES else len(text.encode("utf-8", "surrogatepass"))
    if size > MAX_YAML_BYTES:  # a character takes one to four bytes
        raise _size_error(size, where, MAX_YAML_BYTES)
    try:
        return yaml.load(text, Loader=loader)  # noqa: S506 (a SafeLoader subclass)
    except YamlLimitError as error:
        raise FgdwaError(f"{where}{_at(error.mark)}: {error.problem}") from None
    except yaml.MarkedYAMLError as error:
        mark = error.problem_mark or error.context_mark
        problem = clip(error.problem or error.context or "malformed YAML")
        if mark is None:
            raise FgdwaError(f"{where}: malformed YAML: {problem}") from None
        lines = text.splitlines()
        line = lines[mark.line] if 0 <= mark.line < len(lines) else ""
        raise FgdwaError(f"{where}: malformed YAML{_at(mark)}: {problem} "
                         f"(line {mark.line + 1} = {short_repr(line.strip())})") from None
    except yaml.YAMLError as error:
        raise FgdwaError(f"{where}: malformed YAML: {clip(error)}") from None
    except (ValueError, OverflowError) as error:  # e.g. an integer of more than 4300 digits
        raise FgdwaError(f"{where}: a value of the YAML cannot be read ({clip(error)})") from None


def _at(mark) -> str:
    return "" if mark is None else f" at line {mark.line + 1}, column {mark.column + 1}"


# =====================================================================================
# Arrays
# =====================================================================================

def _npy_header(handle, where: str, max_bytes: int) -> tuple:
    """(shape, dtype) from a .npy header, refusing an array of more than ``max_bytes``."""
    try:
        version = np.lib.format.read_magic(handle)
        if version == (1, 0):
            shape, _, dtype = np.lib.format.read_array_header_1_0(handle)
        elif version in ((2, 0), (3, 0)):  # 3.0 differs only in allowing UTF-8 field names
            shape, _, dtype = np.lib.format.read_array_header_2_0(handle)
        else:
            raise ValueError(f"unknown .npy format version {version}")
    except (ValueError, EOFError, OSError, SyntaxError, TypeError) as error:
        raise FgdwaError(f"{where}: not a readable .npy array ({clip(error)})") from None
    count = math.prod(shape)
    size = count * dtype.itemsize
    if size > max_bytes:
        raise FgdwaError(f"{where}: an array of shape {clip(shape, 80)} and dtype {dtype} takes {size} bytes, over "
                         f"the limit of {max_bytes} (fgdwa.file_limits.MAX_ARRAY_BYTES): refused unread")
    return shape, dtype


def npy_shape(path: Union[str, os.PathLike], where: str, max_bytes: Optional[int] = None) -> tuple:
    """(shape, dtype) of a .npy file, read from its header only."""
    with open(path, "rb") as handle:
        return _npy_header(handle, where, MAX_ARRAY_BYTES if max_bytes is None else max_bytes)


@contextlib.contextmanager
def unreadable_as_error(where: str, kind: str, also: tuple = ()):
    """Turns what the file system or numpy raise on a missing or unreadable file, and the
    exception types ``also`` (a damaged archive's), into FgdwaError naming ``where``
    ("no such file", "not a readable ``kind`` (why)"); FgdwaError passes."""
    try:
        yield
    except FgdwaError:
        raise
    except FileNotFoundError:
        raise FgdwaError(f"{where}: no such file") from None
    except (OSError, ValueError, EOFError) as error:
        raise FgdwaError(f"{where}: not a readable {kind} ({clip(error)})") from None
    except also as error:
        raise FgdwaError(f"{where}: not a readable {kind} ({type(error).__name__}: {clip(error)})") from None


def load_npy(path: Union[str, os.PathLike], where: str, max_bytes: Optional[int] = None) -> np.ndarray:
    """A .npy array of at most ``max_bytes`` bytes (default MAX_ARRAY_BYTES), its size read
    from the header first; no pickled objects."""
    limit = MAX_ARRAY_BYTES if max_bytes is None else max_bytes
    with unreadable_as_error(where, ".npy file"), open(path, "rb") as handle:
        _npy_header(handle, where, limit)
        handle.seek(0)
        return np.lib.format.read_array(handle, allow_pickle=False)


def npz_names(archive: zipfile.ZipFile) -> list:
    """The keys of an .npz archive (its members' names without .npy), from the directory alone."""
    return [name[:-4] if name.endswith(".npy") else name for name in archive.namelist()]


def read_npz_member(archive: zipfile.ZipFile, key: str, where: str, max_bytes: Optional[int] = None) -> np.ndarray:
    """Member ``key`` of an .npz archive, refused before decompression when the zip
    directory or the .npy header says it is larger than ``max_bytes``."""
    limit = MAX_ARRAY_BYTES if max_bytes is None else max_bytes
    try:
        info = archive.getinfo(key + ".npy")
    except KeyError:  # np.savez names members KEY.npy; np.load also takes a bare KEY
        info = archive.getinfo(key)
    if info.file_size > limit + _NPY_HEADER_SLACK:
        raise FgdwaError(f"{where}: key '{key}': {info.file_size} bytes decompressed, over the limit of {limit} "
                         f"(fgdwa.file_limits.MAX_ARRAY_BYTES): refused unread")
    with archive.open(info) as handle:
        _npy_header(handle, f"{where}: key '{key}'", limit)
    with archive.open(info) as handle:
        return np.lib.format.read_array(handle, allow_pickle=False)
