:- begin_tests(curiosity_settings).

:- use_module('../default_values').
:- use_module('../validity').
:- use_module(settings).
:- use_module(interface, [curiosity_module/2]).

% a_0, the default of initial(Props), is a valid antecedent
test(default_initial_is_valid) :-
    default_initial(A),
    valid_antecedent(A).

% the course of a discovering run: course/2's options in the table's
% order, without the paper's slope; probe and prior_batch only when not 0
test(course_options_discover) :-
    settings([curiosity(discover)], S),
    course_options(S, Names),
    Names = [oracle, seed, batch, curiosity, significance, permutations, resample,
             novelty, jumps, probe, probe_attempts, prior_batch, breadth, ridge, initial],
    settings([curiosity(discover), probe(0), prior_batch(0)], S0),
    course_options(S0, Names0),
    \+ memberchk(probe, Names0), \+ memberchk(probe_attempts, Names0),
    \+ memberchk(prior_batch, Names0), memberchk(jumps, Names0).

% the learning curiosity, the default: its budget in pours, its options,
% a_0 the ordinary pour (the empty antecedent) and a batch of its own size
test(course_options_learn) :-
    settings([], S),
    S.curiosity == learn, S.initial == [], once(default(learn_batch, B)), S.batch =:= B,
    course_options(S, [oracle, seed, batch, pours, curiosity, body, queue, uncertainty,
                       doubt, newness, reach, whole_every, breadth, ridge, initial]),
    recorded_settings(S, "9", Facts, []),
    curiosity_settings:table_option(pours, _, _, Pours),
    memberchk(setting(pours, Pours), Facts),
    memberchk(setting(uncertainty_permille, _), Facts).

% the paper's curiosity: its slope, and none of discover's options
test(course_options_paper) :-
    settings([curiosity(paper)], S),
    course_options(S, [oracle, seed, batch, slope, breadth, ridge, initial]).

% the setting/2 facts: recorded/1's options besides the course's, permille
% in thousandths, the oracle with its version, probes at 0 still written,
% the initial antecedent apart
test(recorded_settings) :-
    settings([curiosity(discover), probe(0), seed(7), novelty(0.25),
              initial([pour_near_rim])], S),
    recorded_settings(S, "9", Facts, Antecedents),
    Facts = [setting(oracle, pybullet), setting(oracle_version, "9"), setting(seed, 7),
             setting(batch, _), setting(budget, 25), setting(curiosity, discover)|_],
    memberchk(setting(novelty_permille, 250), Facts),
    memberchk(setting(probe, 0), Facts),
    memberchk(setting(qualify, weighted), Facts),
    \+ memberchk(setting(slope_permille, _), Facts),
    \+ memberchk(setting(initial, _), Facts),
    Antecedents == [setting(initial, pour_near_rim)].

% the oracle's arguments are a dict
test(oracle_options_must_be_a_dict) :-
    settings([oracle_options(_{crash: 3})], S),
    get_dict(oracle_options, S, OO), get_dict(crash, OO, 3),
    catch(settings([oracle_options('{"crash": 3}')], _), exploration_error(M), true),
    M == "oracle_options: expected a dict".

% an option the table does not have is refused by name, not ignored
test(unknown_option_is_refused, [forall(member(O, [ouy('/tmp/x.pl'), outt = '/tmp/x.pl', seed, 7]))]) :-
    catch(settings([oracle(synthetic), O], _), exploration_error(M), true),
    format(string(Want), "unknown option ~q", [O]),
    string(M), sub_string(M, 0, _, _, Want).

% an option that the curiosity does not read (used_by/2 of
% theory/defaults.pl) is refused in one line naming it, the curiosity, its
% budget and its own options; given as Name = Value too
test(an_option_the_curiosity_does_not_read_is_refused,
     [true(M == "budget: not an option of curiosity(learn), whose budget is pours(N); its own options are pours, body, queue, uncertainty, doubt, newness, reach and whole_every (budget is read by curiosity(discover) and curiosity(paper))")]) :-
    catch(settings([curiosity(learn), budget(5)], _), exploration_error(M), true),
    catch(settings([budget = 5], _), exploration_error(M2), true),
    M2 == M.

test(each_curiosity_reads_its_options_and_refuses_the_others,
     [forall(( curiosity_settings:option_used_by(Name, _), curiosity_module(C, _) ))]) :-
    O =.. [Name, _],
    (   catch(( settings([curiosity(C), O], _), Said = read ),
              exploration_error(M), Said = M)
    ->  true
    ;   Said = read
    ),
    (   curiosity_settings:option_used_by(Name, C)
    ->  (   string(Said) -> \+ sub_string(Said, _, _, _, "not an option of") ; true )
    ;   string(Said),
        format(string(Want), "~w: not an option of curiosity(~w)", [Name, C]),
        sub_string(Said, 0, _, _, Want)
    ).

test(options_every_curiosity_reads_are_read_by_each,
     [forall(curiosity_module(C, _))]) :-
    settings([curiosity(C), seed(3), oracle(synthetic), batch(5), executor(inline),
              progress(false), initial([pour_low])], S),
    S.seed == 3.

% A curiosity declares its own options in its module: rows of the table,
% read by it alone, of the run's course when it says so, after the
% curiosity row and the rows of the curiosities loaded before it, or
% after the row option_after/2 names.
test(a_curiosity_s_own_options_are_rows_of_the_table,
     [cleanup(retractall(curiosity_interface:curiosity_module(toy_own, _)))]) :-
    findall(K, curiosity_settings:table_option(K, _, _, _), Before),
    findall(R, defaults:option(R, _, _, _, _), Rows),
    once(nextto(curiosity, Next, Rows)),
    tmp_file_stream(File, Out, [extension(pl)]),
    file_base_name(File, Base),
    once(file_name_extension(Name, _, Base)),
    atom_concat(toy_, Name, Module),
    format(Out, ":- module(~q, []).~n", [Module]),
    forall(member(C, [ "budget(_, 1).", "progress_bar(_, _{total:1, unit:pour}).",
                       "probe_size(_, 0).", "probed(_, _) :- fail.", "priors_due(_, _) :- fail.",
                       "after_batch(_, _, [], _{}).", "second_layer(_, _, _, []).",
                       "theory_layout(_{}).",
                       "option(toy_depth, count, range(1, 9), 3, \"toy: how deep\").",
                       "option(toy_width, permille, range(0, none), 500, \"toy: how wide\").",
                       "course(toy_depth, every).",
                       "option_after(toy_width, seed)." ]),
           format(Out, "~s~n", [C])),
    close(Out),
    curiosity_interface:load_curiosity(toy_own, File),
    curiosity_settings:table_option(toy_depth, count, range(1, 9), 3),
    findall(K, curiosity_settings:table_option(K, _, _, _), Keys),
    once(nextto(seed, toy_width, Keys)),
    once(nextto(toy_depth, Next, Keys)),
    subtract(Keys, [toy_depth, toy_width], Before),
    findall(C, curiosity_settings:option_used_by(toy_depth, C), [toy_own]),
    curiosity_settings:option_course(toy_depth, every),
    \+ curiosity_settings:option_course(toy_width, _),
    catch(settings([toy_depth(2)], _), exploration_error(M), true),
    once(sub_string(M, 0, _, _, "toy_depth: not an option of curiosity(learn)")).

:- end_tests(curiosity_settings).
