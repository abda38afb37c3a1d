"""Files never crash, hang or lie: YAML over its limits (size, aliases, nesting) is refused
with FgdwaError naming the file, and messages format a bounded part of any value."""

import pytest

import fgdwa
from fgdwa import file_limits
from fgdwa.file_limits import MAX_YAML_ALIASES, MAX_YAML_BYTES, MAX_YAML_DEPTH, short_repr
from fgdwa.fuzzy import engine_from_yaml
from fgdwa.io.scenario_file import load_scenario


def refused(load, source, *fragments):
    """``load(source)`` raises FgdwaError (not another exception) holding every fragment."""
    with pytest.raises(fgdwa.FgdwaError) as info:
        load(source)
    message = str(info.value)
    for fragment in fragments:
        assert fragment in message, f"{fragment!r} not in {message!r}"
    assert len(message) < 1000, message
    return message


def billion_laughs(top_key="map"):
    """Nine levels of nine aliases: 10^9 strings once expanded, a few hundred bytes written."""
    lines = ['a0: &a0 ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]']
    lines += [f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 9) + "]" for i in range(1, 10)]
    lines.append(f"{top_key}: *a9")
    return "\n".join(lines) + "\n"


# --- aliases ------------------------------------------------------------------------------------------------------


def test_alias_bomb_in_scenario_text_is_refused():
    refused(load_scenario, billion_laughs(), "<text>", "aliases", "MAX_YAML_NODES")


def test_alias_bomb_in_scenario_file_names_the_file(tmp_path):
    path = tmp_path / "bomb.yaml"
    path.write_text(billion_laughs())
    refused(load_scenario, path, str(path), "aliases", "line 7")


def test_alias_bomb_in_fuzzy_file_names_the_file(tmp_path):
    path = tmp_path / "fuzzy_bomb.yaml"
    path.write_text(billion_laughs("inputs"))
    refused(engine_from_yaml, path, f"fuzzy configuration {path}", "aliases")
    refused(engine_from_yaml, billion_laughs("inputs"), "fuzzy configuration", "aliases")


def test_too_many_alias_uses_are_refused():
    text = "a: &a 1\nb: [" + ", ".join(["*a"] * (MAX_YAML_ALIASES + 1)) + "]\n"
    refused(load_scenario, text, "<text>", f"more than {MAX_YAML_ALIASES} alias uses")


def test_a_few_aliases_still_load():
    text = """\
    map: {size: [3, 2], resolution: 0.5}
    start: &here [0.75, 0.75]
    goal: [2.25, 1.25]
    moving_obstacles:
      - {radius: 0.1, start: *here, velocity: [0.0, 0.0]}
    """
    scenario = load_scenario("\n".join(line[4:] for line in text.splitlines()))
    assert tuple(scenario.world.movers[0].state_at(0.0)[0]) == pytest.approx((0.75, 0.75))


def test_an_alias_inside_its_own_node_is_refused():
    refused(load_scenario, "map: &a [*a]\nstart: [1, 1]\ngoal: [2, 2]\n", "<text>", "*a", "holds itself")


# --- nesting ------------------------------------------------------------------------------------------------------


def test_deep_nesting_is_refused_not_a_recursion_error():
    text = "map: " + "[" * 5000 + "]" * 5000 + "\n"
    refused(load_scenario, text, "<text>", f"nested more than {MAX_YAML_DEPTH} deep")
    block = "map:\n" + "".join("  " * i + "-\n" for i in range(1, 200))
    refused(load_scenario, block, f"nested more than {MAX_YAML_DEPTH} deep")
    refused(engine_from_yaml, "inputs: " + "{a: " * 5000 + "1" + "}" * 5000, "fuzzy configuration", "nested")


def test_nesting_built_from_a_chain_of_aliases_is_refused():
    lines = ["l0: &l0 [1]"] + [f"l{i}: &l{i} [*l{i - 1}]" for i in range(1, 200)] + ["map: *l199"]
    refused(load_scenario, "\n".join(lines), "deep once its aliases (*name) are expanded")


