% The messages of the checks of a theory file that both readers make,
% written once and read by SWI-Prolog (theory/fact_reader.pl:
% check_message/3) and by Python (pantarhei.theory.check_message), so that
% a bad file gets the same words from either, after its `file:line: `.
% check_message(Key, Format): Format is format/2's, with ~w alone (each
% ~w is the next argument, written as it is), which both render alike.
% tests/theory/test_check_messages.py gives both readers the same bad
% files and compares what they say.

% The language of theory files (fact_reader.pl; bridge/theories/facts.py):
% what a file holds that is not a ground fact as both engines read it.
check_message(no_such_file, "no such file").
% A byte (its code in hexadecimal, 0x and two digits).
check_message(not_ascii,
  "byte ~w is not printable ASCII: a theory file is ASCII text (no other characters, no invalid UTF-8)").
check_message(expected_fact, "expected a fact such as name(arg, 1).").
check_message(directive, "a fact, not a directive: a theory file is data").
check_message(hash_directive, "a fact, not a directive (#include, #script, ...): a theory file is data").
check_message(rule_not_fact, "a fact, not a rule").
check_message(variable, "a ground fact (no variables)").
check_message(float, "an integer, not a float (use integer units such as mm or permille)").
check_message(list, "an atom, integer, text or term, not a list").
check_message(not_name, "a name other than not (clingo reads it as negation)").
check_message(text_escape, "quoted text with \\\\, \\\" and \\n as its only escapes").
% A term nested too deep (how deep a term may nest).
check_message(nesting, "a term nested at most ~w deep").
% An integer (as shown: whole, or by its ends and its count of digits).
check_message(int_range, "an integer from -2147483648 to 2147483647, not ~w").
check_message(int_form, "an integer in decimal digits without leading zeros, not ~w").

% A fact of a theory predicate not of its form (its Form, its name and arity).
check_message(arity, "expected ~w, not a ~w/~w fact").
% An argument that must be a name (the fact's form, the argument).
check_message(name_argument, "~w: a name in lower case letters, digits and _, not ~w").
% A rule's kind (the rule, the kind).
check_message(kind, "rule ~w: kind strict, defeasible or defeater, not ~w").
% held/4's counts (the antecedent, the expectation, held, pours).
check_message(held,
  "held(~w, ~w, Held, Pours): Held of Pours pours, whole numbers with 0 <= Held <= Pours, not ~w of ~w").
% A rule's recorded confidence (the rule, the value): some of its pours keep
% its head, or the rule would conclude the other head.
check_message(confidence,
  "rule ~w: a confidence is the permille of its pours that keep its head, 1 to 1000, not ~w").
% A literal (the literal as written).
check_message(double_negation, "a literal or its negation neg(L), not a double negation ~w").
check_message(literal,
  "a literal such as p, bird(tweety) or neg(p) (names and integers as arguments), not ~w").
% A rule named twice in one file (the rule).
check_message(second_rule, "a second rule named ~w").
% body/2 of no rule (the rule, three times).
check_message(dangling_body, "body(~w, _) of a rule ~w that has no rule(~w, Kind, Head) fact").

% A file past theory_bytes_at_most of theory/defaults.pl (its size, the
% most, each in digits grouped by commas).
check_message(too_large,
  "~w bytes, past the ~w a theory file may have (theory_bytes_at_most, theory/defaults.pl)").
% A theory of several files: a rule a file before defined (the rule, that file).
check_message(already_defined, "rule ~w is already defined in ~w").
% sup/2 of a name no rule has (the pair, the name).
check_message(sup_not_a_rule, "sup(~w, ~w) names ~w, which is not a rule").
% A file with nothing of a theory.
check_message(empty_theory, "an empty theory (no facts and no rules)").
% A general rule (provenance(R, layer, general)) the vocabulary cannot
% read: its body, its head, its evidence (the rule first).
check_message(general_body, "general rule ~w: ~w is not a proposition of the vocabulary").
check_message(general_head, "general rule ~w: ~w is not an expectation").
check_message(general_confidence,
  "general rule ~w: a confidence in permille is 0 to 1000, not ~w").
check_message(general_count, "general rule ~w: ~w is a count of pours, not ~w").
check_message(general_kept, "general rule ~w: ~w pours kept of ~w described").

% A name of a theory of pouring that the vocabulary does not know, a
% warning (theory_checks.pl's unknown_lines/2 finds them; Python says them, with the
% nearest known name: bridge/theories/unknown_names.py): what names it
% (such as "rule r1: body"), the name.
check_message(unknown_name, "~w ~w is not a proposition or expectation of pouring").

% A rule could beat itself (and a literal and its complement both be
% concluded): the cycle's rules, joined by " > ", first and last the same.
check_message(superiority_cycle,
  "the superiority relation has a cycle, ~w: it must be acyclic").
