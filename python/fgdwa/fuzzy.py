"""Fuzzy weight controllers from configuration, and the paper's preset (their
control surfaces are drawn by :mod:`fgdwa.plot.fuzzy`).

A configuration is a mapping (from code or YAML)::

    resolution: 1001                # optional: output grid points for the centroid
    inputs:                         # name -> variable, in order
      I: {domain: [0, 2]}           # no terms: the uniform partition S, M, L
      D:
        domain: [0, 5]
        terms:                      # name -> shape, or a list of names (uniform partition)
          S: uniform                # this term's shape in the uniform partition of S, M, L
          M: {gaussian: [2.5, 1.0]}
          L: {trapezoid: [2.5, 4.0, 5.0, 5.0]}
    outputs:
      beta: {domain: [0, 1]}
    rules:
      - IF I is S AND D is S THEN beta is S
      - {if: {I: M, D: S}, then: {beta: M}}

Shapes are ``triangle: [a, b, c]``, ``trapezoid: [a, b, c, d]`` and
``gaussian: [mean, sigma]``. Unknown keys and wrong types raise FgdwaError
naming the key, e.g. ``inputs.D.terms.M``.
"""

from __future__ import annotations

import math
import numbers
from pathlib import Path
from typing import Any, Mapping, Union

from fgdwa._core import (
    FgdwaError,
    FuzzyRule,
    FuzzyVariable,
    MamdaniEngine,
    MembershipFunction,
    mover_fuzzy_controller,
    paper_fuzzy_controller,
)
from fgdwa.file_limits import clip, is_file, load_yaml, read_text, short_repr

__all__ = [
    "engine_from_dict",
    "engine_from_yaml",
    "engine_to_dict",
    "paper_controller_config",
    "mover_fuzzy_controller",
    "paper_fuzzy_controller",
]

_SHAPES = {"triangle": 3, "trapezoid": 4, "gaussian": 2}
MAX_RESOLUTION = 100_001  # output grid points of the centroid (the engine holds a few arrays of this many)
_DEFAULT_TERMS = ("S", "M", "L")

# Table 3 (beta) and Table 4 (delta): rows D, columns I.
_PAPER_BETA = (("S", "M", "L"), ("S", "M", "L"), ("S", "M", "M"))
_PAPER_DELTA = (("S", "S", "S"), ("M", "M", "M"), ("L", "L", "M"))


def _type_name(value: Any) -> str:
    return type(value).__name__


def _mapping(value: Any, where: str) -> Mapping:
    if not isinstance(value, Mapping):
        raise FgdwaError(f"{where}: expected a mapping, got {_type_name(value)}")
    return value


def _only_keys(value: Mapping, known: tuple, where: str) -> None:
    for key in value:
        if key not in known:
            raise FgdwaError(f"{where}: unknown key {short_repr(key)} (known: {', '.join(known)})")


def _name(value: Any, where: str) -> str:
    if not isinstance(value, str):
        raise FgdwaError(f"{where}: expected a name (str), got {_type_name(value)} {short_repr(value)}")
    return value


