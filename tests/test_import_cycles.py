"""Import cycles, as a static tool sees them: every import of a module
(at its top, inside a function or under TYPE_CHECKING alike) is an edge of
the graph of the project's modules. The cycles broken stay broken: the
learner (generalize) and the model of the pours (meaning), and the theory
package and the reader of theory files (facts), lie on no cycle together."""
from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
#: The packages and the folders they are (pyproject.toml's mapping).
PACKAGES = {"pantarhei.theory": ROOT / "theory", "pantarhei.bridge": ROOT / "bridge",
            "pantarhei.oracle": ROOT / "oracle"}

#: Pairs of modules that must not import each other, however indirectly.
APART = [("pantarhei.bridge.learning.generalize", "pantarhei.bridge.learning.meaning"),
         ("pantarhei.theory", "pantarhei.bridge.theories.facts")]


def module_files(packages: dict[str, Path]) -> dict[str, Path]:
    out = {}
    for name, folder in packages.items():
        for path in folder.rglob("*.py"):
            parts = list(path.relative_to(folder).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts.pop()
            out[".".join([name, *parts])] = path
    return out


def import_graph(packages: dict[str, Path]) -> dict[str, set[str]]:
    """Module -> the project's modules it imports (a name imported from a
    package is the package's module, or the package)."""
    files = module_files(packages)
    graph = {}
    for name, path in files.items():
        here = name if path.name == "__init__.py" else name.rpartition(".")[0]
        found = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    up = here.split(".")[: len(here.split(".")) - node.level + 1]
                    base = ".".join(up + ([base] if base else []))
                found.update(f"{base}.{a.name}" if f"{base}.{a.name}" in files else base
                             for a in node.names)
            elif isinstance(node, ast.Import):
                found.update(a.name for a in node.names)
        graph[name] = {m for m in found if m in files and m != name}
    return graph


def reaches(graph: dict[str, set[str]], start: str, goal: str) -> bool:
    seen, todo = {start}, [start]
    while todo:
        for nxt in graph.get(todo.pop(), ()):
            if nxt == goal:
                return True
            if nxt not in seen:
                seen.add(nxt)
                todo.append(nxt)
    return False


@pytest.mark.parametrize("a, b", APART)
def test_the_broken_cycles_stay_broken(a, b):
    graph = import_graph(PACKAGES)
    assert a in graph and b in graph
    assert not (reaches(graph, a, b) and reaches(graph, b, a)), f"{a} and {b} import each other"


def test_a_cycle_through_a_function_s_import_is_found(tmp_path):
    pkg = tmp_path / "p"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    (pkg / "a.py").write_text("from p.b import f\n")
    (pkg / "b.py").write_text("def f():\n    from p import a\n")
    graph = import_graph({"p": pkg})
    assert reaches(graph, "p.a", "p.b") and reaches(graph, "p.b", "p.a")
