"""Defeasible conclusions of a theory, by SWI-Prolog or by clingo.

`conclusions(theory, semantics, engine)` gives the four kinds of conclusion
(+D, -D, +d, -d). The Prolog side is theory/defeasible.pl (tabling under the
well-founded semantics); the ASP side is theory/derivability.lp. `Semantics`
holds the logic's switches.
"""
from __future__ import annotations

import hashlib
import os
import tempfile
from dataclasses import dataclass
from pathlib import Path

from pantarhei.bridge.engines.swipl import engine, prolog_quote, text as prolog_text
from pantarhei.bridge.errors import UserError
from pantarhei.bridge.reasoning.written_theory import AsWritten, load_as_written, prolog_read
from pantarhei.bridge.theories.model import Theory
from pantarhei.theory import THEORY_DIR, TheoryFileError

TAGS = ("+D", "-D", "+d", "-d")
ENGINES = ("prolog", "asp")


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


# -- Prolog -----------------------------------------------------------------

def prolog_load(theory: Theory):
    """Make `theory` the current theory of the Prolog engine (loaded again
    only when its text changed since the engine last loaded one): for a
    theory read from files and unchanged since (written_theory.AsWritten),
    the files as they are written."""
    if isinstance(theory, AsWritten):
        e = load_as_written(theory)
        if e is not None:
            return e
    e = engine()
    e.use_module("defeasible")
    text = theory.native()
    digest = hashlib.sha1(text.encode()).hexdigest()
    if e.theory_digest != digest:
        fd, name = tempfile.mkstemp(suffix=".pl", prefix="pantarhei-theory-")
        try:
            with os.fdopen(fd, "w") as f:
                f.write(text)
            e.load_theory_file(name, theory.source)
        finally:
            os.unlink(name)
        e.theory_digest = digest
    return e


def prolog_file_conclusions(paths: list | tuple, semantics: Semantics = Semantics()
                            ) -> dict[str, list[str]]:
    """The four kinds of conclusion of the theory files as written
    (prolog_read; a theory of any literals: no warnings)."""
    return _conclusions_of(prolog_read(paths, pouring=False), semantics)


def prolog_conclusions(theory: Theory, semantics: Semantics = Semantics()) -> dict[str, list[str]]:
    return _conclusions_of(prolog_load(theory), semantics)


def _conclusions_of(e, semantics: Semantics) -> dict[str, list[str]]:
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
        from pantarhei.bridge.errors import SWIPL_MISSING

        raise UserError(SWIPL_MISSING)
    with tempfile.TemporaryDirectory(prefix="pantarhei-batch-") as tmp:
        goals = [f":- use_module({prolog_quote(str(THEORY_DIR / 'defeasible'))})."]
        for i, (theory, sem) in enumerate(jobs):
            f = Path(tmp) / f"t{i}.pl"
            f.write_text(theory.native())
            goals.append(f"job({i}, {prolog_quote(str(f))}, {sem.prolog()}).")
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


# -- ASP --------------------------------------------------------------------

#: The most theory bytes clingo's alternating fixpoint grounds in all (two
#: layers an alternation step, the steps doubled until they suffice): some
#: ten seconds. Past it asp_conclusions refuses; SWI-Prolog, whose fixpoint
#: is not grounded, answers.
ALTERNATION_BYTES_AT_MOST = 2_000_000


def asp_conclusions(theory: Theory, semantics: Semantics = Semantics(),
                    steps: int = 8) -> dict[str, list[str]]:
    """Solve derivability.lp: in one layer for an acyclic theory, else
    doubling the alternation steps until they suffice."""
    from pantarhei.bridge.engines.asp import solve

    try:
        # the one check of a cycle on this side (check_acyclic, its message
        # theory/check_messages.pl's): derivability.lp's superiority is a part
        # of the relation checked here (specificity only among the rules
        # that may apply), so its sup_cycle/1, which is for clingo alone,
        # finds none that this did not
        theory.check_acyclic()
    except TheoryFileError as e:
        raise UserError(str(e)) from None
    text = theory.encoded()
    acyclic = theory.acyclic()
    if acyclic:
        steps = 0
    grounded = 0
    while True:
        grounded += 0 if acyclic else 2 * steps * len(text)
        if grounded > ALTERNATION_BYTES_AT_MOST:
            raise UserError(f"{theory.source}: clingo grounds a theory whose rules depend on "
                            f"themselves once per alternation of its fixpoint, and this one "
                            f"({len(text):,} bytes) needs more than {steps // 2 or steps} of them, "
                            f"past the {ALTERNATION_BYTES_AT_MOST:,} bytes it grounds at most: "
                            f"ask it with --engine prolog (the same conclusions)")
        consts = {**semantics.asp_constants(), "steps": str(steps), "acyclic": str(acyclic).lower()}
        (model,) = solve(["derivability.lp", "conclusions.lp"], text, files=(),
                         args=[f"-c{k}={v}" for k, v in consts.items()])
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
