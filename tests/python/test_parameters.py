"""Every parameter is declared once, in C++: each surface derives from the schema."""

import math
import pickle
from pathlib import Path

import pytest

import fgdwa
from fgdwa.params_doc import PARAMETER_SETS, parameter_reference
from fgdwa.io.scenario_values import ValueReader, param_keys

ROOT = Path(__file__).resolve().parents[2]


def leaves(cls):
    return [entry for entry in cls.schema() if entry["type"] != "group"]


def test_the_reference_page_is_the_schemas():
    assert (ROOT / "docs" / "parameters.md").read_text() == parameter_reference() + "\n", \
        "docs/parameters.md is stale: fgdwa params > docs/parameters.md"


@pytest.mark.parametrize("cls", PARAMETER_SETS, ids=lambda cls: cls.__name__)
def test_every_field_is_on_every_surface(cls):
    page = (ROOT / "docs" / "parameters.md").read_text()
    defaults = cls()
    # The ROS node reads each set's fields by the schema (the lidar's noise alone).
    ros_source = (ROOT / "cpp" / "ros" / "node_params.cpp").read_text()
    assert f"add_entries(c.{cls.name}, out)" in ros_source or cls is fgdwa.LidarParams
    for entry in leaves(cls):
        name = entry["name"]
        # Python: a readable attribute by its C++ name, dotted into nested sets.
        assert defaults.get(name) is not None or entry["type"] == "text"
        # The reference page (and so the ROS node's names, '/'-joined).
        assert f"`{cls.name}/{name.replace('.', '/')}`" in page
        assert entry["unit"] in page
        # Files: the key is taken (an angle in degrees as well).
        top = name.split(".")[0]
        assert top in param_keys(cls)
        if entry["unit"] == "rad" and "." not in name:
            assert name + "_deg" in param_keys(cls)


@pytest.mark.parametrize("cls", PARAMETER_SETS, ids=lambda cls: cls.__name__)
def test_set_get_and_pickle_round_trip(cls):
    params = cls()
    assert pickle.loads(pickle.dumps(params)) == params
    assert cls(**params.to_dict()) == params


def test_a_bound_broken_names_the_full_path_and_the_unit():
    with pytest.raises(fgdwa.FgdwaError, match=r"^navigator\.occupancy\.edge_margin = -1: must be >= 0 \(m\)$"):
        fgdwa.NavigatorParams(occupancy={"edge_margin": -1})
    params = fgdwa.NavigatorParams()
    with pytest.raises(fgdwa.FgdwaError, match=r"^tracker\.gate = 0: must be > 0 \(m\)$"):
        params.tracker.gate = 0.0
    with pytest.raises(fgdwa.FgdwaError, match="navigator.max_recoveries: expected an integer, got float"):
        params.max_recoveries = 1.5
    for value, why in ((-1.0, r"-1: must be >= 0"), (math.nan, r"nan: must be finite"), (1e300, r"1e\+300: must be <= 3600")):
        with pytest.raises(fgdwa.FgdwaError, match=rf"^planner\.moving_reach = {why} \(m\)$"):
            fgdwa.PlannerParams(moving_reach=value)


def test_an_unknown_name_says_did_you_mean():
    with pytest.raises(fgdwa.FgdwaError, match=r"unknown parameter 'n_v'; did you mean 'window\.n_v'"):
        fgdwa.PlannerParams(n_v=15)
    with pytest.raises(fgdwa.FgdwaError, match=r"did you mean 'stall_time'"):
        fgdwa.NavigatorParams(stal_time=1.0)
    assert fgdwa.nearest_names("planner/n_v", ["planner/window/n_v", "planner/dt"]) == ["planner/window/n_v"]


def test_nested_sets_take_dicts_dotted_names_and_attributes():
    params = fgdwa.PlannerParams(window={"n_v": 15}, **{"key_nodes.reach_radius": 0.5})
    assert (params.window.n_v, params.window.n_omega, params.key_nodes.reach_radius) == (15, 21, 0.5)
    params.window.n_omega = 9
    assert params.get("window.n_omega") == 9
    params.set("key_nodes.min_turn", 0.3)
    assert params.key_nodes.min_turn == 0.3


def test_relations_are_checked_when_the_set_is_built():
    with pytest.raises(fgdwa.FgdwaError, match=r"limits\.v_min = 2: must be <= v_max = 1"):
        fgdwa.RobotLimits(v_min=2.0, v_max=1.0)
    occupancy = fgdwa.OccupancyParams()
    occupancy.free = 0.7  # each field alone is in bounds
    with pytest.raises(fgdwa.FgdwaError, match="occupancy: need clamp_min <= free < occupied"):
        occupancy.validate()


def test_file_keys_take_degrees_only_under_deg(tmp_path):
    reader = ValueReader("<test>", tmp_path)
    fields = reader.param_fields(fgdwa.PlannerParams, {"key_nodes": {"min_turn_deg": 10}}, "overrides")
    assert fields == {"key_nodes.min_turn": 10 * math.pi / 180.0}
    assert fields["key_nodes.min_turn"] == fgdwa.KeyNodeParams().min_turn  # the C++ default is 10 degrees
    with pytest.raises(fgdwa.FgdwaError, match="overrides.key_nodes.min_turn = 10: .*must be < 3.14"):
        reader.param_fields(fgdwa.PlannerParams, {"key_nodes": {"min_turn": 10}}, "overrides")
