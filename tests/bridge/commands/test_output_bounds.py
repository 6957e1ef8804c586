"""What the writing commands refuse before writing, in one line: a report
folder holding a file of the report's name that no report wrote, a render
whose frames would pass the memory it states, more pours than simulate
holds, a --params file past its size; and every error line is safe to
print (control characters escaped, a long input cut)."""
from __future__ import annotations

import json

from pantarhei.bridge.commands.evaluate import MANIFEST, record_own, require_own
from pantarhei.bridge.commands.simulate import PARAMS_BYTES_AT_MOST, POURS_AT_MOST
from pantarhei.bridge.errors import LINE_AT_MOST, UserError, escaped, safe_line

import pytest

from tests.conftest import assert_one_line_error, run_cli


def test_a_report_folder_with_a_persons_readme_is_refused(tmp_path):
    (tmp_path / "README.md").write_text("# My notes\n")
    r = run_cli("evaluate", "--out", str(tmp_path), "--no-progress")
    assert "'README.md' was not written by a report" in assert_one_line_error(r)
    assert (tmp_path / "README.md").read_text() == "# My notes\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["README.md"]


def test_the_report_rewrites_only_what_it_recorded_unchanged(tmp_path):
    (tmp_path / "README.md").write_text("# Evaluation of `t.pl`\n")      # a report's
    (tmp_path / "notes.txt").write_text("mine")                          # not the report's name
    require_own(tmp_path)
    record_own(tmp_path)
    assert set(json.loads((tmp_path / MANIFEST).read_text())) == {"README.md"}
    require_own(tmp_path)
    (tmp_path / "README.md").write_text("# Evaluation of `t.pl`\nedited by hand\n")
    with pytest.raises(UserError, match="or was changed since"):
        require_own(tmp_path)
    (tmp_path / MANIFEST).write_text("[1, 2]")
    with pytest.raises(UserError, match="is not the report's record"):
        require_own(tmp_path)


def test_render_refuses_frames_past_its_memory_bound_before_simulating(tmp_path):
    out = tmp_path / "p.gif"
    r = run_cli("render", "--antecedent", "pour_low", "--size", "4096x4096", "--out", str(out))
    line = assert_one_line_error(r)
    assert "more than the 512 MiB render holds at most" in line and not out.exists()
    r = run_cli("render", "--antecedent", "pour_low", "--size", "1024x1024", "--fps", "240",
                "--out", str(out))
    assert "give a smaller --size or --fps" in assert_one_line_error(r)


def test_simulate_refuses_more_pours_than_it_holds(tmp_path):
    r = run_cli("simulate", "--antecedent", "pour_low", "-n", str(POURS_AT_MOST + 1), "--no-store")
    assert f"must be at most {POURS_AT_MOST}" in assert_one_line_error(r)
    big = tmp_path / "p.json"
    big.write_bytes(b"[" + b" " * PARAMS_BYTES_AT_MOST + b"]")
    r = run_cli("simulate", "--params", str(big), "--no-store")
    assert "larger than 16 MiB" in assert_one_line_error(r)
    deep = tmp_path / "deep.json"
    deep.write_text("[" * 100_000 + "]" * 100_000)
    r = run_cli("simulate", "--params", str(deep), "--no-store")
    assert "nested too deeply" in assert_one_line_error(r)


def test_an_error_line_escapes_control_characters_and_cuts_long_inputs():
    assert escaped("a\x1b[2Jb\x07c\rd\ne\u2028") == "a\\x1b[2Jb\\x07c\\rd\\ne\\u2028"
    line = safe_line("x" * 1_000_000)
    assert len(line) <= LINE_AT_MOST and "more ...]" in line


def test_a_question_with_terminal_escapes_comes_back_escaped():
    r = run_cli("ask", "\x1b]0;pwned\x07\x1b[2J zorbleflax " + "q" * 100_000)
    line = assert_one_line_error(r, code=r.code or 2)
    assert "\x1b" not in r.err and "\x07" not in r.err and len(line) <= LINE_AT_MOST + 40
