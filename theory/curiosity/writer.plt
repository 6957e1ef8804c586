:- begin_tests(curiosity_writer).

:- use_module(writer).
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

% the learning curiosity's layer ends with its explored antecedents: their
% propositions and their pours per expectation, under a header saying what
% they mean, read back by the theory reader
test(explored_antecedents_written_and_read, [setup(tmp_file(theory, F)), cleanup(delete_file(F))]) :-
    Reply = _{pours:8, own_pours:0, sup:[],
              rules:[_{id:g0_no_spill, expectation:no_spill, holds:true, body:[], level:0,
                       support:8, kept:7, confidence_permille:875, antecedent:a1}],
              explored:[_{id:a1, body:[], held:[[no_spill, 7, 8]]},
                        _{id:a2, body:[pour_low, light_liquid], held:[[no_spill, 1, 4]]}]},
    once(curiosity_writer:layer_facts(Reply, General)),
    write_theory(F, _{oracle:synthetic, seed:1}, _{header:[], layer_header:["% the layer"]},
                 [], General),
    read_file_to_string(F, Text, []),
    once(sub_string(Text, _, _, _, "% explored(A, Prop): the antecedent A says Prop")),
    read_theory_file(F, LineFacts),
    findall(X, ( member(_-X, LineFacts), functor(X, N, _), memberchk(N, [explored, held]) ), Xs),
    Xs == [held(a1, no_spill, 7, 8), explored(a2, pour_low), explored(a2, light_liquid),
           held(a2, no_spill, 1, 4)],
    % a reply without them (the other curiosities' general layer) writes none
    once(curiosity_writer:layer_facts(Reply.put(explored, []), G0)),
    \+ memberchk(held(_, _, _, _), G0).

:- end_tests(curiosity_writer).
