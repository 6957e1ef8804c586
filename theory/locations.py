"""Where the theory's files are: the folder theory/ (package data of
pantarhei.theory) and the files of it that Python names. Imports nothing of
the project but the names of the table of check messages and of the
defaults (its reader's, which reads them), so that every
module of the package (the option table, the defaults) can name the files
without importing the package's own readers."""
from __future__ import annotations

from pathlib import Path

from pantarhei.bridge.theories.facts import CHECK_MESSAGES, DEFAULTS

#: The folder that holds the theory files.
THEORY_DIR = Path(__file__).resolve().parent
#: The vocabulary fact files, read by SWI-Prolog and by clingo alike.
VOCABULARY_FILES = tuple(THEORY_DIR / "vocabulary" / f"{name}.pl"
                         for name in ("parameters", "propositions", "expectations", "constraints"))

#: The file that loads every Prolog module of the theory (and the shipped
#: theory) into a plain SWI-Prolog: the one list of the Prolog modules.
PROLOG_ENTRY = THEORY_DIR / "pantarhei.pl"

#: The project's defaults (exploration settings, a_0, where the learned
#: theory and the store go), read by Prolog and Python alike.
DEFAULTS_FILE = THEORY_DIR / DEFAULTS

#: The messages of the checks of a theory file that both readers make
#: (`check_message` of bridge/theories/facts.py; SWI-Prolog's
#: check_message/3 of fact_reader.pl).
CHECK_MESSAGES_FILE = THEORY_DIR / CHECK_MESSAGES
