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

:- end_tests(curiosity_interface).
