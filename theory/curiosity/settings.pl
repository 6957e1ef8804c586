:- module(curiosity_settings,
          [ settings/2                % +Options, -Settings
          ]).
/** <module> The settings of an exploration

Read the options of explore/1 into one dict, the Settings every part of
the loop reads: each option checked, and those not given taken from the
defaults of theory/defaults.pl. A bad option raises
=|exploration_error(Text)|= with one line saying which and why.
*/

:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(option)).
:- use_module(library(http/json)).
:- use_module('../vocabulary').
:- use_module('../validity').
:- use_module('../default_values').

%!  settings(+Options:list, -Settings:dict) is det.
%
%   Settings holds every option of explore/1 (see explore.pl): those of
%   Options, checked, the others their defaults. The discovering
%   curiosity's options are read and checked first (curiosity_options/4),
%   then those of every run (run_options/4); store, workers, ray_address
%   and oracle_options are keys only when given.
%
%   @error exploration_error(Text) for the first bad option.
settings(Options, S) :-
    must_be(list, Options),
    curiosity_options(Options, Curiosity, DThreshold, Discover),
    run_options(Options, Curiosity, DThreshold, Run),
    put_dict(Run, Discover, S0),
    optional(store, Options, S0, S1),
    optional(workers, Options, S1, S2),
    optional(ray_address, Options, S2, S3),
    (   option(oracle_options(OO), Options)
    ->  (   is_dict(OO) -> OracleOptions = OO ; atom_json_dict(OO, OracleOptions, []) ),
        put_dict(oracle_options, S3, OracleOptions, S)
    ;   S = S3
    ).

%   curiosity_options(+Options, -Curiosity, -DThreshold, -Settings): the
%   curiosity and the options of the discovering one, checked; DThreshold
%   is the default threshold of that curiosity (a slope for the paper's, a
%   significance level for the discovering one).
curiosity_options(Options, Curiosity, DThreshold, Settings) :-
    default(threshold, DSlope),
    default(significance, DLevel),
    option_default(curiosity, Options, Curiosity),
    (   memberchk(Curiosity, [paper, discover])
    ->  true
    ;   throw(exploration_error("curiosity: expected paper or discover"))
    ),
    (   Curiosity == paper -> DThreshold = DSlope ; DThreshold = DLevel ),
    option_default(permutations, Options, Permutations),
    check_positive(permutations, Permutations),
    option_default(resample, Options, Resample),
    (   integer(Resample), Resample >= 0 -> true
    ;   throw(exploration_error("resample: expected a whole number >= 0"))
    ),
    option_default(queue, Options, Queue),
    check_positive(queue, Queue),
    option_default(jumps, Options, Jumps),
    check_positive(jumps, Jumps),
    option_default(probe, Options, Probe),
    (   integer(Probe), Probe >= 0 -> true
    ;   throw(exploration_error("probe: expected a whole number >= 0"))
    ),
    option_default(probe_attempts, Options, Attempts),
    check_positive(probe_attempts, Attempts),
    option_default(cover, Options, Cover),
    (   integer(Cover), Cover >= 0 -> true
    ;   throw(exploration_error("cover: expected a whole number >= 0"))
    ),
    option_default(prior, Options, Prior),
    (   memberchk(Prior, [0, 1]) -> true
    ;   throw(exploration_error("prior: expected 0 or 1"))
    ),
    option_default(novelty, Options, Novelty0),
    (   number(Novelty0), Novelty0 >= 0, Novelty0 =< 1 -> Novelty is float(Novelty0)
    ;   throw(exploration_error("novelty: expected a number from 0 to 1"))
    ),
    Settings = _{curiosity:Curiosity, permutations:Permutations, resample:Resample,
                 novelty:Novelty, queue:Queue, jumps:Jumps, probe:Probe,
                 probe_attempts:Attempts, cover:Cover, prior:Prior}.

