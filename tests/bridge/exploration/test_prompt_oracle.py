"""The oracle at the Prolog prompt (bridge/exploration/prompt_oracle.py,
theory/curiosity/oracle_prompt.pl's sample/4, simulate/3 and describe/2), as `pantarhei prolog -g`
runs them."""
from __future__ import annotations

from tests.conftest import run_cli


def test_prolog_command_samples_and_simulates(tmp_path):
    goal = (f"sample([pour_to_side, pour_steeply_tilted, pour_low], 3, 1, Rows), length(Rows, 3), "
            f"simulate(Rows, [oracle(synthetic), executor(inline), store('{tmp_path / 's.sqlite'}')], "
            f"Scores), forall(member(S, Scores), (memberchk(no_spill-X, S), X < 0.5)), "
            f"format('spills ~w~n', [3])")
    r = run_cli("prolog", "-g", goal)
    assert r.code == 0, r.err
    assert "spills 3" in r.out
    bad = run_cli("prolog", "-g", "sample([pour_sideways], 1, 1, _)")
    assert bad.code == 1
    assert "unknown proposition 'pour_sideways'" in bad.err


def test_prolog_describes_a_pour_as_it_was_sampled():
    goal = ("sample([pour_to_side, light_liquid], 3, 7, Rows), "
            "forall(member(R, Rows), (describe(R, Ps), subtract([pour_to_side, light_liquid], Ps, []))), "
            "Rows = [R0|_], describe(R0, P0), length(P0, N), format('~w~n', [N])")
    r = run_cli("prolog", "-g", goal)
    assert r.code == 0, r.err
    assert int(r.out.split()[-1]) > 2          # the unsaid dimensions are described too
    bad = run_cli("prolog", "-g", "describe([1, 2, 3], _)")
    assert bad.code != 0 and "expected rows of 30 numbers" in bad.err
