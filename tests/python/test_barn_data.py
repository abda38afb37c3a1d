"""BARN maps: the barn.npz loader, the converter from the challenge's own files, and
world selections.

The data is not in the repository: the tests read FGDWA_BARN_DATA (barn.npz, or the
directory holding it and worlds/) or /work/shared/benchmarks/barn/, and skip when
neither is there.
"""

import argparse
import io
import re
import shutil
import struct
import zipfile

import numpy as np
import pytest

import fgdwa
from conftest import barn_locations
from fgdwa import FgdwaError
from fgdwa.bench.barn import barn_import_command, register_barn_commands
from fgdwa.io import (
    BarnDataset,
    barn_score,
    convert_barn_worlds,
    fill_holes,
    find_barn_file,
    load_barn,
    parse_world_selection,
)
from fgdwa.io.barn_data import GOAL, START

CONVERTED_WORLDS = (0, 150, 299)  # the worlds whose original files are in worlds/


@pytest.fixture(scope="module")
def raw(barn_file):
    with np.load(barn_file) as npz:
        return {key: npz[key] for key in npz.files}


@pytest.fixture(scope="module")
def world_dir():
    _, worlds, where = barn_locations()
    needed = [worlds / f"{kind}_{i}.{ext}" for i in CONVERTED_WORLDS for kind, ext in (("world", "world"), ("path", "npy"))]
    missing = [p.name for p in needed if not p.is_file()]
    if missing:
        pytest.skip(f"BARN challenge files not found in {worlds} ({where}): missing {', '.join(missing)}")
    return worlds


def _dilate(cells, half):
    """Max filter of size (2 half + 1)^2: obstacles grown by `half` cells each way."""
    padded = np.pad(cells, half)
    rows, cols = cells.shape
    out = np.zeros_like(cells)
    for dr in range(2 * half + 1):
        for dc in range(2 * half + 1):
            out |= padded[dr:dr + rows, dc:dc + cols]
    return out


# ---------------------------------------------------------------------------------
# The shared barn.npz
# ---------------------------------------------------------------------------------

def test_the_shared_file_holds_250_worlds_without_the_held_back_ones(barn):
    assert len(barn) == 250
    ids = barn.world_ids
    assert ids == sorted(ids) and len(set(ids)) == 250
    assert all(i % 6 != 3 for i in ids) and min(ids) == 0 and max(ids) == 299
    assert set(range(0, 300, 6)) <= set(ids)  # the challenge's local test set


def test_every_world_has_the_documented_shapes_task_and_frame(barn):
    for world in barn:
        assert isinstance(world.grid, fgdwa.OccupancyGrid)
        assert world.grid.shape == (50, 100)
        assert world.grid.resolution == 0.15
        assert world.grid.origin == (0.0, -1.5)
        assert world.field.shape == (30, 30) and world.field.dtype == np.uint8
        assert world.path.ndim == 2 and world.path.shape[1] == 2 and world.path.dtype == np.float64
        assert world.start == (3.0, 2.25, 0.0)
        assert world.goal == (13.0, 2.25)
        assert world.goal_radius == 1.0 and world.time_limit == 100.0
        assert 0 < world.optimal_time < 10


def test_grid_frame_row_zero_at_the_bottom_and_the_field_inside_it(barn):
    world = barn.world(0)
    grid = world.grid
    walls = np.array([[1.0, 0.075], [1.0, 4.425], [0.075, 2.25], [9.5, 0.075], [9.5, 4.425]])
    assert grid.occupied_at(walls).all()
    free = np.array([world.start[:2], world.goal, [1.0, 2.25], [12.0, 0.075], [12.0, 4.425]])
    assert not grid.occupied_at(free).any()
    cells = grid.cells
    r, c = np.meshgrid(np.arange(30), np.arange(30), indexing="ij")
    np.testing.assert_array_equal(cells[39 - r, 34 + c], world.field)
    # Field row 0 and row 29 are the side walls; outside the walled part, nothing.
    assert world.field[0].all() and world.field[29].all()
    assert not cells[:, 64:].any() and not cells[:10].any() and not cells[40:].any()


