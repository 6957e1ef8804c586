"""`pantarhei ask`'s door to SWI-Prolog: one `swipl` process that reads the
theory files as they are written and answers questions about scenes
(theory/ask.pl, `serve/0`). Python turns words into propositions; the
reading, checking, answering and the deciding rule's words are Prolog's.

The process starts first, so that SWI-Prolog reads the theory while
Python reads the question; a request is one line, its reply lines ending
in `end`. No Python copy of the theory is made. SWI-Prolog starts from a
compiled state of the theory's modules, cached per source and swipl
(`compiled_state`), once the first question has compiled it.
"""
from __future__ import annotations

import os
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path

from pantarhei.bridge.errors import SWIPL_MISSING, UserError
from pantarhei.theory import THEORY_DIR


@dataclass(frozen=True)
class Evidence:
    """The pours behind an answer, counted for the expectation holding
    (the polarity of the answer's likelihood, whatever the deciding
    rule's head): `held` of the `pours` learned from that could have been
    drawn for the propositions `of`: the scene asked when it is an
    antecedent `explored` (its id) without a rule of its own for the
    expectation, else the deciding rule's `body` (None where the rule
    records no pours: written by hand, or one of Algorithm 1's); and
    `unruled`, the propositions of the scene the rule's body does not hold
    (no rule of their own decides: they are answered as the body)."""
    held: int | None
    pours: int | None
    body: tuple[str, ...]
    unruled: tuple[str, ...]
    explored: str | None = None
    of: tuple[str, ...] = ()

    def as_json(self) -> dict:
        return {"held": self.held, "pours": self.pours, "of": list(self.of),
                "explored": self.explored, "body": list(self.body),
                "unruled": list(self.unruled)}


@dataclass(frozen=True)
class Answer:
    """What the theory says about one expectation in a scene."""
    expectation: str
    value: str          # "holds", "fails", "uncertain" or "unknown"
    #: the share of such pours in which the expectation holds: the
    #: deciding rule's estimate, pooled from every pour learned from
    likelihood: float | None
    rule: str | None    # the rule named for it (ask:named_rule/2), "fact", or None (unknown)
    because: str        # why, in one line: the deciding rule in words, or why not
    reason: str         # for an undecided expectation, its brief why-not
    evidence: Evidence | None = None    # the pours behind it (None: given, or unknown)


def answer_of(fields: list[str]) -> Answer:
    """An Answer from the fields of ask:answers/3's answer/7, as text
    (serve/0's reply: the evidence as ask:evidence_fields/7 writes it)."""
    exp, value, p, rule, because, reason, *ev = fields
    evidence = None
    if value != "unknown" and rule not in ("fact", "none"):
        held, of, body, unruled, explored, counted = ev
        evidence = Evidence(None if held == "none" else int(held),
                            None if of == "none" else int(of),
                            tuple(x for x in body.split(",") if x),
                            tuple(x for x in unruled.split(",") if x),
                            None if explored == "none" else explored,
                            tuple(x for x in counted.split(",") if x))
    return Answer(exp, value, None if p == "none" else float(p),
                  None if value == "unknown" else rule, because, reason, evidence)


