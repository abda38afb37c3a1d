"""`fgdwa --version` prints the installed package's version."""

import importlib.metadata

import pytest

from fgdwa.cli import main


def test_version_prints_the_package_version(capsys):
    with pytest.raises(SystemExit) as exit_info:
        main(["--version"])
    assert exit_info.value.code == 0
    assert capsys.readouterr().out.strip() == f"fgdwa {importlib.metadata.version('fgdwa')}"