def test_reference_paths_lie_in_free_space_of_the_5x5_dilated_grid(barn):
    for world in barn:
        dilated = _dilate(world.grid.cells, 2)
        grown = fgdwa.OccupancyGrid(dilated, world.grid.resolution, world.grid.origin)
        assert not grown.occupied_at(world.path).any(), f"world {world.world_id}"
    # The path is in cell centres of the field: x in [5.175, 9.525], y in [0.075, 4.425].
    path = barn.world(0).path
    assert path[:, 0].min() >= 5.175 - 1e-9 and path[:, 0].max() <= 9.525 + 1e-9


def test_optimal_time_is_the_challenge_path_length_over_two(barn):
    # The challenge's cell-to-Gazebo conversion is offset from the cell centres by
    # (-0.1, +0.15) m in map (x, y); the optimal time includes that offset.
    for world in barn.select("0-299:6"):
        points = np.vstack([world.start[:2], world.path + (-0.1, 0.15), world.goal])
        length = np.hypot(*np.diff(points, axis=0).T).sum()
        assert world.optimal_time == pytest.approx(length / 2, abs=1e-12)


def test_arrays_handed_out_are_read_only(barn):
    world = barn[0]
    with pytest.raises(ValueError):
        world.path[0, 0] = 0.0
    with pytest.raises(ValueError):
        world.field[0, 0] = 0


# ---------------------------------------------------------------------------------
# Selection by position, by id, by selection string
# ---------------------------------------------------------------------------------

def test_worlds_by_position_and_by_world_id(barn):
    assert barn[0].world_id == 0
    assert barn[3].world_id == 4  # world 3 is held back
    assert barn[-1].world_id == 299
    assert barn.world(150).world_id == 150
    assert barn.index_of(150) == barn.world_ids.index(150)
    np.testing.assert_array_equal(barn.world(150).path, barn[barn.index_of(150)].path)
    assert 150 in barn and 3 not in barn
    with pytest.raises(FgdwaError, match="world 3 is not in this data set"):
        barn.world(3)
    with pytest.raises(FgdwaError, match="out of range"):
        barn[250]
    with pytest.raises(FgdwaError, match="by position"):
        barn["0"]


def test_select_reads_world_ids(barn):
    assert [w.world_id for w in barn.select("0,6,12")] == [0, 6, 12]
    first = barn.select_ids("0-49")
    assert first == [i for i in range(50) if i % 6 != 3] and len(first) == 42
    assert len(barn.select("all")) == 250
    assert barn.select_ids("0-299:6") == list(range(0, 300, 6))
    assert barn.select_ids([12, 0, 12]) == [12, 0]
    assert barn.select_ids(150) == [150]
    with pytest.raises(FgdwaError, match="world 3 is not in the data set"):
        barn.select("0,3")
    with pytest.raises(FgdwaError, match="world 9 is not in this data set"):
        barn.select([0, 9])


def test_parse_world_selection_without_a_data_set():
    assert parse_world_selection("0,6,12") == [0, 6, 12]
    assert parse_world_selection("0-49") == list(range(50))
    assert parse_world_selection(" 5 - 7 , 2, 6 ") == [5, 6, 7, 2]
    assert parse_world_selection("0-20:6") == [0, 6, 12, 18]
    assert parse_world_selection("ALL", [4, 1, 2]) == [1, 2, 4]
    assert parse_world_selection("0-10", [1, 3, 20]) == [1, 3]


@pytest.mark.parametrize("text, message", [
    ("", "empty"),
    ("all", "needs a data set"),
    ("7-2", "runs backwards"),
    ("0-9:0", "step >= 1"),
    ("zero", "cannot read 'zero'"),
    ("1,,2", "cannot read ''"),
    ("-3", "cannot read '-3'"),
    ("1.5", "cannot read '1.5'"),
])
def test_parse_world_selection_rejects(text, message):
    with pytest.raises(FgdwaError, match=message):
        parse_world_selection(text)


def test_a_range_must_keep_one_available_world():
    with pytest.raises(FgdwaError, match="no world of '3-3'"):
        parse_world_selection("3-3", [0, 1, 2])


