"""Reading theories: a file in either format, several files merged, or the
shipped learned theory when none is named; and what a learned theory says
of the exploration behind it (its `setting/2` facts)."""
from __future__ import annotations

import re
from pathlib import Path

from pantarhei.bridge.errors import UserError
from pantarhei.bridge.files import theory_file_problem
from pantarhei.bridge.theories import prolog_checks
from pantarhei.bridge.theories.dfl import is_dfl, read_dfl
from pantarhei.bridge.theories.model import Theory
from pantarhei.bridge.theories.native import read_native
from pantarhei.theory import TheoryFileError, check_message, default_theory, defaults

#: The theory the exploration writes, used when no theory file is named.
DEFAULT_THEORY = default_theory()
NO_THEORY = (f"no learned theory yet ({DEFAULT_THEORY} does not exist): run the exploration "
             f"(`pantarhei explore`) to learn one, or give a theory file with --theory FILE "
             f"(native facts or .dfl, e.g. examples/extend_by_hand/learned.pl)")


def too_large(size: int) -> str | None:
    """Why a theory file of `size` bytes is not read, or None."""
    most = int(defaults()["theory_bytes_at_most"])
    return check_message("too_large", f"{size:,}", f"{most:,}") if size > most else None


def read_theory(path: Path | str) -> Theory:
    """A theory file, native or DFL; UserError with `file:line: what`."""
    try:
        why = too_large(Path(path).stat().st_size)
    except OSError:
        why = None                      # the reader names what is wrong
    if why:
        raise UserError(f"{path}: {why}")
    try:
        return read_dfl(path) if is_dfl(path) else read_native(path)
    except TheoryFileError as e:
        raise UserError(str(e)) from None


def load(paths: Path | str | list | tuple | None = None, check: bool = True,
         pouring: bool = False) -> Theory:
    """The theory of one or more files (merged: a learned theory and rules
    added by hand), or the shipped learned theory when none is given.
    Its general rules and its superiority relation (with `check`, sup/2
    naming rules of the theory) are checked by theory/ask.pl
    (bridge/theories/prolog_checks.py). With `pouring`, the theory is read
    as a theory of pouring: a rule that names something the vocabulary does
    not know gets a warning on stderr (the same check's,
    bridge/theories/unknown_names.py's words)."""
    if paths is None or (isinstance(paths, (list, tuple)) and not paths):
        if not DEFAULT_THEORY.is_file():
            raise UserError(NO_THEORY)
        paths = [DEFAULT_THEORY]
    if not isinstance(paths, (list, tuple)):
        paths = [paths]
    for p in paths:
        problem = theory_file_problem(p)
        if problem:
            raise UserError(problem)
    theories = [read_theory(p) for p in paths]
    for t in theories:
        check_file(t)
    try:
        theory = merge(theories)
        unknown = prolog_checks.check(theories, names=pouring, sup_names=check)
    except TheoryFileError as e:
        raise UserError(str(e)) from None
    if unknown:
        from pantarhei.bridge.theories.unknown_names import print_warnings

        print_warnings(unknown)
    return theory


def check_file(t: Theory) -> None:
    """UserError for a theory file that is empty (its general rules, its
    names and its superiority relation are theory/ask.pl's to check: load,
    or SWI-Prolog reading a stand-in for it)."""
    if not (t.facts or t.rules or t.sup or t.settings or t.extra):
        raise UserError(f"{t.source}: " + check_message("empty_theory"))


def merge(theories: list[Theory]) -> Theory:
    """One theory from several files (a learned theory and rules added by
    hand); rule names must be distinct, sup/2 may cross files."""
    if len(theories) == 1:
        return theories[0]
    out = Theory(source=" + ".join(t.source for t in theories))
    owner: dict[str, str] = {}
    for t in theories:
        for f in t.facts:
            if f not in out.facts:
                out.facts.append(f)
        for r in t.rules:
            if r.id in owner:
                raise TheoryFileError(f"{t.where(r.id)}: "
                                      + check_message("already_defined", r.id, owner[r.id]))
            owner[r.id] = t.source
            out.rules.append(r)
        out.sup.extend(t.sup)
        out.learned |= t.learned
        for k, values in t.settings.items():
            have = out.settings.setdefault(k, [])
            have.extend(v for v in values if v not in have)
        out.provenance.extend(t.provenance)
        out.extra.extend(t.extra)
        out.schemas.extend(t.schemas)
    return out


def converted(theory: Theory, to: str, out: Path | str | None = None) -> str:
    """The theory as the text of a file in format `to` (dfl or native),
    holding every fact it was read from; UserError (one line) for what that
    format cannot hold, or for an `out` file whose name would be read as
    the other format."""
    from pantarhei.bridge.theories.dfl import is_dfl, write_dfl

    if to not in ("dfl", "native"):
        raise UserError(f"a theory converts to dfl or native, not {to}")
    if out is not None and is_dfl(out) != (to == "dfl"):
        raise UserError(f"{out}: a {'DFL' if to == 'dfl' else 'native'} theory goes in a "
                        f"{'.dfl' if to == 'dfl' else 'file not named .dfl'} (the name says how it is read)")
    if theory.schemas:
        where, label = theory.schemas[0]
        raise UserError(f"{where}: rule {label} has variables, which convert would ground into "
                        f"instances and lose: write its instances by hand, or keep the DFL file")
    return write_dfl(theory, provenance_lines(theory)) if to == "dfl" else theory.native()


#: Settings of theories learned before explore's options had one meaning
#: each, by the names they have now (the discovering curiosity's
#: significance_permille kept its name).
RENAMED_SETTINGS = {"max_rules": "budget", "samples": "batch",
                    "threshold_permille": "slope_permille", "prior": "prior_batch"}

_SETTING = re.compile(r"^\s*setting\(\s*([a-z][A-Za-z0-9_]*)\s*,\s*(.+?)\s*\)\s*\.\s*$")


def settings(theory: Theory) -> dict[str, list]:
    """The theory's `setting(Key, Value)` facts, values in file order: what
    `pantarhei explore` records of the exploration behind a learned theory
    (oracle, oracle_version, seed, batch, initial, ...). Those read from
    its native file(s) (`Theory.settings`), then any among the lines it keeps
    aside (`extra`); none for DFL files or hand-written theories without
    such facts. Values are str or int."""
    out = {RENAMED_SETTINGS.get(k, k): list(v) for k, v in theory.settings.items()}
    for m in map(_SETTING.match, theory.extra):
        if m:
            v = m.group(2).strip('"')
            have = out.setdefault(RENAMED_SETTINGS.get(m.group(1), m.group(1)), [])
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