class Door:
    """One swipl process serving questions to the theory of `files`:
    (path read, name said, checked) each, `checked` for a file that
    stands in for another that was read and checked already (a DFL file
    written out natively); with none and `unread`, it checks scenes only.
    Use as a context manager."""

    def __init__(self, files: list[tuple[str, str, bool]], source: str,
                 unread: str | None = None) -> None:
        #: The theory's name: its files' names joined with " + ".
        self.source = source
        #: Why the theory was not given (no such file...), said once a
        #: question's scene is found valid; None when it was.
        self.unread = unread
        #: The shipped theory's path when the files named stand in place of
        #: it (it is not among them): the answers say so; None otherwise.
        self.replaces: str | None = None
        swipl = shutil.which("swipl")
        if swipl is None:
            raise UserError(SWIPL_MISSING)
        args: list[str] = []
        fds: list[int] = []
        try:
            for path, name, checked in files:
                path = _utf8_path(path, fds)
                args += [("checked:" if checked else "file:") + path, _utf8(str(name))]
            self._process = subprocess.Popen(
                [*serving(swipl), "--", *args], pass_fds=fds,
                stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                text=True, encoding="utf-8", errors="replace")
        finally:
            for fd in fds:
                os.close(fd)
        self._status: tuple[list[tuple[str, str, str]], str | None] | None = None

    def __enter__(self) -> "Door":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def close(self) -> None:
        p = self._process
        if p.poll() is None:
            try:
                p.stdin.close()
                p.wait(timeout=5)
            except (OSError, subprocess.TimeoutExpired):
                p.kill()
                p.wait()
        for f in (p.stdout, p.stderr):
            f.close()

    def _line(self) -> str:
        line = self._process.stdout.readline()
        if not line:
            err = self._process.stderr.read().strip().splitlines()
            raise UserError(f"SWI-Prolog stopped: {err[-1] if err else 'no reason given'}")
        return line.rstrip("\n")

    def status(self) -> tuple[list[tuple[str, str, str]], str | None]:
        """The unknown names the theory's rules use, (where, what, name),
        and the one line that says why the theory could not be read (None
        when it was). The first call prints the warnings (print_warnings)."""
        if self._status is None:
            warnings = []
            while True:
                kind, *fields = self._line().split("\t")
                if kind == "warning":
                    warnings.append(tuple(fields))
                    continue
                self._status = (warnings, fields[0] if kind == "error" else None)
                break
            print_warnings(warnings)
        return self._status

    def require_theory(self) -> None:
        """UserError if the theory was not given or could not be read (its
        warnings are printed)."""
        _, error = self.status()
        if self.unread or error:
            raise UserError(self.unread or error)

    def _ask(self, request: str) -> list[list[str]]:
        """The reply lines to one request, split at tabs."""
        self.status()
        try:
            self._process.stdin.write(request + "\n")
            self._process.stdin.flush()
        except BrokenPipeError:
            pass                                  # _line says why
        out = []
        while True:
            line = self._line()
            if line == "end":
                return out
            out.append(line.split("\t"))

    def _reply(self, request: str) -> list[list[str]]:
        """The reply to a request about a scene: UserError naming the first
        violated constraint if the scene is not valid, else why the theory
        was not given (`unread`), else why it could not be read."""
        reply = self._ask(request)
        bad = [r[1:] for r in reply if r[0] == "invalid"]
        if bad:
            from pantarhei.bridge.reasoning.valid_scenes import Violation, invalid

            raise UserError(invalid([Violation(*v) for v in bad]))
        if self.unread:
            raise UserError(self.unread)
        errors = [r[1] for r in reply if r[0] == "error"]
        if errors:
            raise UserError(errors[0])
        return reply

    def answers(self, scene: list[str]) -> list[Answer]:
        """One Answer per expectation for the scene (its propositions)."""
        reply = self._reply(f"answer({_list(scene)}).")
        return [answer_of(r[1:]) for r in reply if r[0] == "answer"]

    def why(self, scene: list[str], literal: str) -> str:
        """Why (or why not) the theory concludes `literal` in the scene, in
        words, sentences separated by "; "."""
        return self.why_proof(scene, literal)[0]

    def why_proof(self, scene: list[str], literal: str) -> tuple[str, dict]:
        """`why`'s words, and the argument as a structure
        (theory/ask.pl's proof_json/2): its kind, literal, rule, the proofs
        of the rule's body, and the rules against it and why each loses,
        or why it is not concluded."""
        import json

        reply = self._reply(f"why({_list(scene)}, {literal}).")
        text = next(r[1] for r in reply if r[0] == "why")
        proof = next(("\t".join(r[1:]) for r in reply if r[0] == "proof"), "null")
        return text, json.loads(proof)


def _utf8(text: str) -> str:
    """Text that SWI-Prolog can take as an argument: a byte of a file name
    that is not UTF-8 (held as a surrogate escape) shown as U+FFFD."""
    return text.encode("utf-8", "replace").decode("utf-8")


def _utf8_path(path: str, fds: list[int]) -> str:
    """`path` as SWI-Prolog can take it: itself, or for a name that is not
    UTF-8, the file opened here and handed over as /dev/fd/N (its
    descriptor added to `fds`)."""
    try:
        str(path).encode("utf-8")
        return str(path)
    except UnicodeEncodeError:
        fd = os.open(path, os.O_RDONLY)
        fds.append(fd)
        return f"/dev/fd/{fd}"