# ---------------------------------------------------------------------------------
# Converting the challenge's files
# ---------------------------------------------------------------------------------

def test_converter_reproduces_the_shared_file_for_its_three_worlds(world_dir, raw, tmp_path):
    out = tmp_path / "converted.npz"
    convert_barn_worlds(world_dir, out)
    with np.load(out) as npz:
        got = {key: npz[key] for key in npz.files}
    assert sorted(got) == sorted(
        ["world_ids", "grids", "fields", "optimal_time", "resolution", "origin", "start", "goal", "goal_radius",
         "time_limit"] + [f"path_{i}" for i in CONVERTED_WORLDS])
    np.testing.assert_array_equal(got["world_ids"], CONVERTED_WORLDS)
    rows = [int(np.flatnonzero(raw["world_ids"] == i)[0]) for i in CONVERTED_WORLDS]
    for key in ("world_ids", "grids", "fields", "optimal_time"):
        expected = raw[key][rows]
        assert got[key].dtype == expected.dtype and got[key].shape == expected.shape, key
        assert np.array_equal(got[key], expected), key
    for key in ["resolution", "origin", "start", "goal", "goal_radius", "time_limit"] + [
            f"path_{i}" for i in CONVERTED_WORLDS]:
        assert got[key].dtype == raw[key].dtype and got[key].shape == raw[key].shape, key
        assert np.array_equal(got[key], raw[key]), key
    assert len(load_barn(out)) == 3


def test_hole_filling_matters_for_the_converted_worlds(world_dir, raw):
    # Worlds 150 and 299 have solid blocks whose inner cylinders were dropped.
    from fgdwa.io.barn_convert import _cylinder_positions

    k = int(np.flatnonzero(raw["world_ids"] == 299)[0])
    count = sum(1 for _, _, y in _cylinder_positions(world_dir / "world_299.world") if y >= 5.1)
    assert count < int(raw["fields"][k].sum())


def test_converter_takes_a_selection_and_the_challenge_layout(world_dir, raw, tmp_path):
    challenge = tmp_path / "BARN"
    (challenge / "path_files").mkdir(parents=True)
    for i in CONVERTED_WORLDS:
        shutil.copy(world_dir / f"world_{i}.world", challenge)
        shutil.copy(world_dir / f"path_{i}.npy", challenge / "path_files")
    out = tmp_path / "sub" / "one.npz"
    convert_barn_worlds(challenge, out, world_ids=[150])
    one = load_barn(out)
    assert one.world_ids == [150]
    np.testing.assert_array_equal(one.world(150).path, raw["path_150"])
    convert_barn_worlds(challenge, out, world_ids="0,299")
    assert load_barn(out).world_ids == [0, 299]
    assert not list(out.parent.glob("*.partial"))


def test_import_command_writes_the_file_and_reports(world_dir, tmp_path, capsys):
    out = tmp_path / "barn.npz"
    assert barn_import_command(str(world_dir), str(out)) == 0
    assert "3 BARN worlds" in capsys.readouterr().out
    assert load_barn(out).world_ids == list(CONVERTED_WORLDS)


def test_import_command_registers_with_argparse(world_dir, tmp_path, capsys):
    parser = argparse.ArgumentParser(prog="fgdwa")
    register_barn_commands(parser.add_subparsers(dest="command", required=True))
    out = tmp_path / "x.npz"
    args = parser.parse_args(["barn", "import", str(world_dir), "--out", str(out), "--worlds", "150"])
    assert args.func(args) == 0
    assert load_barn(out).world_ids == [150]


