"""The options of Algorithm 1 (`pantarhei explore`, explore/1), declared
once as `option(Name, Type, Range, Default, Help)` facts, read here for
Python: the command line (bridge/commands/explore.py), the options Python
passes to explore/1 (bridge/exploration/explore_call.py) and the
reference page docs/options.md (`options_page`). SWI-Prolog checks
explore/1's options against the same facts (theory/curiosity/settings.pl).

theory/defaults.pl declares the options that every curiosity, or several,
read; an option that one curiosity alone reads is declared in that
curiosity's module (theory/curiosity/NAME.pl, NAME a value of the
`curiosity` row, the one list), as ground facts each starting a line, in
the language of theory files: its `option/5` row, and `prolog_only/1`
if it has no flag. Such an option is read by its curiosity alone (its
`used_by`). A curiosity's rows follow the `curiosity` row, the
curiosities in the list's order, each in its file's order; a row that a
fact `option_after(Name, Row)` places follows the row Row of
theory/defaults.pl instead (learn's budget, `pours`, beside `budget`).
A row named by a `prolog_only/1` fact is an option of explore/1's option
list alone: the command line has no flag for it (`Option.prolog_only`).
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any

from pantarhei.bridge.theories.facts import parse, read_facts
from pantarhei.theory.locations import DEFAULTS_FILE, THEORY_DIR

#: The reference page the table gives (`options_page`).
OPTIONS_PAGE = THEORY_DIR.parent / "docs" / "options.md"
#: The folder of the curiosities' modules (NAME.pl for the curiosity NAME).
CURIOSITY_DIR = THEORY_DIR / "curiosity"
#: What a curiosity's module declares of its own options.
DECLARED = ("option", "prolog_only", "option_after")
#: A declaration in a curiosity's module: a fact of DECLARED starting a
#: line and ending one, its quoted text read whole.
_DECLARATION = re.compile(r'^(?:%s)\((?:[^"]|"(?:[^"\\]|\\.)*")*?\)\.[ \t]*$'
                          % "|".join(DECLARED), re.M)


@dataclass(frozen=True)
class Option:
    """One row of the table. `low`/`high` bound a count or a number (high
    None: unbounded; numbers as floats, not thousandths), `choices` those of
    a choice, `default` the value as Python holds it (None: set otherwise,
    as the help says)."""
    name: str
    type: str
    low: float | None
    high: float | None
    choices: tuple
    default: Any
    help: str
    #: The project's default(Key, _) the default is, if it is one (theory, store).
    ref: str | None = None
    #: An option of explore/1's option list alone, without a flag (prolog_only/1).
    prolog_only: bool = False
    #: The curiosities that read it (used_by/2); empty: every curiosity.
    curiosities: tuple = ()

    def read_by(self, curiosity: str) -> bool:
        """Does the curiosity read this option?"""
        return not self.curiosities or curiosity in self.curiosities

    @property
    def flag(self) -> str:
        """The command line's flag: --name, or --no-name for a flag that is on by default."""
        dashed = self.name.replace("_", "-")
        return f"--no-{dashed}" if self.type == "flag" and self.default is True else f"--{dashed}"

    def value(self, v: Any) -> Any:
        """A value of the option as Python holds it (thousandths as a float)."""
        return v / 1000 if self.type == "permille" and isinstance(v, int) else v


@lru_cache(maxsize=None)
def option_table() -> tuple[Option, ...]:
    """The option table: the option/5 facts of theory/defaults.pl and of
    the modules of the curiosities it lists, in the table's order."""
    return read_table(DEFAULTS_FILE, CURIOSITY_DIR)


def read_table(defaults: Path, curiosity_dir: Path) -> tuple[Option, ...]:
    """The option table of the defaults file `defaults` and of the modules
    in `curiosity_dir` of the curiosities its `curiosity` row lists.
    ValueError for an option declared twice, or placed after no row of
    `defaults`."""
    facts = read_facts([defaults])
    project = {k: v for k, v in facts.get("default", [])}
    project["initial"] = tuple(p for (p,) in facts.get("default_initial", []))
    prolog_only = {name for (name,) in facts.get("prolog_only", [])}
    used: dict[str, tuple] = {}
    for name, curiosity in facts.get("used_by", []):
        used[name] = used.get(name, ()) + (curiosity,)
    shared = facts.get("option", [])
    choices = next(row[2][1:] for row in shared if row[0] == "curiosity")
    own: list[tuple] = []           # the curiosities' rows, each with where it goes
    for curiosity in choices:
        declared = declarations(curiosity_dir / f"{curiosity}.pl")
        after = dict(declared.get("option_after", []))
        prolog_only |= {name for (name,) in declared.get("prolog_only", [])}
        for row in declared.get("option", []):
            used[row[0]] = (curiosity,)
            own.append((after.get(row[0], "curiosity"), row))
    names = [row[0] for row in shared] + [row[0] for _, row in own]
    if twice := sorted({n for n in names if names.count(n) > 1}):
        raise ValueError(f"options declared twice: {', '.join(twice)}")
    if nowhere := sorted({at for at, _ in own} - {row[0] for row in shared}):
        raise ValueError(f"options placed after no row of {defaults.name}: {', '.join(nowhere)}")
    rows = [r for row in shared for r in (row, *(o for at, o in own if at == row[0]))]
    return tuple(_option(row, project, row[0] in prolog_only, used.get(row[0], ())) for row in rows)


