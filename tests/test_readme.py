"""README stays true: its tables and figures are the vocabulary's."""
from pathlib import Path

from pantarhei.bridge.commands.vocab import markdown_tables
from pantarhei.bridge.reasoning.scenes import count_valid

README = (Path(__file__).resolve().parents[1] / "README.md").read_text()


def test_readme_tables_are_the_vocabulary():
    begin, end = "<!-- vocabulary:begin -->\n", "<!-- vocabulary:end -->"
    section = README[README.index(begin) + len(begin):README.index(end)]
    assert section == markdown_tables()


def test_readme_count_is_the_count():
    assert f"**{count_valid():,}**" in README


def test_quick_start_is_two_commands():
    start = README.index("## Quick start")
    block = README[README.index("```sh", start) + 5:README.index("```", README.index("```sh", start) + 5)]
    assert [line.split("#")[0].strip() for line in block.strip().splitlines()] == ["make demo", "make test"]


def test_readme_says_how_each_score_is_computed():
    from pantarhei.oracle.scoring import EXPLANATIONS

    begin, end = "<!-- scores:begin -->\n", "<!-- scores:end -->"
    section = README[README.index(begin):README.index(end)]
    for name, words in EXPLANATIONS.items():
        assert f"| `{name}` | {words} |" in section


def test_readme_headline_figures_are_the_shipped_evaluation():
    """README's evaluation table is the one `make evaluate` wrote to report/."""
    from pantarhei.bridge.evaluation.report import headline_markdown, load

    root = Path(__file__).resolve().parents[1]
    ev = load(root / "report" / "evaluation.json")
    begin, end = "<!-- evaluation:begin -->\n", "<!-- evaluation:end -->"
    section = README[README.index(begin) + len(begin):README.index(end)]
    assert section == headline_markdown(ev)
    assert ev.theory.endswith("theory/learned/pouring.pl")
