"""Files in and out: scenario YAML (``scenario_file`` with its readers
``scenario_values``, ``scenario_maps`` and ``scenario_checks``), the scenarios
built in code (``builtin``; the YAML ones ship in ``fgdwa/scenarios``), the BARN
challenge's worlds (``barn_data`` loads barn.npz, ``barn_convert`` makes it),
DynaBARN-style fields of moving discs written as scenario documents
(``dynamic_fields``), the DynaBARN worlds' data files (``dynabarn_data``) and ROS 1 bags (``rosbag_reader``). Every reader holds
its input to the limits of :mod:`fgdwa.file_limits`; data sets themselves are
never part of the package (docs/barn.md).
"""

from fgdwa.io.barn_convert import convert_barn_worlds, fill_holes, read_barn_world
from fgdwa.io.barn_data import (
    BARN_FIELD_SIZE,
    BarnDataset,
    BarnWorld,
    barn_score,
    describe_world_ids,
    find_barn_file,
    load_barn,
    parse_world_selection,
)
from fgdwa.io.dynabarn_data import DynabarnDataset, DynabarnWorld, find_dynabarn_file, load_dynabarn
from fgdwa.io.dynamic_fields import LEVELS, field_yaml, generate_field, write_field
from fgdwa.io.rosbag_reader import read_bag, topics
from fgdwa.io.scenario_file import load_scenario, scenario_from_dict, shipped_scenario_path, shipped_scenarios

__all__ = [
    "BARN_FIELD_SIZE",
    "BarnDataset",
    "BarnWorld",
    "DynabarnDataset",
    "DynabarnWorld",
    "LEVELS",
    "barn_score",
    "convert_barn_worlds",
    "describe_world_ids",
    "field_yaml",
    "fill_holes",
    "find_barn_file",
    "find_dynabarn_file",
    "generate_field",
    "load_barn",
    "load_dynabarn",
    "load_scenario",
    "parse_world_selection",
    "read_bag",
    "read_barn_world",
    "scenario_from_dict",
    "shipped_scenario_path",
    "shipped_scenarios",
    "topics",
    "write_field",
]
