"""Import cycles, as a static tool sees them: every import of a module
(at its top, inside a function or under TYPE_CHECKING alike) is an edge of
the graph of the project's modules, and the graph of the whole `pantarhei`
package has no cycle. The cycles once there stay broken: the learner (generalize) and the model of the pours
(meaning), the theory package and the reader of theory files (facts),
and the plan search and the order in which it tries manners (plan_order),
the reading's words and the numbers in words (numerals) lie on no cycle
together."""
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
         ("pantarhei.theory", "pantarhei.bridge.theories.facts"),
         ("pantarhei.bridge.reasoning.plan_search", "pantarhei.bridge.reasoning.plan_order"),
         ("pantarhei.bridge.reasoning.words", "pantarhei.bridge.reasoning.quantities")]


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


def cycles(graph: dict[str, set[str]]) -> list[set[str]]:
    """The strongly connected components of two or more modules: each is
    the set of modules that lie on a cycle together (Tarjan's algorithm,
    without recursion)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    out = []
    for root in sorted(graph):
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            node, edges = work[-1]
            nxt = next(edges, None)
            if nxt is not None:
                if nxt not in index:
                    index[nxt] = low[nxt] = len(index)
                    stack.append(nxt)
                    on_stack.add(nxt)
                    work.append((nxt, iter(sorted(graph[nxt]))))
                elif nxt in on_stack:
                    low[node] = min(low[node], index[nxt])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = set()
                while True:
                    m = stack.pop()
                    on_stack.discard(m)
                    component.add(m)
                    if m == node:
                        break
                if len(component) > 1:
                    out.append(component)
    return out


def unknown_cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The cycles of the graph, each as its sorted modules."""
    return [sorted(c) for c in cycles(graph)]


def test_the_package_has_no_import_cycle():
    found = unknown_cycles(import_graph(PACKAGES))
    assert not found, "modules that import each other, however indirectly: " + \
        "; ".join(", ".join(c) for c in found)


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


def test_a_new_cycle_is_reported_and_a_chain_is_not(tmp_path):
    pkg = tmp_path / "p"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    (pkg / "a.py").write_text("from p import b\n")
    (pkg / "b.py").write_text("import p.c\n")
    (pkg / "c.py").write_text("")
    (pkg / "d.py").write_text("from p.a import x\n")
    assert cycles(import_graph({"p": pkg})) == []
    (pkg / "c.py").write_text("if False:\n    from p.a import y\n")
    assert cycles(import_graph({"p": pkg})) == [{"p.a", "p.b", "p.c"}]
    assert unknown_cycles(import_graph({"p": pkg})) == [["p.a", "p.b", "p.c"]]
