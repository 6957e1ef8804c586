"""Imports a static tool can follow: every module of the project, named as
it is imported (`pantarhei.bridge.learning.doubts`), is found by a plain
search of the paths (what mypy and pyright do, as pyproject.toml
configures them: `.imports`, where `pantarhei/` links each folder of the
loop) at the file the project runs."""
from __future__ import annotations

import tomllib
from importlib.machinery import PathFinder
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
IMPORTS = ROOT / ".imports"


def package_dirs() -> dict[str, Path]:
    """The installed packages and their folders (pyproject.toml)."""
    table = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["package-dir"]
    return {name: ROOT / folder for name, folder in table.items()}


def modules() -> dict[str, Path]:
    """Every module of the installed packages, by its dotted name."""
    out = {}
    for name, folder in package_dirs().items():
        for f in sorted(folder.glob("*.py")):
            out[name if f.stem == "__init__" else f"{name}.{f.stem}"] = f
    return out


def found(dotted: str, paths: list[str]) -> Path | None:
    """Where a plain search of `paths` finds the module `dotted`."""
    spec, name = None, ""
    for part in dotted.split("."):
        name = f"{name}.{part}" if name else part
        spec = PathFinder.find_spec(name, paths)
        if spec is None:
            return None
        paths = list(spec.submodule_search_locations or [])
    return Path(spec.origin).resolve() if spec and spec.origin else None


def test_the_static_tools_are_told_where_the_packages_are():
    tools = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]
    assert tools["mypy"]["mypy_path"] == ".imports" and tools["pyright"]["extraPaths"] == [".imports"]
    tops = {name.split(".")[1] for name in package_dirs()}
    assert {p.name for p in (IMPORTS / "pantarhei").iterdir()} == tops


@pytest.mark.parametrize("dotted", sorted(modules()))
def test_a_module_is_found_where_it_runs(dotted):
    assert found(dotted, [str(IMPORTS)]) == modules()[dotted].resolve()


def test_a_module_is_not_found_without_the_links(tmp_path):
    assert found("pantarhei.bridge.verdicts", [str(tmp_path)]) is None