def _number(value: Any, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise FgdwaError(f"{where}: expected a number, got {_type_name(value)} {short_repr(value)}")
    try:
        value = float(value)
    except OverflowError:  # an integer beyond float's range
        raise FgdwaError(f"{where} = {short_repr(value)}: must be finite") from None
    if not math.isfinite(value):
        raise FgdwaError(f"{where} = {value}: must be finite")
    return value


def _numbers(value: Any, count: int, where: str) -> list:
    if isinstance(value, (str, bytes, Mapping)) or not isinstance(value, (list, tuple)):
        raise FgdwaError(f"{where}: expected a list of {count} numbers, got {_type_name(value)} {short_repr(value)}")
    if len(value) != count:
        raise FgdwaError(f"{where}: expected {count} numbers, got {len(value)}")
    return [_number(v, f"{where}[{i}]") for i, v in enumerate(value)]


def _shape(value: Any, where: str) -> MembershipFunction:
    spec = _mapping(value, where)
    if len(spec) != 1:
        raise FgdwaError(f"{where}: expected one shape, e.g. {{triangle: [a, b, c]}}, "
                         f"got keys {short_repr(list(spec))}")
    (shape, params), = spec.items()
    if shape not in _SHAPES:
        raise FgdwaError(f"{where}: unknown shape {short_repr(shape)} (known: {', '.join(_SHAPES)})")
    args = _numbers(params, _SHAPES[shape], f"{where}.{shape}")
    try:
        return getattr(MembershipFunction, shape)(*args)
    except FgdwaError as err:
        raise FgdwaError(f"{where}: {err}") from None


def _variable(name: Any, value: Any, where: str) -> FuzzyVariable:
    name = _name(name, f"{where} name")
    where = f"{where}.{clip(name, 80)}"
    spec = _mapping(value, where)
    _only_keys(spec, ("domain", "terms"), where)
    if "domain" not in spec:
        raise FgdwaError(f"{where}: missing key 'domain'")
    lo, hi = _numbers(spec["domain"], 2, f"{where}.domain")
    terms = spec.get("terms", list(_DEFAULT_TERMS))
    if isinstance(terms, (list, tuple)):
        names = [_name(t, f"{where}.terms[{i}]") for i, t in enumerate(terms)]
        return FuzzyVariable.uniform(name, (lo, hi), names)
    terms = _mapping(terms, f"{where}.terms")
    if not terms:
        raise FgdwaError(f"{where}.terms: needs at least one term")
    names = [_name(t, f"{where}.terms name") for t in terms]
    uniform = None
    shapes = {}
    for term, shape in terms.items():
        if shape == "uniform":
            if uniform is None:
                uniform = FuzzyVariable.uniform(name, (lo, hi), names).terms
            shapes[term] = uniform[term]
        else:
            shapes[term] = _shape(shape, f"{where}.terms.{clip(term, 80)}")
    return FuzzyVariable(name, (lo, hi), shapes)


def _variables(value: Any, where: str) -> list:
    spec = _mapping(value, where)
    if not spec:
        raise FgdwaError(f"{where}: needs at least one variable")
    return [_variable(name, var, where) for name, var in spec.items()]


def _clauses(value: Any, where: str) -> list:
    spec = _mapping(value, where)
    if not spec:
        raise FgdwaError(f"{where}: needs at least one 'variable: term'")
    return [(_name(k, f"{where} variable"), _name(v, f"{where}.{clip(k, 80)}")) for k, v in spec.items()]


def _rule(value: Any, where: str) -> FuzzyRule:
    if isinstance(value, str):
        try:
            return FuzzyRule.parse(value)
        except FgdwaError as err:
            raise FgdwaError(f"{where}: {err}") from None
    spec = _mapping(value, where)
    _only_keys(spec, ("if", "then"), where)
    for key in ("if", "then"):
        if key not in spec:
            raise FgdwaError(f"{where}: missing key {short_repr(key)}")
    return FuzzyRule(_clauses(spec["if"], f"{where}.if"), _clauses(spec["then"], f"{where}.then"))


def engine_from_dict(config: Mapping) -> MamdaniEngine:
    """A MamdaniEngine from a configuration mapping (see the module docstring).

    Raises FgdwaError naming the key at fault."""
    config = _mapping(config, "fuzzy configuration")
    _only_keys(config, ("resolution", "inputs", "outputs", "rules"), "fuzzy configuration")
    for key in ("inputs", "outputs", "rules"):
        if key not in config:
            raise FgdwaError(f"fuzzy configuration: missing key {short_repr(key)}")
    resolution = config.get("resolution", 1001)
    if isinstance(resolution, bool) or not isinstance(resolution, numbers.Integral):
        raise FgdwaError(f"resolution: expected an integer, got {_type_name(resolution)} {short_repr(resolution)}")
    if not 3 <= resolution <= MAX_RESOLUTION:
        raise FgdwaError(f"resolution = {short_repr(resolution)}: must be in [3, {MAX_RESOLUTION}] "
                         f"(grid points; fgdwa.fuzzy.MAX_RESOLUTION)")
    rules = config["rules"]
    if isinstance(rules, (str, bytes, Mapping)) or not isinstance(rules, (list, tuple)):
        raise FgdwaError(f"rules: expected a list of rules, got {_type_name(rules)}")
    return MamdaniEngine(_variables(config["inputs"], "inputs"), _variables(config["outputs"], "outputs"),
                         [_rule(r, f"rules[{i}]") for i, r in enumerate(rules)], int(resolution))


def engine_from_yaml(source: Union[str, Path]) -> MamdaniEngine:
    """A MamdaniEngine from YAML: a path to a file, or the YAML text itself."""
    where = "fuzzy configuration"
    text = source
    if isinstance(source, Path) or (isinstance(source, str) and "\n" not in source and is_file(source)):
        where = f"fuzzy configuration {clip(source, 4096)}"
        try:
            text = read_text(source, where)
        except (OSError, ValueError) as err:  # ValueError: not UTF-8
            raise FgdwaError(f"{where}: {clip(err)}") from None
    elif not isinstance(source, str):
        raise FgdwaError(f"fuzzy configuration: expected a path or YAML text, got {_type_name(source)}")
    config = load_yaml(text, where)
    if not isinstance(config, Mapping):
        # A one-line string that is not a file reads as a YAML scalar: say so.
        hint = f" (no file named {short_repr(source)})" if isinstance(config, str) else ""
        raise FgdwaError(f"{where}: expected a mapping at the top level, got {_type_name(config)}{hint}")
    return engine_from_dict(config)


def _variable_to_dict(variable: FuzzyVariable) -> dict:
    return {"domain": [variable.lo, variable.hi],
            "terms": {name: {mf.shape: list(mf.params)} for name, mf in variable.terms.items()}}


def engine_to_dict(engine: MamdaniEngine) -> dict:
    """The configuration that engine_from_dict turns back into the same engine."""
    return {
        "resolution": engine.resolution,
        "inputs": {v.name: _variable_to_dict(v) for v in engine.inputs},
        "outputs": {v.name: _variable_to_dict(v) for v in engine.outputs},
        "rules": [str(r) for r in engine.rules],
    }


def paper_controller_config() -> dict:
    """The paper's controller (Tables 3 and 4) as a configuration to edit and pass
    to engine_from_dict; unchanged, it builds the same engine as paper_fuzzy_controller()."""
    rules = []
    for d, (beta_row, delta_row) in enumerate(zip(_PAPER_BETA, _PAPER_DELTA)):
        for i in range(3):
            rules.append(f"IF I is {_DEFAULT_TERMS[i]} AND D is {_DEFAULT_TERMS[d]} "
                         f"THEN beta is {beta_row[i]} AND delta is {delta_row[i]}")
    return {
        "resolution": 1001,
        "inputs": {"I": {"domain": [0.0, 2.0], "terms": list(_DEFAULT_TERMS)},
                   "D": {"domain": [0.0, 5.0], "terms": list(_DEFAULT_TERMS)}},
        "outputs": {"beta": {"domain": [0.0, 1.0], "terms": list(_DEFAULT_TERMS)},
                    "delta": {"domain": [0.0, 5.0], "terms": list(_DEFAULT_TERMS)}},
        "rules": rules,
    }
