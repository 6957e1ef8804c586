"""Defeasible reasoning over a theory, by SWI-Prolog or by clingo.

`load(path)` reads a theory (native or DFL; without a path, the shipped
learned theory). `conclusions(theory, semantics, engine)` gives the four
kinds of conclusion. The Prolog side is theory/defeasible.pl (tabling
under the well-founded semantics); the ASP side is theory/defeasible.lp.
`assumptions(theory, props)` completes a question with the theory's
ordinary pour; `what_happens` and `explain` answer it.
"""
from __future__ import annotations

import hashlib
import os
import re
import tempfile
from dataclasses import dataclass
from pathlib import Path

from pantarhei.theory import THEORY_DIR, TheoryFileError

from .dfl import is_dfl, read_dfl
from .errors import UserError
from .prolog import text as prolog_text
from .theories import Theory, merge, read_native

TAGS = ("+D", "-D", "+d", "-d")
ENGINES = ("prolog", "asp")
#: The theory the exploration writes, used when no --theory is given.
DEFAULT_THEORY = THEORY_DIR / "learned" / "pouring.pl"
NO_THEORY = (f"no learned theory yet ({DEFAULT_THEORY} does not exist): run the exploration "
             f"(`pantarhei explore`) to learn one, or give a theory file with --theory FILE "
             f"(native facts or .dfl, e.g. examples/extend_by_hand/learned.pl)")


@dataclass(frozen=True)
class Semantics:
    """The switches of the logic; the defaults are the usual ones."""
    ambiguity: str = "blocking"          # or "propagation"
    team_defeat: bool = True
    well_founded: bool = True

    def __post_init__(self) -> None:
        if self.ambiguity not in ("blocking", "propagation"):
            raise ValueError(f"ambiguity must be blocking or propagation, not {self.ambiguity}")

    def prolog(self) -> str:
        return (f"sem({self.ambiguity}, {str(self.team_defeat).lower()}, "
                f"{str(self.well_founded).lower()})")

    def options(self) -> str:
        """As the option list of theory/queries.pl."""
        return (f"[ambiguity({self.ambiguity}), team_defeat({str(self.team_defeat).lower()}), "
                f"well_founded({str(self.well_founded).lower()})]")

    def asp_constants(self) -> dict[str, str]:
        return {"ambiguity": self.ambiguity, "team_defeat": str(self.team_defeat).lower(),
                "well_founded": str(self.well_founded).lower()}


ALL_SEMANTICS = tuple(Semantics(a, t, w) for a in ("blocking", "propagation")
                      for t in (True, False) for w in (True, False))


def read_theory(path: Path | str) -> Theory:
    """A theory file, native or DFL; UserError with `file:line: what`."""
    try:
        return read_dfl(path) if is_dfl(path) else read_native(path)
    except TheoryFileError as e:
        raise UserError(str(e)) from None


def load(paths: Path | str | list | tuple | None = None, check: bool = True) -> Theory:
    """The theory of one or more files (merged: a learned theory and rules
    added by hand), or the shipped learned theory when none is given.
    With `check`, sup/2 must name rules of the theory."""
    if paths is None or (isinstance(paths, (list, tuple)) and not paths):
        if not DEFAULT_THEORY.is_file():
            raise UserError(NO_THEORY)
        paths = [DEFAULT_THEORY]
    if not isinstance(paths, (list, tuple)):
        paths = [paths]
    for p in paths:
        path = Path(p)
        if not path.exists():
            raise UserError(f"{p}: no such theory file")
        if path.is_dir():
            raise UserError(f"{p}: a directory, not a theory file")
        if not path.is_file():
            raise UserError(f"{p}: not a regular file (a device or a pipe), not a theory file")
    theories = [read_theory(p) for p in paths]
    for t in theories:
        if not (t.facts or t.rules or t.sup or t.settings or t.extra):
            raise UserError(f"{t.source}: an empty theory (no facts and no rules)")
    try:
        theory = merge(theories)
        if check:
            theory.check_superiority()
        theory.check_acyclic()
    except TheoryFileError as e:
        raise UserError(str(e)) from None
    return theory


# -- Prolog -----------------------------------------------------------------

_loaded_digest: list[str] = [""]


