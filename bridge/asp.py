"""clingo hosted in this process: run an encoding over theory files."""
from __future__ import annotations

from pathlib import Path
from typing import Iterable, Sequence

from pantarhei.theory import THEORY_DIR, VOCABULARY_FILES, _clean_clingo_message

from .errors import CLINGO_MISSING, UserError


def _clingo():
    try:
        import clingo
    except ImportError:
        raise UserError(CLINGO_MISSING) from None
    return clingo


def solve(encodings: Sequence[str | Path], facts: str = "", *, files: Iterable[Path] = VOCABULARY_FILES,
          models: int = 1, args: Sequence[str] = ()) -> list[list]:
    """Ground and solve: the shown symbols of up to `models` answer sets
    (0 for all). `encodings` are names under theory/ or paths."""
    clingo = _clingo()
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
        raise UserError(_clean_clingo_message(first)) from None
    answers: list[list] = []
    with ctl.solve(yield_=True) as handle:
        for model in handle:
            answers.append(list(model.symbols(shown=True)))
    return answers
