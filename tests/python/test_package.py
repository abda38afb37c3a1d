import importlib
import subprocess
import sys
from pathlib import Path

import pytest

import fgdwa

PACKAGE = Path(fgdwa.__file__).parent
SOURCE_STUB = Path(__file__).resolve().parents[2] / "python" / "fgdwa" / "_core.pyi"


def test_typing_markers_ship_with_the_package():
    assert (PACKAGE / "py.typed").exists()
    assert (PACKAGE / "_core.pyi").exists()


@pytest.mark.parametrize("package", ["fgdwa.sim", "fgdwa.io", "fgdwa.bench", "fgdwa.plot", "fgdwa.adapters"])
def test_each_sub_package_says_its_role_and_exports_its_names(package):
    module = importlib.import_module(package)
    assert module.__doc__ and module.__all__
    assert all(hasattr(module, name) for name in module.__all__)


def test_the_top_level_package_and_the_fuzzy_module_draw_nothing():
    # The algorithm's helpers load neither the simulator nor matplotlib: plots live in fgdwa.plot.
    code = ("import sys, fgdwa, fgdwa.fuzzy; "
            "print(sorted(m for m in sys.modules if m == 'matplotlib' or m.startswith(('fgdwa.sim', 'fgdwa.plot'))))")
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True).stdout
    assert out.strip() == "[]"


def test_stub_matches_the_compiled_module(tmp_path):
    pytest.importorskip("pybind11_stubgen")
    subprocess.run([sys.executable, "-m", "pybind11_stubgen", "fgdwa._core", "-o", str(tmp_path)], check=True,
                   capture_output=True)
    generated = (tmp_path / "fgdwa" / "_core.pyi").read_text()
    assert generated == SOURCE_STUB.read_text(), "python/fgdwa/_core.pyi is stale: run `make stubs`"


def test_reprs_say_what_they_hold():
    assert repr(fgdwa.RobotLimits()).startswith("RobotLimits(v_min=0")
    assert repr(fgdwa.Footprint.circle(0.25)) == "Footprint.circle(radius=0.25)"
    assert "critics=[{'name': 'heading', 'weight': 0.5, 'params': {}}" in repr(fgdwa.PlannerParams())
    assert "window={'n_v': 21, 'n_omega': 21}" in repr(fgdwa.PlannerParams())
    assert repr(fgdwa.Disc((1, 2), 0.5)) == "Disc(center=(1, 2), radius=0.5, velocity=(0, 0))"
