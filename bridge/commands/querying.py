"""`pantarhei ask`, `conclusions`, `convert`: questions to a defeasible theory
(`plan` is plan.py)."""
from __future__ import annotations

import argparse
import json
import re
import sys

from pantarhei.bridge.commands import options
from pantarhei.bridge.commands.answering import answer    # demo asks through it too
from pantarhei.bridge.errors import UserError, safe_line
from pantarhei.bridge.reasoning.valid_scenes import known

#: The engines of `conclusions` (bridge/reasoning/logic.py's ENGINES; named
#: here so that declaring the flag does not start SWI-Prolog).
ENGINES = ("prolog", "asp")

THEORY_HELP = ("theory file, native facts or .dfl, in place of the shipped learned theory "
               "theory/learned/pouring.pl (the default); repeat to merge files, e.g. the shipped "
               "theory and rules written by hand")


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("ask", help="what happens when pouring like this? (Prolog)")
    p.add_argument("question", nargs="?",
                   help='the scene in words, e.g. "pour from the side"; without it (or with -), '
                        'one question a line from standard input, each answered at once')
    p.add_argument("--props", help="the scene as propositions P1,P2 (instead of words)")
    p.add_argument("--theory", action="append", metavar="FILE", help=THEORY_HELP)
    p.add_argument("--why", metavar="LITERAL",
                   help="explain why the theory concludes LITERAL in the scene, or why not "
                        "(an expectation, or neg(E))")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.add_argument("--check", type=options.count(0, options.VERIFY_MAX), default=0, metavar="N",
                   help="also simulate N pours of the question (seeded, kept in --store, with the "
                        "oracle the theory was learned from) and show the share observed beside "
                        "each answer, flagging those the pours contradict (default 0: none)")
    options.add_seed(p, 0, "--check's sampling")
    options.add_store(p, "simulations for --check")
    p.set_defaults(run=ask, pin=lambda args: args.check > 0)     # --check simulates
    # a negated expectation after --why (-no_spill) is its value, not an option:
    # argparse takes an argument that this matches for a value (every
    # expectation's name holds an underscore, no option of ask does)
    p._negative_number_matcher = re.compile(r"^-\d+$|^-\d*\.\d+$|^-[a-z][a-z0-9]*_[a-z0-9_]+$")

    p = sub.add_parser("conclusions", help="all conclusions (+D, -D, +d, -d) of a theory file")
    p.add_argument("file", nargs="+", metavar="FILE", help="theory file(s), native facts or .dfl")
    p.add_argument("--ambiguity", choices=("blocking", "propagation"), default="blocking")
    p.add_argument("--no-team-defeat", action="store_true", help="a single rule must beat every attacker")
    p.add_argument("--no-well-founded", action="store_true",
                   help="Kunen semantics: literals whose proofs loop stay undecided")
    p.add_argument("--engine", choices=ENGINES, default="prolog")
    p.add_argument("--json", action="store_true", help="print JSON")
    p.set_defaults(run=conclusions)

    p = sub.add_parser("convert", help="write a theory in DFL (SPINdle, silkie) or in the native format")
    p.add_argument("file", nargs="+", metavar="FILE", help="theory file(s), native facts or .dfl")
    p.add_argument("--to", choices=("dfl", "native"), default="dfl", help="output format (default dfl)")
    p.add_argument("-o", "--output", metavar="OUT", help="write to OUT instead of printing")
    p.set_defaults(run=convert)


def _split(text: str | None) -> list[str]:
    return [x.strip() for x in (text or "").split(",") if x.strip()]


# -- ask ----------------------------------------------------------------------

def ask(args: argparse.Namespace) -> int:
    from pantarhei.bridge.reasoning.pattern_store import kept_patterns

    with kept_patterns():          # the reader's patterns, compiled by an earlier question
        return _ask(args)


