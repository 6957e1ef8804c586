"""README stays a page for users and true; the reference pages it links
(docs/) hold the tables and texts that the code generates, and stay equal
to it."""
import re
import shlex
from pathlib import Path

import pytest

from pantarhei.bridge.commands.vocab import markdown_tables
from pantarhei.bridge.reasoning.valid_scenes import count_valid

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
README = (ROOT / "README.md").read_text()


def page(name: str) -> str:
    return (DOCS / name).read_text()


def between(text: str, begin: str, end: str) -> str:
    start = text.index(begin) + len(begin)
    return text[start:text.index(end, start)]


def fenced_blocks(text: str) -> list[str]:
    return re.findall(r"^```[a-z]*\n(.*?)^```", text, flags=re.S | re.M)


def links(text: str) -> list[str]:
    """The targets of the Markdown links of `text` (not inside code)."""
    prose = re.sub(r"^```.*?^```", "", text, flags=re.S | re.M)
    return re.findall(r"\]\(([^)\s]+)\)", prose)


def anchors(text: str) -> set[str]:
    """GitHub's anchors of the headings of a Markdown text."""
    prose = re.sub(r"^```.*?^```", "", text, flags=re.S | re.M)
    out = set()
    for heading in re.findall(r"^#+ (.+)$", prose, flags=re.M):
        slug = re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")
        out.add(slug)
    return out


# -- the reference pages hold what the code generates --------------------------

def test_vocabulary_tables_are_the_vocabulary():
    section = between(page("vocabulary.md"), "<!-- vocabulary:begin -->\n", "<!-- vocabulary:end -->")
    assert section == markdown_tables()


def test_vocabulary_count_is_the_count():
    assert f"**{count_valid():,}**" in page("vocabulary.md")


def test_oracle_page_says_how_each_score_is_computed():
    from pantarhei.oracle.scoring import EXPLANATIONS

    section = between(page("oracle.md"), "<!-- scores:begin -->", "<!-- scores:end -->")
    for name, words in EXPLANATIONS.items():
        assert f"| `{name}` | {words} |" in section


# -- README --------------------------------------------------------------------

def test_quick_start_is_two_commands():
    start = README.index("## Quick start")
    block = README[README.index("```sh", start) + 5:README.index("```", README.index("```sh", start) + 5)]
    assert [line.split("#")[0].strip() for line in block.strip().splitlines()] == ["make demo", "make test"]


def test_readme_types_in_no_measured_figures():
    """The figures are report/'s (written by `make evaluate`) and the
    benchmarks' own: README links them and types none in, so learning the
    theory again never leaves README behind."""
    from pantarhei.bridge.evaluation.headline import headline
    from pantarhei.bridge.evaluation.report import load

    assert "<!-- evaluation:" not in README
    assert re.findall(r"\d\s?%", README) == []                  # no percentages
    assert re.findall(r"\b\d+(?:\.\d+)?x\b", README) == []      # no ratios such as 2.00x
    assert "percent" not in README.lower()
    numbers = set(re.findall(r"(?<![\w.])\d+(?:\.\d+)?(?![\w.])", README))
    for measure, value, target, met in headline(load(ROOT / "report" / "evaluation.json")):
        if re.fullmatch(r"\d", str(value)):    # a count of one digit is any "section 3"
            continue
        assert not re.search(rf"(?<![\w.]){re.escape(str(value))}(?![\w.])", README), (measure, value)
        assert not numbers & set(re.findall(r"\d+\.\d+", str(value))), (measure, value)
    assert "](report/README.md)" in README
    assert "](benchmarks/)" in README


def test_readme_commands_exist():
    """Every command README's table lists is a `pantarhei` subcommand or a
    Makefile target."""
    from pantarhei.bridge.cli import parser

    subcommands = set(parser()._subparsers._group_actions[0].choices)
    targets = set(re.findall(r"^([a-z][\w-]*):", (ROOT / "Makefile").read_text(), flags=re.M))
    table = between(README, "## Commands\n\n", "\n\n")
    listed = re.findall(r"^\| `(pantarhei|make) ([\w-]+)", table, flags=re.M)
    assert len(listed) >= len(subcommands)
    for tool, name in listed:
        assert name in (subcommands if tool == "pantarhei" else targets), f"{tool} {name}"
    assert subcommands <= {name for tool, name in listed if tool == "pantarhei"}


def shown_command_lines() -> list[tuple[str, list[str]]]:
    """(file, arguments) of every `pantarhei` command line shown in a code
    block of README or docs/, comments and pipes taken out, every optional
    part ([...]) given, and the first of alternatives (a|b)."""
    lines = []
    for path in [ROOT / "README.md", *sorted(DOCS.glob("*.md"))]:
        for block in fenced_blocks(path.read_text()):
            for line in block.splitlines():
                line = line.removeprefix("$ ").strip()
                if not line.startswith(".venv/bin/pantarhei "):
                    continue
                line = line.split(" | ")[0]
                line = re.sub(r"\s#.*$", "", line)
                while re.search(r"\[[^\[\]]*\]", line):
                    line = re.sub(r"\[([^\[\]]*)\]", r"\1", line)
                args = [re.sub(r"^([\w-]+)(\|[\w-]+)+$", r"\1", a)
                        for a in shlex.split(line)[1:] if a != "..."]
                lines.append((path.name, args))
    return lines


def test_shown_commands_parse():
    """Every `pantarhei` command line README and docs/ show is one the
    command line accepts, options and all."""
    from pantarhei.bridge.cli import parser

    p = parser()
    for command in p._subparsers._group_actions[0].choices.values():
        command.allow_abbrev = False        # an option shown is spelled in full
    shown = shown_command_lines()
    assert any(f == "README.md" for f, _ in shown)
    for name, args in shown:
        try:
            p.parse_args(args)
        except SystemExit:
            pytest.fail(f"{name}: pantarhei {shlex.join(args)}")


def test_every_docs_page_is_linked_from_readme():
    linked = {t.split("#")[0] for t in links(README) if t.startswith("docs/")}
    pages = {f"docs/{p.name}" for p in DOCS.glob("*.md")}
    assert pages, "no docs/ pages"
    assert linked == pages, (sorted(linked - pages), sorted(pages - linked))


def test_links_of_readme_and_docs_resolve():
    """Every relative link of README and docs/ names a file that exists, and
    an anchor its heading gives."""
    for path in [ROOT / "README.md", *sorted(DOCS.glob("*.md"))]:
        for target in links(path.read_text()):
            if re.match(r"[a-z]+:", target):
                continue
            file, _, anchor = target.partition("#")
            where = (path.parent / file).resolve() if file else path
            assert where.exists(), f"{path.name}: {target}"
            if anchor:
                assert anchor in anchors(where.read_text()), f"{path.name}: {target}"


def test_readme_conclusions_example_prints_what_it_shows(tmp_path):
    """README's clingo example, run as written (in a temporary folder),
    prints exactly the lines it shows."""
    import subprocess

    block = next(b for b in fenced_blocks(README) if "conclusions --engine asp" in b)
    commands = [line[2:] for line in block.splitlines() if line.startswith("$ ")]
    shown = [line for line in block.splitlines() if not line.startswith("$ ")]
    script = "\n".join(commands).replace("/tmp/", f"{tmp_path}/")
    out = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", script], cwd=ROOT,
                         capture_output=True, text=True, check=True).stdout
    assert out.splitlines() == shown