def declarations(module: Path) -> dict[str, list[tuple]]:
    """What a curiosity's module declares of its own options: the facts of
    DECLARED in it (each starting a line), by predicate name, in file
    order; TheoryFileError (`file:line: what`) for one that is not a fact
    of a theory file."""
    text = module.read_text(encoding="utf-8")
    out: dict[str, list[tuple]] = {}
    for m in _DECLARATION.finditer(text):
        line = text.count("\n", 0, m.start()) + 1
        for fact in parse(m.group(0), str(module), line):
            out.setdefault(fact.name, []).append(fact.args)
    return out


def command_line_options() -> tuple[Option, ...]:
    """The rows `pantarhei explore` has a flag for: every row but the
    prolog_only ones, in file order."""
    return tuple(o for o in option_table() if not o.prolog_only)


def _option(row: tuple, project: dict, prolog_only: bool = False,
            curiosities: tuple = ()) -> Option:
    name, kind, rng, default, help_text = row
    low = high = ref = None
    choices: tuple = ()
    scale = 1000 if kind == "permille" else 1
    if isinstance(rng, tuple) and rng[0] == "range":
        low = rng[1] / scale if scale > 1 else rng[1]
        high = None if rng[2] == "none" else (rng[2] / scale if scale > 1 else rng[2])
    elif isinstance(rng, tuple) and rng[0] == "one_of":
        choices = tuple(rng[1:])
    if default == "none":       # a_0 is the default_initial facts; the others are set otherwise
        default = project["initial"] if kind == "antecedent" else None
    elif isinstance(default, tuple) and default[0] == "default":
        ref = default[1]
        default = project[ref]
    elif kind == "flag":
        default = default == "true"
    elif kind == "permille":
        default = default / 1000
    return Option(name, kind, low, high, choices, default, help_text, ref, prolog_only, curiosities)


def option(name: str) -> Option:
    """The table's row for `name`."""
    for o in option_table():
        if o.name == name:
            return o
    raise KeyError(name)


def options_page() -> str:
    """docs/options.md as the table gives it (tests/theory/test_option_table.py
    keeps the file equal to it; `python -m pantarhei.theory.option_table`
    writes it): the flags of `pantarhei explore`, then the options of
    explore/1's option list alone."""
    lines = ["# The options of `pantarhei explore`", "",
             "This page is written from the option table in `theory/defaults.pl`",
             "and in the curiosities' modules (`theory/curiosity/NAME.pl` declares",
             "the options that the curiosity NAME alone reads)",
             "(`python -m pantarhei.theory.option_table`). The same names are the",
             "options of `explore/1` at the Prolog prompt (`seed(3)` for `--seed 3`,",
             "underscores for dashes, `progress(false)` for `--no-progress`).",
             "An option is read by the curiosities its row names (`used_by/2` of",
             "`theory/defaults.pl`; an option of a curiosity's module, by that",
             "curiosity); one that the chosen curiosity does not read",
             "is refused in one line, at the prompt and on the command line",
             "(given at its default value on the command line, it changes nothing",
             "and is not passed on).", "",
             "| flag | values | default | read by | what it does |", "|---|---|---|---|---|"]
    for o in command_line_options():
        lines.append(f"| `{o.flag}` | {_values(o)} | {_default_text(o)} | {_readers(o)} | {o.help} |")
    lines += ["", "## Options of explore/1 alone", "",
              "These tune each curiosity's choices beyond its defaults, or choose",
              "the paper's planes and qualify. `explore/1` takes them in its option",
              "list (`pantarhei prolog`, then `explore([curiosity(discover),",
              "probe(0)])`); the command line has no flag for them. [Tried and",
              "dropped](dropped.md) gives, for each, the figure that kept its",
              "default.", "",
              "| option | values | default | read by | what it does |", "|---|---|---|---|---|"]
    for o in option_table():
        if o.prolog_only:
            lines.append(f"| `{o.name}(V)` | {_values(o)} | {_default_text(o)} | {_readers(o)} "
                         f"| {o.help} |")
    return "\n".join(lines) + "\n"


def _readers(o: Option) -> str:
    """The curiosities that read the option, as the page names them."""
    return ", ".join(f"`{c}`" for c in o.curiosities) if o.curiosities else "every"


def _values(o: Option) -> str:
    if o.choices:
        shown = [f"`{c}`" for c in o.choices]
        return shown[0] if len(shown) == 1 else ", ".join(shown[:-1]) + " or " + shown[-1]
    if o.type in ("count", "permille"):
        what = "whole number" if o.type == "count" else "number"
        return f"{what} from {_number(o.low)}" + (f" to {_number(o.high)}" if o.high is not None else "")
    return {"flag": "(a flag)", "antecedent": "propositions", "path": "file", "text": "text"}[o.type]


def _number(x: float) -> str:
    return str(int(x)) if float(x).is_integer() else f"{x:g}"


def default_text(o: Option) -> str:
    """The option's default as the help and the page show it ('' for a
    flag, or one set otherwise)."""
    if o.default is None or o.type == "flag":
        return ""
    if o.type == "antecedent":
        return ",".join(o.default)
    if o.ref == "theory":
        return f"theory/{o.default}"
    return _number(o.default) if isinstance(o.default, (int, float)) else str(o.default)


def _default_text(o: Option) -> str:
    text = default_text(o)
    return f"`{text}`" if text else ""


def write_options_page() -> None:
    """Write docs/options.md from the table."""
    OPTIONS_PAGE.write_text(options_page(), encoding="utf-8")


if __name__ == "__main__":
    write_options_page()
