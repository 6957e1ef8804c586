:- begin_tests(curiosity_interface).

:- use_module(interface).

% Every value of the option curiosity/1 has its module, and each module
% defines the whole interface.
test(every_curiosity_has_a_module_with_the_whole_interface) :-
    defaults:option(curiosity, choice, Range, _, _),
    Range =.. [one_of|Curiosities],
    forall(member(C, Curiosities),
           ( curiosity_module(C, M),
             forall(member(P/N, [budget/2, progress_bar/2, probe_size/2, probed/2,
                                 priors_due/2, after_batch/4, second_layer/4,
                                 theory_layout/1]),
                    ( current_predicate(M:P/N) -> true ; format("~w lacks ~w~n", [M, P/N]), fail ))
           )).

settings(C, _{curiosity:C, budget:25, batch:31, pours:775, probe:8, prior_batch:1}).

test(the_budget_and_the_bar_are_the_curiosity_s) :-
    settings(learn, L), settings(discover, D), settings(paper, P),
    by_curiosity(L, budget(L, 775)),
    by_curiosity(D, budget(D, 775)),
    by_curiosity(P, budget(P, 775)),
    by_curiosity(L, progress_bar(L, _{total:775, unit:pour})),
    by_curiosity(D, progress_bar(D, _{total:775, unit:pour})),
    by_curiosity(P, progress_bar(P, _{total:25, unit:rule})).

% Only the discovering curiosity probes: not a_0, the priors or more pours,
% nor with probe(0).
test(the_probe_policy_is_the_discovering_curiosity_s) :-
    settings(learn, L), settings(discover, D), settings(paper, P),
    Near = cand([pour_low], a1, near),
    by_curiosity(D, probed(Near, D)),
    by_curiosity(D, probe_size(D, 8)),
    \+ by_curiosity(D, probed(cand([pour_low], none, initial), D)),
    \+ by_curiosity(D, probed(cand([], none, prior), D)),
    \+ by_curiosity(D, probed(cand([pour_low], a1, more(a1, 1)), D)),
    \+ by_curiosity(D.put(probe, 0), probed(Near, D.put(probe, 0))),
    \+ by_curiosity(L, probed(Near, L)), by_curiosity(L, probe_size(L, 0)),
    \+ by_curiosity(P, probed(Near, P)), by_curiosity(P, probe_size(P, 0)).

test(only_the_discovering_curiosity_explores_the_priors) :-
    settings(learn, L), settings(discover, D), settings(paper, P),
    by_curiosity(D, priors_due([], D)),
    \+ by_curiosity(D, priors_due([ant(a2, [], none, prior)], D)),
    \+ by_curiosity(D.put(prior_batch, 0), priors_due([], D.put(prior_batch, 0))),
    \+ by_curiosity(L, priors_due([], L)),
    \+ by_curiosity(P, priors_due([], P)).

% The loop, the probes and explore/1 ask the curiosity's module; none of
% them names a curiosity.
test(the_loop_names_no_curiosity) :-
    module_property(curiosity_interface, file(Here)),
    file_directory_name(Here, Dir),
    forall(member(F, ['loop.pl', 'probe.pl', 'run.pl', 'writer.pl']),
           ( directory_file_path(Dir, F, Path),
             read_file_to_string(Path, Text, []),
             forall(member(C, ["== learn", "== discover", "== paper", "\\== discover",
                               "learn,", "discover)", "(learn"]),
                    \+ sub_string(Text, _, _, _, C)) )).

% A curiosity's module is checked when it loads: one that lacks a
% predicate of the interface, or declares a Python side that is no list of
% module names, is refused; one without python_side/1 has none.
test(a_curiosity_is_checked_when_it_loads) :-
    toy_module(Fine, [ "budget(_, 1).", "progress_bar(_, _{total:1, unit:pour}).",
                       "probe_size(_, 0).", "probed(_, _) :- fail.", "priors_due(_, _) :- fail.",
                       "after_batch(_, _, [], _{}).", "second_layer(_, _, _, []).",
                       "theory_layout(_{})." ]),
    load_curiosity(toy_fine, Fine),
    curiosity_python_side(toy_fine, []),
    by_curiosity(_{curiosity:toy_fine}, budget(_, 1)),
    retractall(curiosity_interface:curiosity_module(toy_fine, _)),
    toy_module(Lacking, [ "budget(_, 1)." ]),
    catch(load_curiosity(toy_lacking, Lacking), curiosity_interface(toy_lacking, _, Lacks), true),
    Lacks == lacks(progress_bar/2),
    \+ curiosity_module(toy_lacking, _),
    toy_module(Bad, [ "budget(_, 1).", "progress_bar(_, _{total:1, unit:pour}).",
                      "probe_size(_, 0).", "probed(_, _) :- fail.", "priors_due(_, _) :- fail.",
                      "after_batch(_, _, [], _{}).", "second_layer(_, _, _, []).",
                      "theory_layout(_{}).", "python_side(teaching)." ]),
    catch(load_curiosity(toy_bad, Bad), curiosity_interface(toy_bad, _, Side), true),
    Side == python_side(teaching),
    message_to_codes(curiosity_interface(toy_bad, 'toy.pl', Side), Text),
    once(sub_string(Text, _, _, _, "the curiosity toy_bad (toy.pl) declares python_side(teaching)")).

% A curiosity that declares an option the table has already is refused.
test(a_curiosity_s_option_is_new_to_the_table) :-
    toy_module(Twice, [ "budget(_, 1).", "progress_bar(_, _{total:1, unit:pour}).",
                        "probe_size(_, 0).", "probed(_, _) :- fail.", "priors_due(_, _) :- fail.",
                        "after_batch(_, _, [], _{}).", "second_layer(_, _, _, []).",
                        "theory_layout(_{}).",
                        "option(seed, count, range(0, 9), 1, \"again\")." ]),
    catch(load_curiosity(toy_twice, Twice), curiosity_interface(toy_twice, _, Problem), true),
    Problem == option_twice(seed),
    \+ curiosity_module(toy_twice, _),
    message_to_codes(curiosity_interface(toy_twice, 'toy.pl', Problem), Text),
    once(sub_string(Text, _, _, _, "declares the option seed, which the option table has already")).

% The Python sides of the curiosities of the list.
test(each_curiosity_declares_its_python_side) :-
    forall(curiosity_module(C, _),
           ( curiosity_python_side(C, Modules), Modules \== [],
             forall(member(M, Modules), sub_atom(M, 0, _, _, 'pantarhei.bridge.exploration.')) )).

%   toy_module(-File, +Clauses): a module file of its own holding Clauses.
toy_module(File, Clauses) :-
    tmp_file_stream(File, Out, [extension(pl)]),
    file_base_name(File, Base),
    once(file_name_extension(Name, _, Base)),
    atom_concat(toy_, Name, Module),
    format(Out, ":- module(~q, []).~n", [Module]),
    forall(member(C, Clauses), format(Out, "~s~n", [C])),
    close(Out).

message_to_codes(Term, Text) :-
    once(phrase(prolog:message(Term), Lines)),
    with_output_to(string(Text), print_message_lines(current_output, '', Lines)).

:- end_tests(curiosity_interface).
