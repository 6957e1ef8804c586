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
                       doubt, newness, reach, breadth, ridge, initial]),
    recorded_settings(S, "9", Facts, []),
    once(default(pours, Pours)),
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
     [true(M == "budget: not an option of curiosity(learn), whose budget is pours(N); its own options are pours, body, queue, uncertainty, doubt, newness and reach (budget is read by curiosity(discover) and curiosity(paper))")]) :-
    catch(settings([curiosity(learn), budget(5)], _), exploration_error(M), true),
    catch(settings([budget = 5], _), exploration_error(M2), true),
    M2 == M.

test(each_curiosity_reads_its_options_and_refuses_the_others,
     [forall(( defaults:used_by(Name, _), curiosity_module(C, _) ))]) :-
    defaults:option(Name, _, _, _, _),
    O =.. [Name, _],
    (   catch(( settings([curiosity(C), O], _), Said = read ),
              exploration_error(M), Said = M)
    ->  true
    ;   Said = read
    ),
    (   defaults:used_by(Name, C)
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

:- end_tests(curiosity_settings).