def prolog_load(theory: Theory):
    """Make `theory` the current theory of the Prolog engine (once per text)."""
    from .prolog import engine

    e = engine()
    e.use_module("defeasible")
    text = theory.native()
    digest = hashlib.sha1(text.encode()).hexdigest()
    if _loaded_digest[0] != digest:
        fd, name = tempfile.mkstemp(suffix=".pl", prefix="pantarhei-theory-")
        try:
            with os.fdopen(fd, "w") as f:
                f.write(text)
            r = e.once("catch((defeasible:load_theory(F), R = ok), E, "
                       "theory_files:error_message(E, R))", F=name)
        finally:
            os.unlink(name)
        if prolog_text(r["R"]) != "ok":
            raise UserError(f"{theory.source}: {prolog_text(r['R']).split(': ', 1)[-1]}")
        _loaded_digest[0] = digest
    return e


def prolog_conclusions(theory: Theory, semantics: Semantics = Semantics()) -> dict[str, list[str]]:
    e = prolog_load(theory)
    out = {}
    for tag in TAGS:
        r = e.once(f"findall(S, (defeasible:conclusion({semantics.prolog()}, T, L), "
                   "format(string(S), '~q', [L])), Ss)", T=tag)
        out[tag] = sorted(prolog_text(s) for s in r["Ss"])
    return out


def prolog_conclusions_batch(jobs: list[tuple[Theory, Semantics]]) -> list[dict[str, list[str]]]:
    """The conclusions of many theories, computed by one `swipl` process
    (for many theories at once, a separate process keeps the host's engine
    out of the way)."""
    import shutil
    import subprocess

    swipl = shutil.which("swipl")
    if swipl is None:
        from .errors import SWIPL_MISSING

        raise UserError(SWIPL_MISSING)
    with tempfile.TemporaryDirectory(prefix="pantarhei-batch-") as tmp:
        goals = [f":- use_module({_quote(str(THEORY_DIR / 'defeasible'))})."]
        for i, (theory, sem) in enumerate(jobs):
            f = Path(tmp) / f"t{i}.pl"
            f.write_text(theory.native())
            goals.append(f"job({i}, {_quote(str(f))}, {sem.prolog()}).")
        goals.append("main :- forall(job(I, F, S), (load_theory(F), "
                     "forall((member(T, ['+D', '-D', '+d', '-d']), conclusion(S, T, L)), "
                     "format('~w\\t~w\\t~q~n', [I, T, L])))).")
        script = Path(tmp) / "batch.pl"
        script.write_text("\n".join(goals) + "\n")
        p = subprocess.run([swipl, "-q", "-g", "main", "-t", "halt", str(script)],
                           capture_output=True, text=True)
        if p.returncode != 0:
            raise RuntimeError(f"swipl failed: {p.stderr.strip()}")
    out: list[dict[str, list[str]]] = [{t: [] for t in TAGS} for _ in jobs]
    for line in p.stdout.splitlines():
        i, tag, lit = line.split("\t")
        out[int(i)][tag].append(lit)
    return [{t: sorted(v) for t, v in d.items()} for d in out]


def _quote(s: str) -> str:
    return "'" + s.replace("\\", "\\\\").replace("'", "\\'") + "'"


# -- ASP --------------------------------------------------------------------

def asp_conclusions(theory: Theory, semantics: Semantics = Semantics(),
                    steps: int = 8) -> dict[str, list[str]]:
    """Solve defeasible.lp: in one layer for an acyclic theory, else
    doubling the alternation steps until they suffice."""
    from .asp import solve

    text = theory.native()
    acyclic = theory.acyclic()
    if acyclic:
        steps = 0
    while True:
        consts = {**semantics.asp_constants(), "steps": str(steps), "acyclic": str(acyclic).lower()}
        (model,) = solve(["defeasible.lp", "conclusions.lp"], text, files=(),
                         args=[f"-c{k}={v}" for k, v in consts.items()])
        cycle = sorted(str(s.arguments[0]) for s in model if s.name == "sup_cycle")
        if cycle:
            raise UserError(f"{theory.source}: the superiority relation has a cycle through "
                            f"{', '.join(cycle)}: it must be acyclic")
        if not any(s.name == "changed" for s in model):
            break
        steps *= 2
    out: dict[str, list[str]] = {t: [] for t in TAGS}
    for s in model:
        if s.name == "concl":
            out[s.arguments[0].string].append(str(s.arguments[1]))
    return {t: sorted(v) for t, v in out.items()}


def conclusions(theory: Theory, semantics: Semantics = Semantics(),
                engine: str = "prolog") -> dict[str, list[str]]:
    """The four kinds of conclusion, each a sorted list of native literals."""
    if engine == "prolog":
        return prolog_conclusions(theory, semantics)
    if engine == "asp":
        return asp_conclusions(theory, semantics)
    raise UserError(f"unknown engine '{engine}' (choose prolog or asp)")


# -- Questions about pouring --------------------------------------------------