def test_converter_errors(world_dir, tmp_path):
    with pytest.raises(FgdwaError, match="not a directory"):
        convert_barn_worlds(tmp_path / "nowhere", tmp_path / "o.npz")
    empty = tmp_path / "empty"
    empty.mkdir()
    with pytest.raises(FgdwaError, match="no world_<i>.world files"):
        convert_barn_worlds(empty, tmp_path / "o.npz")
    lonely = tmp_path / "lonely"
    lonely.mkdir()
    shutil.copy(world_dir / "world_0.world", lonely)
    with pytest.raises(FgdwaError, match="no path_0.npy"):
        convert_barn_worlds(lonely, tmp_path / "o.npz")
    with pytest.raises(FgdwaError, match="no world_5.world"):
        convert_barn_worlds(world_dir, tmp_path / "o.npz", world_ids=[0, 5])
    bad = tmp_path / "bad"
    bad.mkdir()
    (bad / "world_1.world").write_text("<sdf><world name='default'><model name='box'/></world></sdf>")
    np.save(bad / "path_1.npy", np.array([[0, 0]], dtype=np.int64))
    with pytest.raises(FgdwaError, match="no unit_cylinder_N model"):
        convert_barn_worlds(bad, tmp_path / "o.npz")
    text = (world_dir / "world_0.world").read_text().replace("-0.075000 0.075000 0.000000", "-0.075000 0.125000 0.0", 1)
    (bad / "world_1.world").write_text(text)
    with pytest.raises(FgdwaError, match="unit_cylinder_0 .* not on a 0.15 m cell"):
        convert_barn_worlds(bad, tmp_path / "o.npz")
    shutil.copy(world_dir / "world_0.world", bad / "world_1.world")
    np.save(bad / "path_1.npy", np.array([[0.0, 1.0]]))
    with pytest.raises(FgdwaError, match="path_1.npy: dtype float64"):
        convert_barn_worlds(bad, tmp_path / "o.npz")
    np.save(bad / "path_1.npy", np.array([[0, 30]]))
    with pytest.raises(FgdwaError, match="outside the 30x30 field"):
        convert_barn_worlds(bad, tmp_path / "o.npz")
    assert not (tmp_path / "o.npz").exists()


def test_fill_holes_matches_scipy():
    ndimage = pytest.importorskip("scipy.ndimage")
    rng = np.random.default_rng(7)
    for density in (0.2, 0.45, 0.6, 0.75):
        for _ in range(25):
            cells = (rng.random((30, 30)) < density).astype(np.uint8)
            expected = ndimage.binary_fill_holes(cells).astype(np.uint8)
            np.testing.assert_array_equal(fill_holes(cells), expected)
    ring = np.zeros((5, 5), np.uint8)
    ring[1:4, 1:4] = 1
    ring[2, 2] = 0
    assert fill_holes(ring)[2, 2] == 1
    # A diagonal gap does not connect a hole to the border (4-connectivity).
    diamond = np.array([[0, 1, 0], [1, 0, 1], [0, 1, 0]], np.uint8)
    assert fill_holes(diamond)[1, 1] == 1


# ---------------------------------------------------------------------------------
# Malformed files
# ---------------------------------------------------------------------------------

def _small_arrays(ids=(0, 6)):
    n = len(ids)
    arrays = {
        "world_ids": np.array(ids, dtype=np.int64),
        "grids": np.zeros((n, 50, 100), np.uint8),
        "fields": np.zeros((n, 30, 30), np.uint8),
        "optimal_time": np.full(n, 5.0),
        "resolution": np.float64(0.15),
        "origin": np.array([0.0, -1.5]),
        "start": np.array([3.0, 2.25, 0.0]),
        "goal": np.array([13.0, 2.25]),
        "goal_radius": np.float64(1.0),
        "time_limit": np.float64(100.0),
    }
    for i in ids:
        arrays[f"path_{i}"] = np.array([[5.175, 2.25], [9.525, 2.25]])
    return arrays


def _write(tmp_path, arrays, name="bad.npz"):
    path = tmp_path / name
    np.savez(path, **arrays)
    return path


def test_a_small_valid_file_loads(tmp_path):
    dataset = load_barn(_write(tmp_path, _small_arrays(), "good.npz"))
    assert isinstance(dataset, BarnDataset) and dataset.world_ids == [0, 6]
    assert dataset.world(6).optimal_time == 5.0
    assert "good.npz" in repr(dataset)


def _without(key):
    def change(a):
        del a[key]
    return change


def _setting(key, value):
    def change(a):
        a[key] = value
    return change


def _robot_off_the_map(a):
    a["start"] = np.array([1000.0, 1000.0, 0.0])
    a["goal"] = np.array([1010.0, 1000.0])