def serving(swipl: str) -> list[str]:
    """The command that starts theory/ask.pl's serve/0: from a compiled
    state of the theory's modules when one is cached for these sources and
    this swipl (it starts in a third of the time), else from the sources,
    compiling the state meanwhile for the next question."""
    goal = ["-q", "--no-signals", "-g", "ask:serve", "-t", "halt"]
    state = compiled_state(swipl)
    if state is not None and _usable(state):
        return [swipl, "-x", str(state), *goal]
    if state is not None:
        _compile_state(swipl, state)
    return [swipl, *goal, str(THEORY_DIR / "ask.pl")]


def _usable(state: Path) -> bool:
    """Is the cached state there and whole (a ZIP archive, as SWI-Prolog
    saves it)? One that is not (cut short, overwritten) is removed, so that
    it is compiled again; a cache folder that cannot be read is no cache."""
    import zipfile

    try:
        if not state.is_file():
            return False
        if zipfile.is_zipfile(state):
            return True
        state.unlink()
    except OSError:
        pass
    return False


def compiled_state(swipl: str) -> Path | None:
    """Where the compiled state of theory/ask.pl and the modules it loads
    is cached: named by a digest of every Prolog file of theory/ (the
    learned theories aside: they are read when asked) and of the swipl
    binary, so that a changed source or another SWI-Prolog never uses an
    old state. None when there is no cache folder to write."""
    from pantarhei.bridge.reasoning.cache_files import cache_file, theory_sources

    return cache_file("ask", [Path(swipl).resolve(), *theory_sources()], ".state")


def _compile_state(swipl: str, state: Path) -> None:
    """Compile the state in the background, into a file of its own that
    is renamed to `state` when whole (nothing is written if the cache
    folder cannot be made)."""
    try:
        state.parent.mkdir(parents=True, exist_ok=True)
        if not os.access(state.parent, os.W_OK | os.X_OK):
            return
    except OSError:
        return
    tmp = state.with_name(f".{state.name}.{os.getpid()}")
    subprocess.Popen(["sh", "-c", 'swipl="$1"; tmp="$2"; "$swipl" -q -o "$tmp" -c "$3" -g true '
                      '&& mv -f "$tmp" "$4" || rm -f "$tmp"', "sh", swipl, str(tmp),
                      str(THEORY_DIR / "ask.pl"), str(state)],
                     stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                     stderr=subprocess.DEVNULL, start_new_session=True)


def _list(names: list[str]) -> str:
    """Names (checked: propositions of the vocabulary) as a Prolog list."""
    return "[" + ", ".join(names) + "]"


def print_warnings(warnings: list[tuple[str, str, str]]) -> None:
    """`warning: file:line: ...` on stderr for each name of a rule that is
    no proposition or expectation (theory/ask.pl found them), with the
    nearest known name: the words of bridge/theories/unknown_names.py, at
    most WARNINGS_AT_MOST of them one a line."""
    if not warnings:
        return
    from pantarhei.bridge.theories import unknown_names

    unknown_names.print_warnings(warnings, WARNINGS_AT_MOST)


#: The most names print_warnings shows one a line (a file of 20,000 unknown
#: names would print 20,000 lines, each matched against the vocabulary).
WARNINGS_AT_MOST = 20


def files_to_read(paths: list[str] | None) -> tuple[list[tuple[str, str, bool]], str, str | None]:
    """The files the door reads for the theory files a user named (the
    shipped theory for none), (path, name, False) each, their names joined
    with " + ", and why they cannot be read (None when they can; then no
    file: the door checks scenes only)."""
    from pantarhei.bridge.files import theory_file_problem
    from pantarhei.theory import default_theory

    if not paths:
        shipped = default_theory()
        if not shipped.is_file():
            from pantarhei.bridge.theories.loading import NO_THEORY

            return [], str(shipped), NO_THEORY
        paths = [str(shipped)]
    for p in paths:
        problem = theory_file_problem(p)
        if problem:
            return [], " + ".join(paths), problem
    return [(p, p, False) for p in paths], " + ".join(paths), None


def replaced_shipped(paths: list[str] | None) -> str | None:
    """The shipped theory's path when theory files are named and it is not
    among them (they replace it), else None."""
    from pantarhei.theory import default_theory

    if not paths:
        return None
    shipped = default_theory()
    for p in paths:
        try:
            if Path(p).resolve() == shipped.resolve():
                return None
        except (OSError, RuntimeError, ValueError):
            continue
    relative = os.path.relpath(shipped)
    return str(shipped) if relative.startswith("..") else relative
