"""The warning that says each name a theory of pouring's rules use that
the vocabulary does not know. The check that finds them is
theory/theory_checks.pl's alone, made by theory/ask.pl's load_theories/3: `ask` (and every command that gives SWI-Prolog the files as
written) has it made of the files it reads, and of a DFL file's stand-in
at the DFL file's lines (its `written_at/4` facts); a theory Python read
for a command that also reasons with it in Python (plan, demo) is handed
to the same check, its facts at the lines Python read them
(bridge/theories/prolog_checks.py). The words are
theory/check_messages.pl's (`unknown_name`), with the nearest known name
as a hint, said here alone."""
from __future__ import annotations

import sys


def warning_lines(unknown: list[tuple[str, str, str]], at_most: int | None = None) -> list[str]:
    """`warning: file:line: ...` for each unknown name (where, what, name),
    with the nearest known name; past `at_most` of them, one line that
    says how many more."""
    if not unknown:
        return []
    import difflib

    from pantarhei.theory import check_message
    from pantarhei.theory.lexicon import load_vocabulary

    vocab = load_vocabulary()
    known = sorted(set(vocab.propositions) | set(vocab.expectation_names))
    shown = unknown if at_most is None else unknown[:at_most]
    out = []
    for where, what, name in shown:
        near = difflib.get_close_matches(name, known, n=1, cutoff=0.6)
        hint = f" (did you mean {near[0]}?)" if near else ""
        out.append(f"warning: {where}: {check_message('unknown_name', what, name)}{hint}")
    if len(unknown) > len(shown):
        out.append(f"warning: and {len(unknown) - len(shown)} more names that are not "
                   f"propositions or expectations of pouring")
    return out


def print_warnings(unknown: list[tuple[str, str, str]], at_most: int | None = None) -> None:
    """warning_lines on stderr."""
    for line in warning_lines(unknown, at_most):
        print(line, file=sys.stderr)
