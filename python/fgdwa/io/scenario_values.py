"""Reading scenario YAML: a strict YAML loader, and the typed readers whose
every error names the file, the key path and the offending value.

Every number read is held to the limits of ``fgdwa.file_limits``: a position to
MAX_COORDINATE, a length to MAX_LENGTH, a time to MAX_DURATION, a count to
MAX_COUNT, and any number without a narrower limit to MAX_MAGNITUDE, so that no
file can hand the core a value it would choke on (docs/scenarios.md, Limits)."""

from __future__ import annotations

import difflib
import math
import re
from pathlib import Path
from typing import Any, Optional, Sequence, Union

import numpy as np
import yaml

from fgdwa._core import FgdwaError, critic_names
from fgdwa import file_limits as limits
from fgdwa.file_limits import LimitedSafeLoader, clip, is_file, load_yaml, short_repr


class _StrictLoader(LimitedSafeLoader):
    """The limited SafeLoader (fgdwa.file_limits) refusing duplicate keys and reading
    1e-3 as a number (YAML 1.1 wants 1.0e-3)."""

    def construct_mapping(self, node, deep=False):
        if isinstance(node, yaml.MappingNode):
            self.flatten_mapping(node)
            seen = set()
            for key_node, _ in node.value:
                key = self.construct_object(key_node, deep=True)
                try:
                    duplicate = key in seen
                except TypeError:
                    raise yaml.constructor.ConstructorError(None, None, f"unhashable key {short_repr(key)}",
                                                            key_node.start_mark) from None
                if duplicate:
                    raise yaml.constructor.ConstructorError(None, None, f"duplicate key {short_repr(key)}",
                                                            key_node.start_mark)
                seen.add(key)
        return super().construct_mapping(node, deep=deep)


_StrictLoader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"""^[-+]?(?:[0-9][0-9_]*)(?:\.[0-9_]*)?[eE][-+]?[0-9]+$"""),
    list("-+0123456789"))


def parse_yaml(text: str, where: str) -> Any:
    """A scenario document: strict YAML within the limits of fgdwa.file_limits."""
    return load_yaml(text, where, _StrictLoader)


def join_key(parent: str, child: Union[str, int]) -> str:
    if isinstance(child, int):
        return f"{parent}[{child}]"
    return f"{parent}.{child}" if parent else str(child)


def is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def param_keys(cls, prefix: str = "", allowed: Optional[Sequence[str]] = None) -> list:
    """The keys a file takes for parameter class ``cls`` (fields under ``prefix``):
    each field's name, and an angle's (unit rad) name + ``_deg`` for degrees."""
    out = []
    for entry in cls.schema():
        name = entry["name"][len(prefix):]
        if not entry["name"].startswith(prefix) or "." in name or (allowed is not None and name not in allowed):
            continue
        out.append(name)
        if entry["unit"] == "rad":
            out.append(name + "_deg")
    return out