%   run_options(+Options, +Curiosity, +DThreshold, -Settings): the options
%   of every run (oracle, budget, threshold, seed, a_0, modify, qualify,
%   where to simulate and write), checked.
run_options(Options, Curiosity, DThreshold, Settings) :-
    aggregate_all(count, parameter(_, _, _, _, _), NParams),
    DefaultSamples is NParams + 1,
    default_initial(DefaultInitial),
    option_default(oracle, Options, Oracle),
    option_default(max_rules, Options, Max),
    option(samples(Samples), Options, DefaultSamples),
    option(threshold(Threshold0), Options, DThreshold),
    option_default(seed, Options, Seed),
    option(initial(Initial0), Options, DefaultInitial),
    option_default(breadth, Options, Breadth),
    option_default(ridge, Options, Ridge0),
    option_default(qualify, Options, Qualify),
    option(resume(Resume), Options, false),
    option(executor(Executor), Options, local),
    option(progress(Progress), Options, true),
    default_out(DefaultOut),
    option(out(Out0), Options, DefaultOut),
    check_positive(max_rules, Max),
    check_positive(samples, Samples),
    check_positive(breadth, Breadth),
    (   integer(Seed) -> true ; throw(exploration_error("seed: expected an integer")) ),
    (   number(Threshold0), Threshold0 >= 0
    ->  Threshold is float(Threshold0)
    ;   throw(exploration_error("threshold: expected a number >= 0"))
    ),
    (   Curiosity == discover, Threshold > 1
    ->  throw(exploration_error("threshold: a significance level is at most 1"))
    ;   true
    ),
    (   memberchk(Qualify, [weighted, argmax])
    ->  true
    ;   throw(exploration_error("qualify: expected weighted or argmax"))
    ),
    (   number(Ridge0), Ridge0 >= 0
    ->  Ridge is float(Ridge0)
    ;   throw(exploration_error("ridge: expected a number >= 0"))
    ),
    check_initial(Initial0, Initial),
    absolute_file_name(Out0, Out),
    Settings = _{oracle:Oracle, max_rules:Max, samples:Samples, threshold:Threshold,
                 seed:Seed, initial:Initial, breadth:Breadth, ridge:Ridge, qualify:Qualify,
                 resume:Resume, executor:Executor, progress:Progress, out:Out}.

%   option_default(+Key, +Options, -Value): the option Key(Value) of
%   Options, or the default of theory/defaults.pl.
option_default(Key, Options, Value) :-
    default(Key, Default),
    Option =.. [Key, Value],
    option(Option, Options, Default).

%   optional(+Key, +Options, +S0, -S): S0 with Key set to the option
%   Key(Value) of Options (a store as an absolute path), if given.
optional(Key, Options, S0, S) :-
    Opt =.. [Key, V],
    (   option(Opt, Options)
    ->  (   Key == store
        ->  absolute_file_name(V, Value)
        ;   Value = V
        ),
        put_dict(Key, S0, Value, S)
    ;   S = S0
    ).

%   default_out(-File): the default learned theory, relative to theory/
%   (the folder above this one).
default_out(File) :-
    module_property(curiosity_settings, file(Here)),
    file_directory_name(Here, CuriosityDir),
    file_directory_name(CuriosityDir, Dir),
    default(theory, Relative),
    directory_file_path(Dir, Relative, File).

%   check_positive(+Name, +N): N is a whole number above 0, else the error
%   names the option Name.
check_positive(_, N) :- integer(N), N > 0, !.
check_positive(Name, _) :-
    format(string(M), "~w: expected a whole number above 0", [Name]),
    throw(exploration_error(M)).

%   check_initial(+Props, -Set): Props, a list of propositions, sorted, is
%   a valid antecedent (the first reason it is not is the error).
check_initial(Props, Set) :-
    (   is_list(Props) -> true
    ;   throw(exploration_error("initial: expected a list of propositions"))
    ),
    sort(Props, Set),
    violations(Set, Why),
    (   Why = [] -> true
    ;   Why = [unknown(_, W)|_]
    ->  format(string(M), "initial antecedent: ~s", [W]),
        throw(exploration_error(M))
    ;   Why = [violation(_, _, _, W)|_],
        format(string(M), "initial antecedent is invalid: ~s", [W]),
        throw(exploration_error(M))
    ).