def _ask(args: argparse.Namespace) -> int:
    from pantarhei.bridge.reasoning.asking import Door, replaced_shipped

    for flag in ("question", "props", "why"):
        if getattr(args, flag) is not None:
            utf8(getattr(args, flag), "the question" if flag == "question" else f"--{flag}")
    if args.props is not None and args.question:
        raise UserError("give the scene in words or with --props, not both")
    if args.why is not None and not args.why.strip():
        raise UserError("--why: give an expectation E or neg(E) (see `pantarhei vocab`)")
    if args.check and args.why is not None:
        raise UserError("--check checks the answers: ask without --why")
    with _stand_ins(args.theory) as (files, source, unread):
        with Door(files, source, unread) as door:    # SWI-Prolog reads the theory meanwhile
            door.replaces = replaced_shipped(args.theory)
            with _checker(args, files) as check:
                args.checker = check
                if args.props is None and args.question in (None, "-"):    # one question a line
                    door.require_theory()
                    return _ask_each_line(args, door, bounded_lines(sys.stdin.buffer))
                if args.props is not None:
                    props = known(_split(args.props))
                    if not props:
                        raise UserError("--props: no propositions given (see `pantarhei vocab`)")
                else:
                    props = known(_understood(args.question))
                if check is not None:
                    door.require_theory()
                return answer(door, props, _why_literal(args.why), args.json, check=check)


def _checker(args: argparse.Namespace, files):
    """--check's simulator (answering.Checker), or a context of None."""
    import contextlib

    if not args.check:
        return contextlib.nullcontext()
    from pantarhei.bridge.commands.answering import Checker
    from pantarhei.bridge.reasoning.checking import checking_oracle

    return Checker(args.check, args.seed, args.store, checking_oracle([p for p, _, _ in files]))


def _why_literal(why: str | None) -> str | None:
    """--why's literal (E, -E or neg(E)) as a native literal."""
    if why is None:
        return None
    from pantarhei.bridge.reasoning.literals import goal_literal

    return goal_literal(why)


class _stand_ins:
    """The theory files `ask` reads (the shipped theory for none): (path,
    name, checked) each, their names, and why they cannot be read (None
    when they can). A DFL file is read and checked here and written out
    natively for SWI-Prolog to read; that file is removed on exit."""

    def __init__(self, paths: list[str] | None) -> None:
        self.paths = paths
        self.temporary: list[str] = []

    def __enter__(self):
        from pantarhei.bridge.reasoning.asking import files_to_read
        from pantarhei.bridge.files import is_dfl

        files, source, unread = files_to_read(self.paths)
        if unread is None and any(is_dfl(p) for p, _, _ in files):
            files = [self._native(p) if is_dfl(p) else (p, n, c) for p, n, c in files]
        return files, source, unread

    def _native(self, path: str) -> tuple[str, str, bool]:
        import os
        import tempfile
        from pathlib import Path

        from pantarhei.bridge.reasoning.written_theory import stand_in

        fd, name = tempfile.mkstemp(suffix=".pl", prefix="pantarhei-theory-")
        os.close(fd)
        try:
            out = stand_in(path, Path(name))
        except BaseException:           # __exit__ is not called for it
            os.unlink(name)
            raise
        self.temporary.append(name)
        return out

    def __exit__(self, *exc) -> None:
        import os

        for name in self.temporary:
            os.unlink(name)


def utf8(text: bytes | str, what: str) -> str:
    """`text` as a str; UserError naming the first byte that is not UTF-8
    (an argument holds it as a surrogate escape)."""
    if isinstance(text, str):
        text = text.encode("utf-8", "surrogateescape")
    try:
        return text.decode("utf-8")
    except UnicodeDecodeError as e:
        raise UserError(f"{what}: byte {text[e.start]:#04x} is not UTF-8: give text in UTF-8") from None


def _understood(question: str) -> list[str]:
    """The propositions of a question in words (none: the ordinary pour;
    UserError for a question that says nothing of a pour)."""
    from pantarhei.bridge.reasoning.reading import understand

    return understand(question)