def _blocked(world_id, point):
    """Makes the cell under ``point`` an obstacle in world ``world_id`` (a grid of _small_arrays)."""
    def change(a):
        k = list(a["world_ids"]).index(world_id)
        row, col = int((point[1] + 1.5) / 0.15), int(point[0] / 0.15)
        a["grids"][k, row, col] = 1
    return change


@pytest.mark.parametrize("change, key, message", [
    (_without("grids"), "grids", "missing key"),
    (_without("time_limit"), "time_limit", "missing key"),
    (_without("path_6"), "path_6", "world 6 is in world_ids but has no reference path"),
    (_setting("grids", np.zeros((2, 50, 99), np.uint8)), "grids", r"shape \(2, 50, 99\)"),
    (_setting("grids", np.zeros((3, 50, 100), np.uint8)), "grids", "one per world id"),
    (_setting("grids", np.zeros((2, 50, 100), np.float64)), "grids", "dtype float64"),
    (_setting("fields", np.full((2, 30, 30), 2, np.uint8)), "fields", "values other than 0 and 1"),
    (_setting("fields", np.zeros((2, 30, 29), np.uint8)), "fields", "shape"),
    (_setting("world_ids", np.array([0, 0])), "world_ids", "appears more than once"),
    (_setting("world_ids", np.array([0.0, 6.0])), "world_ids", "expected integers"),
    (_setting("world_ids", np.array([[0, 6]])), "world_ids", "shape"),
    (_setting("world_ids", np.array([-1, 6])), "world_ids", "negative"),
    (_setting("optimal_time", np.array([5.0])), "optimal_time", "shape"),
    (_setting("optimal_time", np.array([5.0, -1.0])), "optimal_time", "> 0"),
    (_setting("optimal_time", np.array([5.0, np.nan])), "optimal_time", "non-finite"),
    (_setting("resolution", np.array([0.15])), "resolution", "shape"),
    (_setting("resolution", np.float64(0.0)), "resolution", "must be > 0"),
    (_setting("origin", np.array([0.0, -1.5, 0.0])), "origin", "shape"),
    (_setting("start", np.array([3.0, 2.25])), "start", "shape"),
    (_setting("goal", np.array([13, 2])), "goal", "dtype int64"),
    (_setting("time_limit", np.int64(100)), "time_limit", "dtype int64"),
    (_setting("path_0", np.zeros((4, 3))), "path_0", r"shape \(4, 3\)"),
    (_setting("path_0", np.zeros((0, 2))), "path_0", "shape"),
    (_setting("path_0", np.array([[26, 0], [25, 0]])), "path_0", "the challenge's path_<i>.npy holds"),
    (_setting("path_0", np.array([[np.inf, 0.0]])), "path_0", "non-finite"),
    (_setting("path_9", np.zeros((2, 2))), "path_9", "world 9 is not in world_ids"),
    (_setting("resolution", np.float64(1e300)), "resolution", r"must be within \[0.0001, 1000\]"),
    (_setting("resolution", np.float64(1e-9)), "resolution", "must be within"),
    (_setting("origin", np.array([1e300, -1.5])), "origin", "corners must lie within"),
    (_setting("time_limit", np.float64(1e300)), "time_limit", "must be <= 3600 s"),
    (_setting("optimal_time", np.array([5.0, 150.0])), "optimal_time", "over the time limit 100 s"),
    (_setting("start", np.array([-5.0, 2.25, 0.0])), "start", r"\(-5, 2.25\) is off the map"),
    (_setting("start", np.array([3.0, 100.0, 0.0])), "start", "off the map"),
    (_setting("start", np.array([3.0, 2.25, 1e300])), "start", "yaw"),
    (_setting("goal", np.array([20.0, 2.25])), "goal", r"\(20, 2.25\) is off the map"),
    (_setting("goal", np.array([13.0, 6.0])), "goal", "off the map"),  # the map ends before y = 6.0
    (_robot_off_the_map, "start", "off the map"),
    (_setting("goal_radius", np.float64(20.0)), "goal_radius", "holds the start"),
    (_blocked(6, START), "start", r"obstacle cell \[25, 20\] of world 6 \(grids\[1\]\)"),
    (_blocked(0, GOAL), "goal", r"obstacle cell \[25, 86\] of world 0 \(grids\[0\]\)"),
    (_setting("path_6", np.array([[5.175, 2.25], [99.0, 2.25]])), "path_6", "point 1 .* of world 6 is off the map"),
])
def test_malformed_files_name_the_file_and_the_key(tmp_path, change, key, message):
    arrays = _small_arrays()
    change(arrays)
    path = _write(tmp_path, arrays)
    with pytest.raises(FgdwaError) as caught:
        load_barn(path)
    text = str(caught.value)
    assert str(path) in text and f"'{key}'" in text, text
    assert re.search(message, text), text