class ValueReader:
    """Typed values from one YAML document; every error names ``where``, the key path and the value."""

    def __init__(self, where: str, base_dir: Path, default_name: str = "scenario"):
        self.where = where
        self.base_dir = base_dir
        self.default_name = default_name

    def fail(self, key: str, value: Any, problem: str):
        raise FgdwaError(f"{self.where}: {clip(key, 200)} = {short_repr(value)}: {clip(problem, 4000)}")

    def mapping(self, value: Any, key: str, allowed: Sequence[str], required: Sequence[str] = ()) -> dict:
        if not isinstance(value, dict):
            self.fail(key, value, f"expected a mapping with keys {', '.join(allowed)}")
        for name, item in value.items():
            if not isinstance(name, str) or name not in allowed:
                close = difflib.get_close_matches(clip(str(name), 100), allowed, n=1)
                hint = f"; did you mean {close[0]!r}?" if close else ""
                self.fail(join_key(key, str(name)), item, f"unknown key (known here: {', '.join(allowed)}){hint}")
        for name in required:
            if value.get(name) is None:
                self.fail(join_key(key, name), None, "required")
        return value

    def number(self, value: Any, key: str, low: Optional[float] = None, high: Optional[float] = None,
               low_open: bool = False, limit: str = "MAX_MAGNITUDE") -> float:
        """A finite number within [low, high] (or (low, high]), and within +-``limit``, the
        name of a constant of fgdwa.file_limits (default MAX_MAGNITUDE)."""
        if not is_number(value):
            self.fail(key, value, "expected a number")
        try:
            value = float(value)
        except OverflowError:  # an integer beyond float's range
            self.fail(key, value, "must be finite")
        if not math.isfinite(value):
            self.fail(key, value, "must be finite")
        if low is not None and (value <= low if low_open else value < low):
            self.fail(key, value, f"must be {'>' if low_open else '>='} {low:g}")
        if high is not None and value > high:
            self.fail(key, value, f"must be <= {high:g}")
        bound = getattr(limits, limit)
        if abs(value) > bound:
            self.fail(key, value, f"must be within +-{bound:g} (fgdwa.file_limits.{limit})")
        return value

    def length(self, value: Any, key: str, positive: bool = False) -> float:
        """A length in metres: >= 0 (> 0 when ``positive``), at most MAX_LENGTH."""
        return self.number(value, key, low=0.0, low_open=positive, limit="MAX_LENGTH")

    def duration(self, value: Any, key: str, positive: bool = False) -> float:
        """A time in seconds: >= 0 (> 0 when ``positive``), at most MAX_DURATION."""
        return self.number(value, key, low=0.0, low_open=positive, limit="MAX_DURATION")

    def integer(self, value: Any, key: str, low: Optional[int] = None, limit: str = "MAX_COUNT") -> int:
        """An integer >= ``low`` and at most ``limit``, the name of a constant of
        fgdwa.file_limits (default MAX_COUNT)."""
        if isinstance(value, bool) or not isinstance(value, int):
            self.fail(key, value, "expected an integer")
        if low is not None and value < low:
            self.fail(key, value, f"must be >= {low}")
        bound = getattr(limits, limit)
        if abs(value) > bound:
            self.fail(key, value, f"must be at most {bound} (fgdwa.file_limits.{limit})")
        return int(value)

    def boolean(self, value: Any, key: str) -> bool:
        if not isinstance(value, bool):
            self.fail(key, value, "expected true or false")
        return value

    def string(self, value: Any, key: str) -> str:
        if not isinstance(value, str):
            self.fail(key, value, "expected a string")
        return value

    def point(self, value: Any, key: str, limit: str = "MAX_COORDINATE") -> tuple:
        """[x, y] or {x, y}, each within +-``limit`` (default MAX_COORDINATE, metres)."""
        if isinstance(value, dict):
            self.mapping(value, key, ("x", "y"), required=("x", "y"))
            return (self.number(value["x"], join_key(key, "x"), limit=limit),
                    self.number(value["y"], join_key(key, "y"), limit=limit))
        if not isinstance(value, (list, tuple)) or len(value) != 2:
            self.fail(key, value, "expected [x, y] in metres")
        return tuple(self.number(v, join_key(key, i), limit=limit) for i, v in enumerate(value))

    def points(self, value: Any, key: str, minimum: int) -> np.ndarray:
        if not isinstance(value, (list, tuple)) or len(value) < minimum:
            self.fail(key, value, f"expected a list of at least {minimum} [x, y] points")
        self.count(value, key)
        return np.array([self.point(v, join_key(key, i)) for i, v in enumerate(value)], dtype=float)

    def keyframes(self, value: Any, key: str) -> np.ndarray:
        """(k, 3) timed keyframes [t s, x m, y m], k >= 2, each checked by name."""
        if not isinstance(value, (list, tuple)) or len(value) < 2:
            self.fail(key, value, "expected a list of at least 2 [t, x, y] keyframes (s, m, m)")
        self.count(value, key)
        rows = []
        for i, frame in enumerate(value):
            ikey = join_key(key, i)
            if not isinstance(frame, (list, tuple)) or len(frame) != 3:
                self.fail(ikey, frame, "expected [t, x, y] (s, m, m)")
            rows.append((self.duration(frame[0], join_key(ikey, 0)), *self.point(frame[1:], ikey)))
        return np.array(rows, dtype=float)

    def count(self, items: list, key: str) -> list:
        """``items``, refused when longer than MAX_COUNT."""
        if len(items) > limits.MAX_COUNT:
            self.fail(key, f"<a list of {len(items)} items>",
                      f"more than {limits.MAX_COUNT} items (fgdwa.file_limits.MAX_COUNT)")
        return items

    def file(self, value: Any, key: str, suffixes: Sequence[str]) -> Path:
        name = self.string(value, key)
        try:
            path = Path(name).expanduser()
        except RuntimeError:  # ~user of no user
            path = Path(name)
        if not path.is_absolute():
            path = self.base_dir / path
        if not is_file(path):
            self.fail(key, value, f"no such file ({clip(path, 300)})")
        if path.suffix.lower() not in suffixes:
            self.fail(key, value, f"expected a {' or '.join(suffixes)} file")
        return path

    def core(self, key: str, value: Any, build):
        """Calls a core constructor; its complaint is reported at ``key``."""
        try:
            return build()
        except FgdwaError as error:
            self.fail(key, value, str(error))
        except (TypeError, ValueError, RuntimeError) as error:
            self.fail(key, value, f"rejected ({error})".splitlines()[0])

    def list_of(self, value: Any, key: str) -> list:
        if value is None:
            return []
        if not isinstance(value, list):
            self.fail(key, value, "expected a list")
        return self.count(value, key)

    def critics(self, value: Any, key: str) -> list:
        if not isinstance(value, list) or not value:
            self.fail(key, value, "expected a list of critics: {name, weight, params}")
        self.count(value, key)
        known = critic_names()
        critics = []
        for i, item in enumerate(value):
            ckey = join_key(key, i)
            self.mapping(item, ckey, ("name", "weight", "params"), required=("name",))
            name = self.string(item["name"], join_key(ckey, "name"))
            if name not in known:
                self.fail(join_key(ckey, "name"), name, f"unknown critic (known: {', '.join(known)})")
            weight = self.number(item.get("weight", 1.0), join_key(ckey, "weight"), low=0.0)
            params = item.get("params") or {}
            if not isinstance(params, dict):
                self.fail(join_key(ckey, "params"), params, "expected a mapping of numbers and words")
            for pname, pvalue in params.items():
                pkey = join_key(join_key(ckey, "params"), clip(str(pname), 100))
                if not isinstance(pname, str) or not (is_number(pvalue) or isinstance(pvalue, str)):
                    self.fail(pkey, pvalue, "expected a number or a word")
                if is_number(pvalue):
                    self.number(pvalue, pkey)
            critics.append({"name": name, "weight": weight, "params": dict(params)})
        return critics

    def param_fields(self, cls, value: Any, key: str, allowed: Optional[Sequence[str]] = None,
                     prefix: str = "") -> dict:
        """The fields of parameter class ``cls`` a mapping gives, as {dotted name: value}:
        names as in its schema, a nested set as a mapping, an angle (unit rad) in degrees
        under its name + ``_deg``. Each value is checked against its field's bounds;
        errors name ``key``. ``allowed``: the top-level names taken (default all)."""
        schema = {entry["name"]: entry for entry in cls.schema()}
        keys = param_keys(cls, prefix, allowed)
        self.mapping(value, key, keys)
        out = {}
        for name, item in value.items():
            ikey = join_key(key, name)
            degrees = name.endswith("_deg") and prefix + name not in schema
            field = prefix + (name[:-len("_deg")] if degrees else name)
            entry = schema[field]
            if entry["type"] == "group":
                out.update(self.param_fields(cls, item, ikey, prefix=field + "."))
                continue
            if entry["type"] == "critics":
                item = self.critics(item, ikey)
            elif degrees:
                # As the C++ side turns degrees into radians: deg * pi / 180.
                item = self.number(item, ikey) * math.pi / 180.0
            probe = cls()
            self.core(ikey, value[name], lambda: probe.set(field, item))
            out[field] = probe.get(field) if entry["type"] != "critics" else item
        return out