#: The longest question read from standard input (bytes); a longer line is
#: skipped unread, with one line saying so, so that memory stays bounded.
LINE_BYTES_AT_MOST = 65536


def bounded_lines(stream, at_most: int = LINE_BYTES_AT_MOST):
    """The lines of the binary `stream`, read one at a time, each of at most
    `at_most` bytes; a longer line is read past in pieces of that size and
    given as None."""
    while True:
        line = stream.readline(at_most + 1)
        if not line:
            return
        if len(line) <= at_most or line.endswith(b"\n") and len(line) == at_most + 1:
            yield line
            continue
        while line and not line.endswith(b"\n"):
            line = stream.readline(at_most)
        yield None


def _ask_each_line(args: argparse.Namespace, door, lines) -> int:
    """Answer each question of `lines` (bytes, UTF-8) as it comes (a blank
    line or one starting with # is skipped); a question not understood, or
    not UTF-8, gets its one line on stderr and the next is read. With
    --json, each answer is one line of JSON (JSON Lines) that names its
    line and question. Exit 0 if every one was answered."""
    asked = failed = 0
    for number, raw in enumerate(lines, 1):
        if raw is None:
            failed += 1
            print(f"pantarhei ask: line {number}: longer than {LINE_BYTES_AT_MOST} bytes: "
                  f"not read", file=sys.stderr, flush=True)
            continue
        question = raw.strip()
        if not question or question.startswith(b"#"):
            continue
        if asked and not args.json:
            print()
        asked += 1
        try:
            question = utf8(question, "the question")
            answer(door, known(_understood(question)), _why_literal(args.why), args.json,
                   json_line={"line": number, "question": question},
                   check=getattr(args, "checker", None))
        except UserError as e:
            failed += 1
            print(safe_line(f"pantarhei ask: line {number}: {e}"), file=sys.stderr, flush=True)
        sys.stdout.flush()
    if not asked:
        raise UserError("give a scene: a question in words, --props P1,P2, or questions one a "
                        "line on standard input")
    return 1 if failed else 0


# -- conclusions --------------------------------------------------------------

def conclusions(args: argparse.Namespace) -> int:
    from pantarhei.bridge.reasoning import logic
    from pantarhei.bridge.theories import loading
    from pantarhei.bridge.theories.dfl import dfl_literal

    sem = logic.Semantics(args.ambiguity, not args.no_team_defeat, not args.no_well_founded)
    if args.engine == "prolog":     # SWI-Prolog reads the files as written
        result = logic.prolog_file_conclusions(args.file, sem)
    else:
        result = logic.conclusions(loading.load(args.file), sem, args.engine)
    dfl = {tag: [dfl_literal(x) for x in lits] for tag, lits in result.items()}
    if args.json:
        print(json.dumps(dfl, indent=1))
        return 0
    for tag in logic.TAGS:
        for lit in dfl[tag]:
            print(f"{tag} {lit}")
    return 0


# -- convert ------------------------------------------------------------------

def convert(args: argparse.Namespace) -> int:
    from pathlib import Path

    from pantarhei.bridge.files import require_writable_file, write_text
    from pantarhei.bridge.theories import loading

    out = Path(args.output) if args.output else None
    if out is not None:       # said before reading (converting in place is allowed)
        if not out.parent.is_dir():
            raise UserError(f"{out}: no such directory {out.parent}")
        require_writable_file(out, "-o")
    theory = loading.load(args.file, check=False)
    text = loading.converted(theory, args.to, args.output)
    if out is None:
        print(text, end="")
        return 0
    try:
        write_text(out, text)
    except OSError as e:      # a read-only or full file system: nothing was written
        raise UserError(f"-o {out}: cannot write ({e.strerror or e}); nothing was written") from None
    print(f"wrote {len(theory.rules)} rules, {len(theory.facts)} facts to {out}")
    return 0