def test_files_that_are_not_npz_archives(tmp_path):
    with pytest.raises(FgdwaError, match="no such file"):
        load_barn(tmp_path / "missing.npz")
    text = tmp_path / "text.npz"
    text.write_text("not an archive")
    with pytest.raises(FgdwaError, match="text.npz: not a readable .npz file"):
        load_barn(text)
    single = tmp_path / "single.npy"
    np.save(single, np.zeros(3))
    with pytest.raises(FgdwaError, match="single.npy: not a barn.npz file"):
        load_barn(single)
    truncated = tmp_path / "truncated.npz"
    good = _write(tmp_path, _small_arrays(), "good.npz").read_bytes()
    truncated.write_bytes(good[: len(good) // 2])
    with pytest.raises(FgdwaError, match="truncated.npz"):
        load_barn(truncated)


def _npy_bytes(array):
    buffer = io.BytesIO()
    np.lib.format.write_array(buffer, np.asanyarray(array), allow_pickle=False)
    return buffer.getvalue()


def _npy_header_bytes(shape, dtype=np.uint8):
    """A .npy header announcing ``shape``, followed by 16 bytes: far less data than announced."""
    buffer = io.BytesIO()
    np.lib.format.write_array_header_1_0(buffer, {"descr": np.lib.format.dtype_to_descr(np.dtype(dtype)),
                                                  "fortran_order": False, "shape": shape})
    return buffer.getvalue() + bytes(16)


def _crafted(tmp_path, arrays, raw=(), name="crafted.npz"):
    """An .npz of ``arrays`` plus raw members (name, bytes), deflated as np.savez_compressed does."""
    path = tmp_path / name
    with zipfile.ZipFile(path, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        for key, value in arrays.items():
            archive.writestr(f"{key}.npy", _npy_bytes(value))
        for member, data in raw:
            archive.writestr(member, data)
    return path


def _claim_size(path, member, size):
    """Rewrites the zip directory so that ``member`` says it decompresses to ``size`` bytes."""
    data = bytearray(path.read_bytes())
    at = 0
    while True:
        at = data.find(b"PK\x01\x02", at)
        assert at >= 0, f"{member} not in the zip directory"
        name_len, extra_len, comment_len = struct.unpack("<HHH", data[at + 28:at + 34])
        if data[at + 46:at + 46 + name_len].decode() == member:
            data[at + 24:at + 28] = struct.pack("<I", size)
            break
        at += 46 + name_len + extra_len + comment_len
    path.write_bytes(bytes(data))


def test_a_member_the_zip_directory_says_is_3_gb_is_refused_unread(tmp_path, monkeypatch):
    path = _crafted(tmp_path, _small_arrays())
    _claim_size(path, "grids.npy", 3 * 2**30)
    with zipfile.ZipFile(path) as archive:
        assert archive.getinfo("grids.npy").file_size == 3 * 2**30
    # np.load of the file before the directory was rewritten would read grids whole; now nothing is read.
    read_array = np.lib.format.read_array

    def guarded(handle, *args, **kwargs):
        assert getattr(handle, "name", None) != "grids.npy", "grids.npy was decompressed"
        return read_array(handle, *args, **kwargs)

    monkeypatch.setattr(np.lib.format, "read_array", guarded)
    with pytest.raises(FgdwaError) as caught:
        load_barn(path)
    text = str(caught.value)
    assert str(path) in text and "'grids'" in text and "3221225472 bytes" in text and "refused unread" in text, text


def test_a_member_whose_npy_header_says_3_gb_is_refused_unread(tmp_path):
    arrays = _small_arrays()
    del arrays["grids"]
    path = _crafted(tmp_path, arrays, raw=[("grids.npy", _npy_header_bytes((700_000, 50, 100)))])
    with pytest.raises(FgdwaError) as caught:
        load_barn(path)
    text = str(caught.value)
    assert "'grids'" in text and "shape (700000, 50, 100)" in text and "MAX_ARRAY_BYTES" in text, text


def test_members_over_a_lowered_limit_are_refused(tmp_path, monkeypatch):
    from fgdwa import file_limits

    path = _write(tmp_path, _small_arrays(), "good.npz")
    monkeypatch.setattr(file_limits, "MAX_ARRAY_BYTES", 5_000)  # grids hold 2 x 50 x 100 = 10 000 bytes
    with pytest.raises(FgdwaError, match="'grids': an array of shape \\(2, 50, 100\\) and dtype uint8 takes 10000"):
        load_barn(path)


def test_members_outside_the_format_are_never_opened(tmp_path):
    junk = _npy_header_bytes((3 * 2**30,))  # announces 3 GB, holds 16 bytes
    path = _crafted(tmp_path, _small_arrays(), raw=[("junk.npy", junk), ("notes.txt", b"x" * 100)])
    _claim_size(path, "junk.npy", 3 * 2**30)
    dataset = load_barn(path)
    assert dataset.world_ids == [0, 6]


def test_converter_refuses_a_path_file_over_the_size_limit_unread(tmp_path):
    from fgdwa.io.barn_convert import _read_path_cells

    path = tmp_path / "path_0.npy"
    path.write_bytes(_npy_header_bytes((2**30, 2), np.int64))  # announces 16 GiB
    with pytest.raises(FgdwaError, match="path_0.npy: an array of shape .* refused unread"):
        _read_path_cells(path)


def test_find_barn_file(tmp_path, monkeypatch):
    path = _write(tmp_path, _small_arrays(), "barn.npz")
    assert find_barn_file(path) == path
    assert find_barn_file(tmp_path) == path
    monkeypatch.setenv("FGDWA_BARN_DATA", str(tmp_path))
    assert find_barn_file() == path
    monkeypatch.setenv("FGDWA_BARN_DATA", str(tmp_path / "nope"))
    with pytest.raises(FgdwaError, match="FGDWA_BARN_DATA"):
        find_barn_file()
    monkeypatch.delenv("FGDWA_BARN_DATA")
    with pytest.raises(FgdwaError, match="set FGDWA_BARN_DATA"):
        find_barn_file()


# ---------------------------------------------------------------------------------
# Score
# ---------------------------------------------------------------------------------

def test_score_is_the_challenge_formula():
    ot = 5.0
    assert barn_score(True, 4.0, ot) == 0.5  # clipped up to 2 OT
    assert barn_score(True, 10.0, ot) == 0.5
    assert barn_score(True, 20.0, ot) == pytest.approx(0.25)
    assert barn_score(True, 40.0, ot) == 0.125
    assert barn_score(True, 99.0, ot) == 0.125  # clipped down to 8 OT
    assert barn_score(False, 20.0, ot) == 0.0
    assert barn_score(False, float("nan"), ot) == 0.0
    with pytest.raises(FgdwaError, match="optimal_time"):
        barn_score(True, 10.0, 0.0)
    with pytest.raises(FgdwaError, match="time"):
        barn_score(True, float("nan"), ot)


def test_world_score_uses_its_optimal_time(barn):
    world = barn.world(0)
    assert world.score(True, 3 * world.optimal_time) == pytest.approx(1 / 3)


def test_cli_barn_import_writes_the_file(world_dir, tmp_path):
    from fgdwa.cli import main

    out = tmp_path / "barn.npz"
    assert main(["barn", "import", str(world_dir), "--out", str(out)]) == 0
    assert len(fgdwa.io.barn_data.load_barn(out)) == 3