# --- size ---------------------------------------------------------------------------------------------------------


def test_oversized_scenario_file_is_refused(tmp_path):
    path = tmp_path / "big.yaml"
    path.write_text("# padding\n" * (MAX_YAML_BYTES // 10 + 1))
    refused(load_scenario, path, str(path), "over the limit", str(MAX_YAML_BYTES))


def test_oversized_text_is_refused_and_the_limit_is_read_at_call_time(monkeypatch):
    monkeypatch.setattr(file_limits, "MAX_YAML_BYTES", 100)
    text = "name: x\ndescription: " + "é" * 60 + "\n"  # 82 characters, 142 bytes of UTF-8
    refused(load_scenario, text, "<text>: 142 bytes", "over the limit of 100")
    refused(engine_from_yaml, text, "fuzzy configuration", "over the limit of 100")


def test_oversized_fuzzy_file_is_refused(tmp_path, monkeypatch):
    monkeypatch.setattr(file_limits, "MAX_YAML_BYTES", 1000)
    path = tmp_path / "fuzzy.yaml"
    path.write_text("#" * 2000 + "\n")
    refused(engine_from_yaml, path, str(path), "over the limit of 1000")


# --- values that cannot be read or shown ---------------------------------------------------------------------------


def test_an_integer_too_long_to_read_is_an_fgdwa_error():
    refused(load_scenario, "map: {size: [" + "9" * 5000 + ", 1]}\nstart: [1, 1]\ngoal: [2, 2]\n", "<text>")
    refused(engine_from_yaml, "resolution: " + "9" * 5000, "fuzzy configuration")


def test_an_integer_beyond_float_is_out_of_range_not_an_overflow():
    message = refused(load_scenario, "map: {size: [" + "9" * 400 + ", 1]}\nstart: [1, 1]\ngoal: [2, 2]\n",
                      "map.size[0]")
    assert "OverflowError" not in message


def test_long_one_line_sources_are_not_file_names():
    refused(load_scenario, "x" * 5000, "neither a shipped scenario")
    refused(load_scenario, "a: " + "b" * 5000, "unknown key")
    refused(load_scenario, "a\0b.yaml", "cannot read the scenario file")
    refused(engine_from_yaml, "a: " + "b" * 5000, "unknown key")


def test_duplicate_long_key_message_is_bounded():
    key = "k" * 100_000  # a simple key holds at most 1024 characters: these are explicit (?)
    refused(load_scenario, f"? {key}\n: 1\n? {key}\n: 2\n", "duplicate key")


def test_fuzzy_resolution_is_bounded():
    refused(engine_from_yaml, "resolution: 1000000000\ninputs: {}\noutputs: {}\nrules: []\n",
            "resolution = 1000000000", "MAX_RESOLUTION")


class _Counted:
    calls = 0

    def __repr__(self):
        _Counted.calls += 1
        return "x"


def test_short_repr_formats_a_bounded_part_of_shared_structures():
    value = [_Counted()] * 9
    for _ in range(6):  # 9^7 leaves, the shape an alias bomb loads into
        value = [value] * 9
    _Counted.calls = 0
    text = short_repr(value)
    assert len(text) <= 80
    assert _Counted.calls < 100
    assert short_repr(10 ** 5000).startswith("<an integer of")
    recursive = []
    recursive.append(recursive)
    assert len(short_repr(recursive)) <= 80


def test_a_bomb_given_as_a_dict_is_reported_briefly():
    value = ["lol"] * 9
    for _ in range(8):
        value = [value] * 9
    with pytest.raises(fgdwa.FgdwaError) as info:
        fgdwa.io.scenario_file.scenario_from_dict({"map": value, "start": [1, 1], "goal": [2, 2]})
    assert "map = " in str(info.value) and len(str(info.value)) < 1000
