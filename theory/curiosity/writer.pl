:- module(curiosity_writer,
          [ learned/7,                % +Explored, +SetAside, +Settings, +Layout, +Stop, +Left, -Facts
            rule_facts/3,             % +Explored, +Qualified, -Facts
            general_layer/3,          % +Facts, +Settings, -General
            learned_layer/3,          % +Explored, +Settings, -Layer
            write_theory/5            % +File, +Settings, +Layout, +Facts, +General
          ]).
/** <module> Qualify and the learned theory

At the end of the loop each explored antecedent is qualified (the outcome
of its simulations, exploration_qualify) and becomes defeasible rules, one
per expectation, with their provenance; the settings of the run and the
candidates set aside are facts beside them. The general rules, learned
from every pour, are the second layer (general_layer/3). write_theory/5
writes both, once, in the common subset of Prolog and ASP. What the
run's curiosity writes (whether Algorithm 1's rules, their batches, the
headers) is its theory_layout of interface.pl.
*/

:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(foreign).
:- use_module(state).
:- use_module(settings).
:- use_module('../learned_rules', [rule_id/3, antecedent_id/2]).

%!  learned(+Explored:list, +SetAside:list, +Settings:dict, +Layout:dict, +Stop,
%!          +Left:integer, -Facts:list) is det.
%
%   Facts are those of the learned theory: the settings of the run (with
%   why it stopped, Stop, and how many candidates were left in A_new,
%   Left), set_aside/3 for each proposition of a candidate set aside after
%   its probe, and the rules of the explored antecedents, qualified by
%   exploration_qualify (rule_facts/3), when the curiosity's Layout
%   (theory_layout of interface.pl) writes them (`rules`; the learning
%   curiosity's rules are its one layer, and nothing is qualified), with
%   their batches of pours when it says so (`batches`).
learned(Explored, SetAside, Settings, Layout, Stop, Left, Facts) :-
    (   Layout.rules == true
    ->  Qualified = Explored
    ;   Qualified = []                  % its one layer: learned_layer/3
    ),
    maplist(entry, Qualified, Entries),
    call_bridge(exploration_qualify, _{antecedents:Entries, mode:Settings.qualify,
                                       batches:Layout.batches}, Reply),
    setting_facts(Settings, Reply, Stop, Explored, Left, SettingFacts),
    findall(set_aside(I, K, P), ( member(aside(I, K, Ps), SetAside), member(P, Ps) ), AsideFacts),
    rule_facts(Qualified, Reply.antecedents, RuleFacts),
    append([SettingFacts, AsideFacts, RuleFacts], Facts).

%   setting_facts(+Settings, +Reply, +Stop, +Explored, +Left, -Facts):
%   setting/2 facts saying how the exploration ran: the options the option
%   table records (recorded_settings/4), then the run's own facts, then the
%   initial antecedent (Reply: that of exploration_qualify, with the
%   oracle's version and the simulations).
setting_facts(Settings, Reply, Stop, Explored, Left, Facts) :-
    string_value(Reply.oracle_version, Version),
    recorded_settings(Settings, Version, Options, Antecedents),
    length(Explored, N),
    append([ Options,
             [ setting(explored, N),
               setting(simulations, Reply.simulations),
               setting(failed_simulations, Reply.failed),
               setting(stopped, Stop),
               setting(a_new_left, Left) ],
             Antecedents ], Facts).


%!  rule_facts(+Explored:list, +Qualified:list, -Facts:list) is det.
%
%   The facts of the learned rules: for each explored antecedent
%   ant(Id, Props, Parent, Via) and its qualified outcome (a dict with
%   `outcomes`, a list of dicts with expectation, holds, confidence_permille
%   and score_permille, and the antecedent's `simulations` and
%   `weight_mass_permille`, and `batches`, its batches of pours, when the
%   curiosity's layout records them), one defeasible rule per outcome literal, its
%   body facts, learned/1 and its provenance.
rule_facts(Explored, Qualified, Facts) :-
    foldl(antecedent_facts(Qualified), Explored, Fs, []),
    Facts = Fs.

%   antecedent_facts(+Qualified, +Ant, -Facts, ?Tail): the facts of the
%   rules of one explored antecedent, a difference list.
antecedent_facts(Qualified, ant(Id, Props, Parent, Via), Facts, Tail) :-
    member(Q, Qualified), Q.id == Id, !,
    foldl(outcome_facts(Id, Props, Parent, Via, Q), Q.outcomes, Facts, Tail).

%   outcome_facts(+AId, +Props, +Parent, +Via, +Q, +O, -Facts, ?Tail): the
%   rule of one outcome O of the antecedent AId, its body and provenance.
outcome_facts(AId, Props, Parent, Via, Q, O, Facts, Tail) :-
    antecedent_id(I, AId),
    rule_id(I, O.expectation, Id),
    (   O.holds == true -> Head = O.expectation ; Head = neg(O.expectation) ),
    findall(body(Id, P), member(P, Props), Bodies),
    via_facts(Id, Via, ViaFacts0),
    (   get_dict(batches, Q, B)
    ->  ViaFacts = [provenance(Id, batches, B)|ViaFacts0]
    ;   ViaFacts = ViaFacts0
    ),
    Prov = [ provenance(Id, antecedent, AId),
             provenance(Id, parent, Parent),
             provenance(Id, simulations, Q.simulations),
             provenance(Id, weight_mass_permille, Q.weight_mass_permille),
             provenance(Id, confidence_permille, O.confidence_permille),
             provenance(Id, score_permille, O.score_permille)
           | ViaFacts ],
    append([[rule(Id, defeasible, Head)], Bodies, [learned(Id)], Prov], Fs),
    append(Fs, Tail, Facts).

%   via_facts(+Id, +Via, -Facts): the provenance of how the antecedent was
%   found (the plane, parameter and sign that produced it).
via_facts(_, initial, []).
via_facts(_, prior, []).
via_facts(_, near, []).
via_facts(_, jump, []).
via_facts(Id, via(E, X, Sign), [ provenance(Id, followed, E),
                                 provenance(Id, direction, X),
                                 provenance(Id, sign, Sign) ]).

%!  general_layer(+Facts:list, +Settings:dict, -General:list) is det.
%
%   General are the facts of the general layer (bridge/learning/layers.py,
%   exploration_general): rules learned from every pour of the
%   exploration and the learner's own, by the run's learner (the learner
%   setting), each with its provenance (layer,
%   level, support, kept, confidence in permille), setting/2 facts of how
%   many pours they rest on, and the sup/2 facts that order both layers
%   (Algorithm 1's rules are those of Facts, with their confidence).
general_layer(Facts, Settings, General) :-
    findall(_{id:Id, expectation:E, holds:H, body:B, confidence_permille:C},
            ( member(rule(Id, _, Head), Facts),
              head_expectation(Head, E, H),
              findall(P, member(body(Id, P), Facts), B),
              memberchk(provenance(Id, confidence_permille, C), Facts)
            ), Rules),
    call_bridge(exploration_general, _{rules:Rules, seed:Settings.seed,
                                       learner:Settings.learner}, Reply),
    layer_facts(Reply, General).

%!  learned_layer(+Explored:list, +Settings:dict, -Layer:list) is det.
%
%   Layer are the facts of the learning curiosity's theory, one layer
%   (exploration_general with the explored antecedents): per expectation,
%   the rules of the explored antecedents whose likelihoods the rest of
%   the theory does not give, each naming its antecedent, with every pour
%   of the run pooled for the likelihoods; the setting/2 facts of how many
%   pours they rest on, and their sup/2 facts. A whole (explored via
%   whole) has no rule of its own: no question says it, and its pours
%   teach the rules of the others; its pours are cited as an explored
%   antecedent's.
learned_layer(Explored, Settings, Layer) :-
    maplist(entry, Explored, Entries),
    findall(Id, member(ant(Id, _, _, whole), Explored), Wholes),
    call_bridge(exploration_general, _{rules:[], explored:Entries, ruleless:Wholes,
                                       seed:Settings.seed, learner:Settings.learner}, Reply),
    layer_facts(Reply, Layer).

%   layer_facts(+Reply, -Facts): the rules of exploration_general's
%   reply as facts, after the setting/2 facts of their pours and before
%   their sup/2 facts, and then those of the explored antecedents
%   (explored_facts/2).
layer_facts(Reply, General) :-
    length(Reply.rules, N),
    maplist(general_rule_facts, Reply.rules, RuleFacts),
    findall(sup(A, B), member([A, B], Reply.sup), Sups),
    append(RuleFacts, Rules1),
    (   get_dict(explored, Reply, Explored) -> true ; Explored = [] ),
    explored_facts(Explored, ExploredFacts),
    append([ [ setting(general_pours, Reply.pours),
               setting(general_own_pours, Reply.own_pours),
               setting(general_rules, N) ],
             Rules1, Sups, ExploredFacts ], General).

%!  explored_facts(+Explored:list, -Facts:list) is det.
%
%   The facts of the explored antecedents of exploration_general's reply
%   (each a dict: id, body, held, a list of [Expectation, Held, Pours]):
%   explored(A, Prop) for each proposition of antecedent A, and
%   held(A, E, Held, Pours) for each expectation E: of the Pours pours
%   that could have been drawn for A, Held held E. What an answer cites
%   for an antecedent asked that was explored but has no rule of its own
%   (theory/answer_words.pl).
explored_facts(Explored, Facts) :-
    findall(F, ( member(X, Explored),
                 (   member(P, X.body), F = explored(X.id, P)
                 ;   member([E, K, N], X.held), F = held(X.id, E, K, N)
                 ) ),
            Facts).

head_expectation(neg(E), E, false) :- !.
head_expectation(E, E, true).

%   general_rule_facts(+Rule:dict, -Facts): a general rule of the reply
%   as facts.
general_rule_facts(R, Facts) :-
    head_expectation(Head, R.expectation, R.holds),
    Id = R.id,
    findall(body(Id, P), member(P, R.body), Bodies),
    (   get_dict(antecedent, R, A)
    ->  Antecedent = [provenance(Id, antecedent, A)]
    ;   Antecedent = []
    ),
    (   get_dict(doubt, R, D0)
    ->  atom_string(D, D0), Doubt = [provenance(Id, doubt, D)]
    ;   Doubt = []
    ),
    (   get_dict(beside, R, Bs)
    ->  findall(provenance(Id, beside, B), ( member(B0, Bs), atom_string(B, B0) ), Beside)
    ;   Beside = []
    ),
    append([ [rule(Id, defeasible, Head)], Bodies,
             [ learned(Id),
               provenance(Id, layer, general),
               provenance(Id, level, R.level),
               provenance(Id, support, R.support),
               provenance(Id, kept, R.kept),
               provenance(Id, confidence_permille, R.confidence_permille) ],
             Antecedent, Doubt, Beside ], Facts).

%!  write_theory(+File, +Settings:dict, +Layout:dict, +Facts:list, +General:list) is det.
%
%   Write Facts (Algorithm 1's) and General (the general layer, if any) to
%   File, in the common subset of Prolog and ASP, each with a header
%   saying what it is (the lines of the curiosity's Layout: `header`,
%   `layer_header`). The file is written beside under a temporary name
%   and renamed, so File is never half-written.
write_theory(File, Settings, Layout, Facts, General) :-
    file_directory_name(File, Dir),
    make_directory_path(Dir),
    current_prolog_flag(pid, Pid),
    format(atom(Tmp), "~w.~w.tmp", [File, Pid]),
    setup_call_cleanup(
        open(Tmp, write, Out, [encoding(utf8)]),
        ( write_facts(Out, Settings, Layout.header, Facts),
          write_general(Out, Layout.layer_header, General) ),
        close(Out)),
    rename_file(Tmp, File).

%   write_facts(+Out, +Settings, +Header, +Facts): the header (its common
%   lines, then the curiosity's Header lines and a blank line), then each
%   fact, a blank line before each rule.
write_facts(Out, Settings, Header, Facts) :-
    format(Out, "% A theory of pouring learned by curiosity-driven exploration~n", []),
    format(Out, "% (pantarhei explore, oracle ~w, seed ~w).~n", [Settings.oracle, Settings.seed]),
    format(Out, "%~n", []),
    format(Out, "% Ground facts, read by SWI-Prolog and clingo alike:~n", []),
    format(Out, "%   rule(Id, defeasible, Head): Head is an expectation, or neg(E) when it fails;~n", []),
    format(Out, "%   body(Id, Prop): a scene proposition of the rule's antecedent;~n", []),
    format(Out, "%   learned(Id): a learned rule (superiority from specificity);~n", []),
    format(Out, "%   provenance(Id, Key, Value): where the rule comes from (antecedent,~n", []),
    format(Out, "%   parent antecedent, simulations with a weight, their weight mass and the~n", []),
    format(Out, "%   verdict's confidence in permille, and the plane, parameter and sign~n", []),
    format(Out, "%   that produced the antecedent);~n", []),
    forall(member(Line, Header), format(Out, "~w~n", [Line])),
    nl(Out),
    forall(member(F, Facts),
           (   ( F = rule(_, _, _) -> nl(Out) ; true ),
               write_fact(Out, F)
           )).

%   write_general(+Out, +Header, +General): the general layer (the
%   learning curiosity's one layer) after a blank line, its Header lines,
%   then each fact.
write_general(_, _, []) :- !.
write_general(Out, Header, General) :-
    forall(member(Line, ["" | Header]), format(Out, "~w~n", [Line])),
    partition(explored_fact, General, Explored, Rules),
    forall(member(F, Rules), write_fact(Out, F)),
    (   Explored == []
    ->  true
    ;   forall(member(Line, [ "",
              "% The explored antecedents, with or without a rule of their own:",
              "% explored(A, Prop): the antecedent A says Prop (the ordinary pour,",
              "% which says nothing, has none); held(A, E, Held, Pours): of the Pours",
              "% pours that could have been drawn for A, Held held E. An answer for",
              "% a scene explored cites them (docs/theory-formats.md)." ]),
                 format(Out, "~w~n", [Line])),
        forall(member(F, Explored), write_fact(Out, F))
    ).

explored_fact(explored(_, _)).
explored_fact(held(_, _, _, _)).

write_fact(Out, F) :-
    write_term(Out, F, [quoted(true), spacing(next_argument)]),
    write(Out, '.\n').
