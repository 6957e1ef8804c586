"""Theory files as they are written, made the theory of this process's
SWI-Prolog: read, merged and checked by theory/ask.pl's load_theories/2,
as `ask` reads them, not written out again by Python.

Python reads only what it must: a DFL file (handed over natively, a
stand-in checked before), and the theory a command also reasons with in
Python (clingo's plans, DFL). `AsWritten` is such a theory, read from
its files and unchanged since: reasoning.logic.prolog_load gives
SWI-Prolog its files, not its text; a copy of it with rules added after
its own (`extended`: the rules a refuted plan teaches) is given as its
files and the added rules' text. Any other theory changed or built in
Python is an ordinary Theory, given as its text.
"""
from __future__ import annotations

import hashlib
import tempfile
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Sequence

from pantarhei.bridge.engines.swipl import engine
from pantarhei.bridge.errors import UserError
from pantarhei.bridge.files import is_dfl
from pantarhei.bridge.theories.model import Theory


def prolog_read(paths: Sequence[str | Path] | None, pouring: bool = True, added: str = ""):
    """Make the theory files `paths` (the shipped theory for none) the
    current theory of the Prolog engine as they are written (see the
    module comment). With `pouring`, a warning on stderr for each name
    that is no proposition or expectation, as `ask` says it. Read again
    only when a file changed since the engine last read a theory.
    `added`: facts that Python added (native text), merged after the
    files."""
    from pantarhei.bridge.reasoning.asking import files_to_read, print_warnings

    files, _, unread = files_to_read([str(p) for p in paths] if paths else None)
    if unread is not None:
        raise UserError(unread)
    now = files_digest([p for p, _, _ in files], added)
    e = engine()
    if e.theory_digest != now:
        e.theory_digest = ""            # a theory not read leaves none
        with tempfile.TemporaryDirectory(prefix="pantarhei-theory-") as tmp:
            given = [(stand_in(p, Path(tmp) / f"t{i}.pl") if is_dfl(p)
                      else _as_is(p, Path(tmp) / f"t{i}.pl")) for i, (p, _, _) in enumerate(files)]
            if added:           # checked with the merged theory only (no file of its own)
                (Path(tmp) / "added.pl").write_text(added)
                given.append((str(Path(tmp) / "added.pl"), f"{_shown(files[-1][0])} (added)", True))
            warnings = e.load_theory_files(given)
        e.theory_digest = now
        if pouring:
            print_warnings(warnings)
    return e


def files_digest(paths: Sequence[str], added: str = "") -> str:
    """A digest of the files' names and bytes and of the text added after
    them (distinct from any digest of a theory's text that
    reasoning.logic.prolog_load keeps)."""
    h = hashlib.sha1(b"files as written")
    for p in paths:
        h.update(f"\0{p}\0".encode("utf-8", "surrogateescape") + Path(p).read_bytes())
    h.update(b"\0added\0" + added.encode())
    return h.hexdigest()


def _as_is(path: str, copy: Path) -> tuple[str, str, bool]:
    """A file read as written: itself, or for a name that is not UTF-8
    (which SWI-Prolog cannot be given), a copy of it, named as given."""
    try:
        path.encode("utf-8")
        return path, path, False
    except UnicodeEncodeError:
        copy.write_bytes(Path(path).read_bytes())
        return str(copy), _shown(path), False


def stand_in(path: str, native: Path) -> tuple[str, str, bool]:
    """A DFL file read and checked by Python, written natively into
    `native` for SWI-Prolog, with the lines of its names (written_at/4
    facts, which theory/ask.pl checks): a stand-in for it, (path, name,
    checked) as load_theory_files takes it."""
    from pantarhei.bridge.theories import loading
    from pantarhei.bridge.theories.prolog_checks import stand_in_text

    theory = loading.read_theory(path)
    loading.check_file(theory)      # its rules, names and superiority: SWI-Prolog's to check
    native.write_text(stand_in_text(theory))
    return str(native), _shown(path), True


def _shown(path: str) -> str:
    return path.encode("utf-8", "replace").decode("utf-8")


@dataclass
class AsWritten(Theory):
    """A theory read from `files` (the shipped theory for none) and not
    changed since: what SWI-Prolog is given is the files themselves."""
    files: tuple[str, ...] = ()
    #: What Python added to the files' theory (native text, merged after them).
    added: str = ""
    #: files_digest of the files when read, and the theory's content then
    read_as: tuple = field(default=(), compare=False, repr=False)

    def unchanged(self) -> bool:
        """Are the theory and its files as they were when it was read?"""
        return (bool(self.read_as) and self.read_as[1] == _content(self)
                and self.read_as[0] == files_digest(self.files))

    def extended(self, more: Theory) -> Theory:
        """`more`, a copy of this theory with facts, rules, sup/2 pairs,
        learned rules or provenance added after its own, as an AsWritten
        whose additions are given as text after the files; `more` itself
        when it is not such a copy, or this theory changed since read."""
        if not self.unchanged() or (more.settings, more.extra) != (self.settings, self.extra):
            return more
        tails = []
        for name in ("facts", "rules", "sup", "provenance"):
            have, now = getattr(self, name), getattr(more, name)
            if now[:len(have)] != have:
                return more
            tails.append(now[len(have):])
        if not self.learned <= more.learned:
            return more
        facts, rules, sup, provenance = tails
        added = self.added + Theory(facts, rules, sup, more.learned - self.learned,
                                    provenance=provenance).native()
        out = AsWritten(**{f.name: getattr(more, f.name) for f in fields(Theory)},
                        files=self.files, added=added)
        out.read_as = (self.read_as[0], _content(out))
        return out


def as_written(theory: Theory, paths: Sequence[str | Path] | None) -> AsWritten:
    """`theory`, read from the files `paths` (None: the shipped theory),
    marked as theirs; call it at once after reading them."""
    from pantarhei.bridge.reasoning.asking import files_to_read

    files, _, unread = files_to_read([str(p) for p in paths] if paths else None)
    if unread is not None:
        raise UserError(unread)
    out = AsWritten(**{f.name: getattr(theory, f.name) for f in fields(Theory)},
                    files=tuple(p for p, _, _ in files))
    out.read_as = (files_digest(out.files), _content(out))
    return out


def load_as_written(theory: AsWritten):
    """The Prolog engine holding `theory` read from its files (no
    warnings: they were said when Python read it), or None when it or
    they changed since (then the theory Python holds is the one meant)."""
    if not theory.unchanged():
        return None
    return prolog_read(theory.files, pouring=False, added=theory.added)


def _content(t: Theory) -> tuple:
    """What a theory holds, as a value to compare (no text is written)."""
    return (tuple(t.facts), tuple(t.rules), tuple(t.sup), frozenset(t.learned), tuple(t.extra),
            tuple((k, tuple(v)) for k, v in t.settings.items()), tuple(t.provenance))
