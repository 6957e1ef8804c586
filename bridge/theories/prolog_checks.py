"""The checks of a theory that SWI-Prolog makes, asked of a theory Python
read or built: a general rule (provenance `layer general`) speaks the
vocabulary's words and has its evidence in range, sup/2 names rules, the
superiority relation (sup/2 with specificity) is acyclic, and, read as a
theory of pouring, the names its rules use that the vocabulary does not
know. Each is SWI-Prolog's alone (theory/theory_checks.pl and
superiority.pl, made by theory/ask.pl's load_theories/3), said in the
words of theory/check_messages.pl: Python hands each file it read over as
a stand-in, its native text with the lines Python read its facts at
(`written_at/4` facts), as `ask` hands over a DFL file. The engine is
started only for a theory that has something for those checks to look
at. A theory is a bridge/theories/model.Theory (not imported: the model
asks its cycle check here)."""
from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Sequence

from pantarhei.theory import TheoryFileError


def written_at(theory) -> list[list]:
    """The facts of `theory` that theory/ask.pl's checks read, at the
    lines Python read them: [line, rule, id, head], [line, body, id,
    literal] or [line, fact, fact, literal] (the check of its names,
    theory/theory_checks.pl's unknown_names/2), a literal as its native text; [line, provenance,
    id, key] and [line, sup, a, b] (where its general rules' evidence and
    its superiority pairs are written)."""
    rows = []
    for r in theory.rules:
        line = theory.lines.get(r.id, 0)
        rows.append([line, "rule", r.id, r.head])
        rows.extend([theory.body_lines.get((r.id, b), line), "body", r.id, b] for b in r.body)
    rows.extend([theory.body_lines.get(("", f), 0), "fact", "fact", f] for f in theory.facts)
    at = theory.fact_lines
    rows.extend([at.get(("provenance", rid, key), 0), "provenance", rid, key]
                for rid, key in dict.fromkeys((rid, key) for rid, key, _ in theory.provenance))
    rows.extend([at.get(("sup", a, b), 0), "sup", a, b] for a, b in dict.fromkeys(theory.sup))
    return rows


def stand_in_text(theory) -> str:
    """The text of a stand-in for a theory Python read: its native text and
    written_at/4 facts of the rows of written_at, for SWI-Prolog to check
    it at the lines of the file Python read."""
    return theory.native() + "".join(f"written_at({line}, {kind}, {rid}, {lit}).\n"
                                     for line, kind, rid, lit in written_at(theory))


def needs_prolog(theory) -> bool:
    """Whether `theory` has a general rule or a sup/2 pair: without
    either, its general rules and its superiority relation pass (the
    specificity of learned rules alone has no cycle)."""
    return bool(theory.sup) or any(k == "layer" and v == "general"
                                   for _, k, v in theory.provenance)


def check(theories: Sequence, names: bool = False,
          sup_names: bool = False) -> list[tuple[str, str, str]]:
    """TheoryFileError (`file:line: what`, one line) unless the theories
    (one each of the files a theory was read from, merged in order) pass
    SWI-Prolog's checks of their general rules and of the superiority
    relation they make together (with `sup_names`, each sup/2 pair naming
    rules of theirs: else a pair may name a rule of no file here, as of a
    file of added rules read alone); with `names`, the names their rules
    use that the vocabulary does not know, (where, what, name), by file
    and line (else none). The engine's theory is changed: it holds none
    that a digest names afterwards."""
    if not names and not any(map(needs_prolog, theories)):
        return []
    from pantarhei.bridge.engines.swipl import engine, text

    e = engine()
    e.use_module("ask")
    e.theory_digest = ""                # the theory loaded below is no file's as written
    with tempfile.TemporaryDirectory(prefix="pantarhei-check-") as tmp:
        paths = []
        for i, t in enumerate(theories):
            paths.append(str(Path(tmp) / f"t{i}.pl"))
            Path(paths[-1]).write_text(stand_in_text(t))
        r = e.once(
            "maplist([P, N, file(P, N, checked)]>>true, Ps, Ns, Fs), "
            "catch(( ask:load_theories(Fs, [sup_names(S)], Ws), R = ok, "
            "        findall([W, T, U], member(unknown(W, T, U), Ws), Us) ), "
            "      E, ( ask:error_line(E, R), Us = [] ))",
            Ps=paths, Ns=[t.source for t in theories], S=sup_names)
    if text(r["R"]) != "ok":
        raise TheoryFileError(text(r["R"]))
    return [(text(w), text(what), text(n)) for w, what, n in r["Us"]] if names else []
