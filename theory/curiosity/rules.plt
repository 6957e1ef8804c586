:- begin_tests(curiosity_rules).

:- use_module(rules).
:- use_module('../theory_files').

test(rule_facts_and_theory_file, [setup(tmp_file(theory, F)), cleanup(delete_file(F))]) :-
    Q = _{id:a2, simulations:31, weight_mass_permille:900,
          outcomes:[_{expectation:no_spill, holds:false, confidence_permille:800, score_permille:300}]},
    rule_facts([ant(a2, [pour_to_side], a1, via(no_spill, pour_x, up))], [Q], Facts),
    memberchk(rule(r2_no_spill, defeasible, neg(no_spill)), Facts),
    memberchk(body(r2_no_spill, pour_to_side), Facts),
    memberchk(learned(r2_no_spill), Facts),
    memberchk(provenance(r2_no_spill, direction, pour_x), Facts),
    memberchk(provenance(r2_no_spill, parent, a1), Facts),
    write_theory(F, _{oracle:synthetic, seed:1}, _{header:["%   setting(Key, Value): it ran."], layer_header:[]},
                 [setting(oracle_version, "1")|Facts], []),
    read_file_to_string(F, Text, []),
    once(sub_string(Text, _, _, _, "that produced the antecedent);\n%   setting(Key, Value): it ran.\n\n")),
    theory_files:load_facts(F, explore_plt_theory),
    explore_plt_theory:rule(r2_no_spill, defeasible, neg(no_spill)),
    explore_plt_theory:setting(oracle_version, "1").

:- end_tests(curiosity_rules).
