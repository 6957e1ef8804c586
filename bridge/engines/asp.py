"""clingo hosted in this process: run an encoding over theory files."""
from __future__ import annotations

from pathlib import Path
from typing import Iterable, Sequence

from pantarhei.theory import THEORY_DIR, VOCABULARY_FILES

from pantarhei.theory import clingo_module

from pantarhei.bridge.errors import UserError


def solve(encodings: Sequence[str | Path], facts: str = "", *, files: Iterable[Path] = VOCABULARY_FILES,
          models: int = 1, args: Sequence[str] = ()) -> list[list]:
    """Ground and solve: the shown symbols of up to `models` answer sets
    (0 for all). `encodings` are names under theory/ or paths."""
    clingo = clingo_module()
    messages: list[str] = []
    ctl = clingo.Control([f"--models={models}", "--warn=none", *args],
                         logger=lambda _c, m: messages.append(m), message_limit=1)
    try:
        for f in files:
            ctl.load(str(f))
        for e in encodings:
            ctl.load(str(e if Path(e).is_absolute() else THEORY_DIR / e))
        if facts:
            ctl.add("base", [], facts)
        ctl.ground([("base", [])])
    except RuntimeError:
        first = messages[0].splitlines()[0] if messages else "clingo could not read the theory"
        raise UserError(clingo_message(first)) from None
    answers: list[list] = []
    with ctl.solve(yield_=True) as handle:
        for model in handle:
            answers.append(list(model.symbols(shown=True)))
    return answers


class Checker:
    """An encoding grounded once over the vocabulary, with `Name(P)` as an
    external atom for every proposition P; `shown(props)` sets exactly the
    given ones true and returns the shown symbols of the (single) answer.
    Fast for many small questions, such as validity checks."""

    def __init__(self, encodings: Sequence[str | Path], name: str) -> None:
        clingo = clingo_module()
        self._clingo = clingo
        self._ctl = clingo.Control(["--warn=none"])
        for f in VOCABULARY_FILES:
            self._ctl.load(str(f))
        for e in encodings:
            self._ctl.load(str(e if Path(e).is_absolute() else THEORY_DIR / e))
        self._ctl.add("base", [], f"#external {name}(P) : proposition(P, _, _, _).")
        self._ctl.ground([("base", [])])
        self._atoms = {str(a.symbol.arguments[0]): a.symbol
                       for a in self._ctl.symbolic_atoms.by_signature(name, 1)}

    def shown(self, props: Iterable[str]) -> list:
        on = set(props)
        for name, atom in self._atoms.items():
            self._ctl.assign_external(atom, name in on)
        with self._ctl.solve(yield_=True) as handle:
            for model in handle:
                return list(model.symbols(shown=True))
        return []


def clingo_message(message: str) -> str:
    """clingo's message in one line as `file:line: what`:
    "file:12:5-9: error: syntax error, unexpected ." -> "file:12: syntax error, unexpected ."."""
    import re

    m = re.match(r"^(.*?):(\d+):\d+(?:-\d+(?::\d+)?)?: (?:error|info): (.*)$", message)
    if not m:
        return message
    return f"{m.group(1)}:{m.group(2)}: {m.group(3)}"