_SETTING = re.compile(r"^\s*setting\(\s*([a-z][A-Za-z0-9_]*)\s*,\s*(.+?)\s*\)\s*\.\s*$")


def settings(theory: Theory) -> dict[str, list]:
    """The theory's `setting(Key, Value)` facts, values in file order: what
    `pantarhei explore` records of the exploration behind a learned theory
    (oracle, oracle_version, seed, samples, initial, ...). Those read from
    its native file(s) (`Theory.settings`), then any among the lines it keeps
    aside (`extra`); none for DFL files or hand-written theories without
    such facts. Values are str or int."""
    out = {k: list(v) for k, v in theory.settings.items()}
    for m in map(_SETTING.match, theory.extra):
        if m:
            v = m.group(2).strip('"')
            have = out.setdefault(m.group(1), [])
            value = int(v) if v.lstrip("-").isdigit() else v
            if value not in have:
                have.append(value)
    return out


def provenance_lines(theory: Theory) -> list[str]:
    """Where a learned theory comes from, one `key: values` line per
    setting (for formats without facts for it, as comments in DFL)."""
    s = settings(theory)
    if not s:
        return []
    return ["learned by pantarhei explore; settings of the exploration:"] + \
        [f"  {k}: {', '.join(str(v) for v in vs)}" for k, vs in s.items()]


def initial_antecedent(theory: Theory) -> list[str]:
    """The theory's `setting(initial, P)` propositions, in file order: the
    antecedent a_0 its exploration started from (and which every learned
    rule body therefore contains, or a neighbour of)."""
    return [p for p in settings(theory).get("initial", []) if isinstance(p, str)]


def assumptions(theory: Theory, props: list[str] | tuple[str, ...]) -> list[str]:
    """The propositions to add to the question `props`, in order: the
    theory's initial antecedent (`initial_antecedent`) for each dimension
    the question leaves open, added one at a time in the theory's order and
    skipped when it would make the antecedent invalid (bridge/validity.py).
    `props` should be a valid antecedent; if it is not, nothing is added.
    The scene to reason about is then `props + assumptions(theory, props)`."""
    from pantarhei.oracle.vocabulary import load_vocabulary

    from .validity import violations

    initial = initial_antecedent(theory)
    if not initial:
        return []
    vocab = load_vocabulary()
    scene = list(props)
    if violations(scene):
        return []
    taken = {vocab.propositions[p].dimension for p in scene if p in vocab.propositions}
    added: list[str] = []
    for p in initial:
        prop = vocab.propositions.get(p)
        if prop is None or prop.dimension in taken:
            continue
        if violations(scene + added + [p]):
            continue
        added.append(p)
        taken.add(prop.dimension)
    return added


@dataclass(frozen=True)
class Outcome:
    """What the theory says about one expectation in a scene."""
    expectation: str
    value: str          # "holds", "fails" or "unknown"
    rule: str           # the deciding rule, "fact", or "none"
    reason: str         # in words


def _prolog_list(items) -> str:
    return "[" + ", ".join(items) + "]"


def what_happens(theory: Theory, props: list[str],
                 semantics: Semantics = Semantics()) -> list[Outcome]:
    """The prediction for a scene: one Outcome per expectation, with reasons
    (for an undecided one, the brief why-not of queries:explain_brief/4)."""
    e = prolog_load(theory)
    e.use_module("queries")
    scene = _prolog_list(props)
    sem = semantics.options()
    goal = (f"queries:what_happens({scene}, {sem}, Os), "
            f"findall(S, (member(outcome(E, V, R), Os), "
            f"(V == fails -> L = neg(E) ; L = E), queries:explain_brief({scene}, L, {sem}, T), "
            f"format(string(S), '~w\\t~w\\t~w\\t~s', [E, V, R, T])), Ss)")
    r = e.once(goal)
    out = []
    for line in r["Ss"]:
        exp, value, rule, reason = prolog_text(line).split("\t", 3)
        out.append(Outcome(exp, value, rule, reason))
    return out


def explain(theory: Theory, props: list[str], literal: str,
            semantics: Semantics = Semantics(), brief: bool = False) -> str:
    """Why (or why not) the theory concludes `literal` in the scene, in
    words, sentences separated by "; ". A why-not names every rule for the
    literal (queries:explain/4), or with `brief` at most three
    (queries:explain_brief/4)."""
    e = prolog_load(theory)
    e.use_module("queries")
    pred = "explain_brief" if brief else "explain"
    r = e.once(f"queries:{pred}({_prolog_list(props)}, {literal}, {semantics.options()}, T)")
    return prolog_text(r["T"])
