"""`fgdwa --version` prints the installed package's version."""

import importlib.metadata

import pytest

from fgdwa.cli import main


def test_version_prints_the_package_version(capsys):
    with pytest.raises(SystemExit) as exit_info:
        main(["--version"])
    assert exit_info.value.code == 0
    assert capsys.readouterr().out.strip() == f"fgdwa {importlib.metadata.version('fgdwa')}"


def test_run_checks_its_outputs_and_seed_before_running(tmp_path, capsys):
    from fgdwa.cli import main

    blocked = tmp_path / "file"
    blocked.write_text("a file where a directory should be")
    for argv, says in [
        (["--gif", str(tmp_path / "x.png")], "the file is written as GIF: name it *.gif"),
        (["--gif", str(blocked / "x.gif")], "cannot make its directory"),
        (["--record", str(tmp_path / "x.txt")], "the file is written as RRD: name it *.rrd"),
        (["--seed", "-3"], "seed = -3: must be an integer in [0, "),
        (["--seed", "18446744073709"], "seed = 18446744073709: must be an integer in [0, "),
    ]:
        assert main(["run", "demo", "--max-steps", "3", "--out", str(tmp_path / "out")] + argv) != 0
        err = capsys.readouterr().err
        assert says in err and "Traceback" not in err, err
    assert not (tmp_path / "out" / "demo_fgdwa.png").exists()  # refused before the run


def test_a_scenario_name_never_leaves_the_output_directory(tmp_path):
    from fgdwa.cli import file_stem

    assert file_stem("../../escaped") == "_.._escaped"
    assert "/" not in file_stem("a/b\\c") and len(file_stem("x" * 300)) == 100
    assert file_stem("...") == "scenario" and file_stem("corridor-2.v1") == "corridor-2.v1"
